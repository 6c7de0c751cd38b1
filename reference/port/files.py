"""Reading a port world from a file, whatever form it comes in (the port-labelled model).

:func:`load_port_file` reads a contest map file (``{"problemName", "map"}``, :mod:`topomark.spec.port_icfpc`) or a
bare contest map object (``{"rooms", "startingRoom", "connections"}``, as a ``/guess`` body carries it).  Every
refusal is an :class:`~topomark.spec.errors.InvalidWorld` whose message starts with the file's name.
"""

from __future__ import annotations

from pathlib import Path

from topomark.spec.errors import InvalidWorld
from topomark.spec.jsontext import no_duplicate_keys, parse_json, read_text_file
from topomark.spec.port_icfpc import MAP_KEYS, map_from_json, submission_from_json
from topomark.spec.port_world import PortWorld

__all__ = ["load_port_file", "MAX_PORT_FILE_BYTES"]

MAX_PORT_FILE_BYTES = 64 << 20
"""The largest port world file read (a contest map of 100,000 rooms takes about 40 MB)."""


def load_port_file(path: str | Path) -> tuple[str | None, PortWorld]:
    """The problem name (``None`` when the file has none) and the port world of the file at ``path``."""
    text = read_text_file(path, InvalidWorld, MAX_PORT_FILE_BYTES)
    obj = parse_json(text, str(path), InvalidWorld, object_pairs_hook=no_duplicate_keys)
    try:
        if isinstance(obj, dict) and set(obj) & set(MAP_KEYS):
            return None, map_from_json(obj)
        return submission_from_json(obj)
    except InvalidWorld as e:
        raise InvalidWorld(f"{path}: {e}") from None

"""Reading a port world from a file, whatever form it comes in (the port-labelled model).

:func:`load_port_file` reads a topomark port world file (``"format": "topomark/port-world@1"``,
:mod:`topomark.spec.port_worldfile`), a contest map file (``{"problemName", "map"}``,
:mod:`topomark.spec.port_icfpc`) or a bare contest map object (``{"rooms", "startingRoom", "connections"}``, as a
``/guess`` body carries it).  The form is told by the keys: a ``format`` key means a port world file, a key of a
bare map means a bare map, anything else is read as a contest map file (whose reader names any unknown key).  Every
refusal is an :class:`~topomark.spec.errors.InvalidWorld` whose message starts with the file's name.
"""

from __future__ import annotations

from pathlib import Path

from topomark.spec.errors import InvalidWorld
from topomark.spec.jsontext import no_duplicate_keys, parse_json, read_text_file
from topomark.spec.port_icfpc import MAP_KEYS, map_from_json, submission_from_json
from topomark.spec.port_world import PortWorld
from topomark.spec.port_worldfile import PortDocument, port_world_from_json

__all__ = ["load_port_file", "load_port_document_file", "MAX_PORT_FILE_BYTES"]

MAX_PORT_FILE_BYTES = 64 << 20
"""The largest port world file read (a contest map of 100,000 rooms takes about 40 MB)."""


def load_port_document_file(path: str | Path) -> PortDocument:
    """The port world of the file at ``path`` with its room names (a port world file's ``names``) and its problem
    name (a port world file's ``problem``, a contest map file's ``problemName``), ``None`` where there are none."""
    text = read_text_file(path, InvalidWorld, MAX_PORT_FILE_BYTES)
    obj = parse_json(text, str(path), InvalidWorld, object_pairs_hook=no_duplicate_keys)
    try:
        if isinstance(obj, dict) and "format" in obj:
            return port_world_from_json(obj)
        if isinstance(obj, dict) and set(obj) & set(MAP_KEYS):
            return PortDocument(map_from_json(obj))
        name, world = submission_from_json(obj)
        return PortDocument(world, problem=name)
    except InvalidWorld as e:
        raise InvalidWorld(f"{path}: {e}") from None


def load_port_file(path: str | Path) -> tuple[str | None, PortWorld]:
    """The problem name (``None`` when the file has none) and the port world of the file at ``path``."""
    doc = load_port_document_file(path)
    return doc.problem, doc.world

"""The contest's problems and where a hidden map comes from (the ICFP Contest 2025's problem list).

The contest posed each problem by name with a number of rooms; its server drew a new random map each time a
problem was selected.  :data:`PROBLEMS` lists them: the single maps ``probatio`` (3 rooms), ``primus`` (6),
``secundus`` (12), ``tertius`` (18), ``quartus`` (24), ``quintus`` (30), and the later round's copy maps: ``aleph``
.. ``he``, two copies of 6 .. 30 rooms, and ``vau`` .. ``iod``, three copies of 6 .. 30 rooms.

:class:`Problems` answers "a hidden map for problem NAME", from three sources, the first that knows the name:

* **worlds given by file** (``--world NAME=FILE``): that port world, every time (any name, the contest's too);
* **a directory of maps** (``--maps DIR``, e.g. a folder of contest map files): a random map of the problem, its
  problem read from ``MANIFEST.tsv``'s ``problem`` column when the directory has one (``file`` and ``problem``
  columns, tab-separated), else from each file's ``problemName``;
* **generated** (no directory): :func:`~topomark.reference.port.generate.random_port_world` of the problem's base
  size, redrawn until it is minimal without marks (:func:`distinct_rooms`), as the contest's single maps were, and
  for a copy problem its :func:`~topomark.reference.port.generate.cover`; every draw comes from one seeded random
  stream, so a server started with the same ``--seed`` serves the same maps in the same order.

Examples
--------
>>> p = Problems(seed=1)
>>> w = p.draw("primus")
>>> w.rooms, distinct_rooms(w)
(6, 6)
>>> p.draw("aleph").rooms
12
>>> p.draw("nonesuch")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: unknown problem 'nonesuch' (problems: probatio, primus, secundus, tertius, quartus, quintus, aleph, beth, gimel, daleth, he, vau, zain, hhet, teth, iod)
"""

from __future__ import annotations

import csv
import random
import threading
from pathlib import Path

from topomark.spec.errors import InvalidInput, InvalidWorld, clip, require_input
from topomark.spec.port_world import PortWorld

from topomark.reference.port.files import load_port_file
from topomark.reference.port.generate import cover, random_port_world

__all__ = ["PROBLEMS", "Problems", "distinct_rooms", "MAX_DRAWS"]

PROBLEMS: dict[str, tuple[int, int]] = {
    "probatio": (3, 1), "primus": (6, 1), "secundus": (12, 1), "tertius": (18, 1), "quartus": (24, 1),
    "quintus": (30, 1),
    "aleph": (6, 2), "beth": (12, 2), "gimel": (18, 2), "daleth": (24, 2), "he": (30, 2),
    "vau": (6, 3), "zain": (12, 3), "hhet": (18, 3), "teth": (24, 3), "iod": (30, 3),
}
"""Problem name: (rooms of the base map, copies).  The hidden map has ``rooms × copies`` rooms."""

MAX_DRAWS = 1000
"""How many random worlds a generated problem draws before it reports that none was minimal."""


def distinct_rooms(world: PortWorld) -> int:
    """How many rooms of ``world`` some plan without marks tells apart: the classes of Moore's partition
    refinement on colours and door targets (a map is minimal without marks when this is its room count).

    >>> from topomark.spec.port_world import from_joins
    >>> distinct_rooms(from_joins([0, 0], [((0, 0), (1, 0)), ((0, 1), (1, 1))], 0, doors=2, alphabet=1))
    1
    """
    block = list(world.colours)
    while True:
        signature = [(block[r], *(block[world.target(r, d)] for d in range(world.doors)))
                     for r in range(world.rooms)]
        names: dict[tuple[int, ...], int] = {}
        refined = [names.setdefault(s, len(names)) for s in signature]
        if len(names) == len(set(block)):
            return len(names)
        block = refined


class Problems:
    """The hidden maps this server can serve (see the module's docstring); thread-safe."""

    def __init__(self, *, seed: int = 0, maps: str | Path | None = None,
                 worlds: dict[str, PortWorld] | None = None):
        self._rng = random.Random(seed)
        self._lock = threading.Lock()
        self.worlds = dict(worlds or {})
        self.maps: dict[str, list[PortWorld]] = {} if maps is None else _index(Path(maps))

    def names(self) -> list[str]:
        """Every problem name served: the given worlds', then the directory's (or the contest's, generated)."""
        rest = self.maps if self.maps else PROBLEMS
        return [*self.worlds, *(n for n in rest if n not in self.worlds)]

    def draw(self, name: str) -> PortWorld:
        """A hidden map for problem ``name``; :class:`InvalidInput` names an unknown problem."""
        if name in self.worlds:
            return self.worlds[name]
        require_input(name in (self.maps if self.maps else PROBLEMS),
                      f"unknown problem {clip(name, 40, quote=True)} (problems: {', '.join(self.names())})")
        with self._lock:
            if self.maps:
                return self._rng.choice(self.maps[name])
            seeds = [self._rng.randrange(2 ** 32) for _ in range(MAX_DRAWS)]
        return _generated(name, seeds)


def _generated(name: str, seeds: list[int]) -> PortWorld:
    rooms, copies = PROBLEMS[name]
    for seed in seeds:
        base = random_port_world(seed, rooms)
        if distinct_rooms(base) == rooms:
            return base if copies == 1 else cover(base, copies, seed)
    raise InvalidInput(f"no minimal map of {rooms} rooms in {MAX_DRAWS} random draws")


def _index(folder: Path) -> dict[str, list[PortWorld]]:
    """Problem name: its maps, named by ``MANIFEST.tsv`` when the folder has one, else by each file; every file is
    read (and checked) here, so a bad map stops the server before it serves."""
    require_input(folder.is_dir(), f"--maps {folder}: not a directory")
    manifest = folder / "MANIFEST.tsv"
    found: dict[str, list[PortWorld]] = {}
    if manifest.is_file():
        with manifest.open(newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f, delimiter="\t"))
        require_input(bool(rows) and {"file", "problem"} <= set(rows[0]),
                      f"--maps {manifest}: a manifest has the columns file and problem, tab-separated")
        for row in rows:
            path = folder / row["file"]
            require_input(path.is_file(), f"--maps {manifest}: it lists {clip(row['file'], 80, quote=True)}, "
                          "which is not a file there")
            found.setdefault(row["problem"], []).append(_load(path)[1])
    else:
        for path in sorted(folder.rglob("*.json")):
            name, world = _load(path)
            require_input(name is not None, f"--maps {path}: a map in a directory without MANIFEST.tsv needs its "
                          "problemName (a contest map file)")
            found.setdefault(str(name), []).append(world)
    require_input(bool(found), f"--maps {folder}: no map files (*.json) there")
    return found


def _load(path: Path) -> tuple[str | None, PortWorld]:
    try:
        return load_port_file(path)
    except InvalidWorld as e:
        raise InvalidInput(f"--maps: {e}") from None

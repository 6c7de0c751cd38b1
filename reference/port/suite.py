"""The contest's maps as a suite for the exact judge (the port-labelled model, :mod:`topomark.spec.port_world`).

:func:`run_suite` reads every contest map file under a folder and, for each map: imports it, minimises it
(:mod:`.minimise`) and compares the minimal size with the manifest's ``minimal_rooms`` (a ``MANIFEST.tsv`` with
columns ``file`` and ``minimal_rooms``), then judges it (:func:`.judge.judge`) against changed copies
(:mod:`.variants`): a relabelled copy (rooms renumbered; must be equivalent), a door-permuted copy (one room's doors
renumbered), single passage swaps (two passages' ends exchanged) and, for copy maps, layer swaps (two layers of one
passage of the quotient exchanged).  Every verdict is timed.  The changed copies are drawn from a seed made from the
file's path, so a run is repeatable.
"""

from __future__ import annotations

import random
import statistics
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path

from topomark.reference.port.files import load_port_file
from topomark.reference.port.judge import Verdict, judge
from topomark.reference.port.minimise import Minimised, minimise
from topomark.reference.port.variants import door_permuted, passage_swapped, relabelled, world_passages
from topomark.spec.errors import InvalidInput, InvalidWorld
from topomark.spec.jsontext import read_text_file
from topomark.spec.port_world import DoorEnd, PortWorld

__all__ = ["Trial", "MapResult", "run_suite", "read_manifest", "summary", "SWAPS", "MAX_MANIFEST_BYTES"]

MAX_MANIFEST_BYTES = 16 << 20
"""The largest manifest read."""

SWAPS = 2
"""Passage swaps and layer swaps tried per map."""


@dataclass(frozen=True)
class Trial:
    """One verdict: the kind of changed copy, what the judge said, and how long it took (seconds)."""

    kind: str
    equivalent: bool
    witness: str | None
    reason: str
    seconds: float


@dataclass
class MapResult:
    """What the suite found for one map file."""

    file: str
    rooms: int = 0
    minimal: int | None = None
    expected_minimal: int | None = None
    copies: int | None = None
    error: str | None = None
    trials: list[Trial] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """Imported, minimal size as the manifest says, and the relabelled copy judged equivalent."""
        return self.problem is None

    @property
    def problem(self) -> str | None:
        """What is wrong with the map's results, ``None`` when nothing is."""
        if self.error is not None:
            return self.error
        if self.expected_minimal is not None and self.minimal != self.expected_minimal:
            return f"minimal size {self.minimal}, the manifest says {self.expected_minimal}"
        if not all(t.equivalent for t in self.trials if t.kind == "relabelled"):
            return "the judge calls a relabelled copy different"
        return None


def read_manifest(path: Path) -> dict[str, int]:
    """``file`` → ``minimal_rooms`` from a tab-separated manifest with a header line."""
    lines = read_text_file(path, InvalidInput, MAX_MANIFEST_BYTES).splitlines()
    header = lines[0].split("\t") if lines else []
    if "file" not in header or "minimal_rooms" not in header:
        raise InvalidInput(f"{path}: a manifest needs the columns file and minimal_rooms")
    f, m = header.index("file"), header.index("minimal_rooms")
    sizes = {}
    for k, line in enumerate(lines[1:], start=2):
        row = line.split("\t")
        if not line.strip():
            continue
        if len(row) != len(header) or not row[m].isascii() or not row[m].isdigit():
            raise InvalidInput(f"{path}: line {k} does not have {len(header)} columns with a number of rooms in "
                               "minimal_rooms")
        sizes[row[f]] = int(row[m])
    return sizes


def run_suite(directory: Path, manifest: Path | None = None) -> list[MapResult]:
    """The suite's results for every ``*.json`` file under ``directory`` (see the module's docstring)."""
    if not directory.is_dir():
        raise InvalidInput(f"{directory}: not a folder")
    if manifest is None and (directory / "MANIFEST.tsv").is_file():
        manifest = directory / "MANIFEST.tsv"
    sizes = read_manifest(manifest) if manifest is not None else {}
    results = []
    for path in sorted(directory.rglob("*.json")):
        name = path.relative_to(directory).as_posix()
        result = MapResult(name, expected_minimal=sizes.get(name))
        try:
            _, world = load_port_file(path)
        except InvalidWorld as e:
            result.error = str(e)
            results.append(result)
            continue
        _one_map(world, result, random.Random(zlib.crc32(name.encode())))
        results.append(result)
    return results


def _timed(kind: str, a: PortWorld, b: PortWorld) -> Trial:
    t0 = time.perf_counter()
    v: Verdict = judge(a, b)
    return Trial(kind, v.equivalent, v.witness, v.reason, time.perf_counter() - t0)


def _one_map(world: PortWorld, result: MapResult, rng: random.Random) -> None:
    result.rooms = world.rooms
    m = minimise(world)
    result.minimal = m.quotient.rooms if m.quotient is not None else len(m.fibres)
    result.copies = m.copies
    perm = list(range(world.rooms))
    rng.shuffle(perm)
    result.trials.append(_timed("relabelled", world, relabelled(world, perm)))
    doors = list(range(world.doors))
    rng.shuffle(doors)
    result.trials.append(_timed("door-permuted", world, door_permuted(world, rng.randrange(world.rooms), doors)))
    proper = [(x, y) for x, y in world_passages(world) if x != y]
    for _ in range(SWAPS if len(proper) >= 2 else 0):
        (first, _), (second, _) = rng.sample(proper, 2)
        _try(result, "passage-swap", world, first, second)
    for first, second in _layer_pairs(world, m, rng)[:SWAPS]:
        _try(result, "layer-swap", world, first, second)


def _try(result: MapResult, kind: str, world: PortWorld, first: DoorEnd, second: DoorEnd) -> None:
    try:
        changed = passage_swapped(world, first, second)
    except InvalidInput:
        return  # the swap cut a room off, or the two ends are one passage: not a changed map
    result.trials.append(_timed(kind, world, changed))


def _layer_pairs(world: PortWorld, m: Minimised, rng: random.Random) -> list[tuple[DoorEnd, DoorEnd]]:
    """Pairs of door-ends over one door-end of the quotient (two layers of one passage of it)."""
    if m.copies is None or m.copies < 2:
        return []
    pairs = []
    for fibre in m.fibres:
        for d in range(world.doors):
            ends = [(r, d) for r in fibre if world.joins[r][d] != (r, d)]
            if len(ends) >= 2:
                pairs.append((ends[0], ends[1]))
    rng.shuffle(pairs)
    return pairs


def summary(results: list[MapResult]) -> dict[str, object]:
    """Counts, verdicts by kind and the median and maximum time per verdict (milliseconds)."""
    times = [t.seconds for r in results for t in r.trials]
    kinds: dict[str, dict[str, int]] = {}
    for t in (t for r in results for t in r.trials):
        row = kinds.setdefault(t.kind, {"equivalent": 0, "different": 0, "with-mark": 0})
        row["equivalent" if t.equivalent else "different"] += 1
        row["with-mark"] += t.witness is not None and "[" in t.witness
    return {"maps": len(results), "imported": sum(r.error is None for r in results),
            "minimal_as_manifest": sum(r.expected_minimal is not None and r.minimal == r.expected_minimal
                                       for r in results),
            "with_manifest_size": sum(r.expected_minimal is not None for r in results),
            "ok": sum(r.ok for r in results), "verdicts": len(times), "kinds": kinds,
            "median_ms": round(1000 * statistics.median(times), 3) if times else None,
            "max_ms": round(1000 * max(times), 3) if times else None}

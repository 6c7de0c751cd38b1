"""Census of indistinguishable worlds per marker class (thesis §3.2, §3.3, §3.7, §6.1).

For a marker class (:mod:`topomark.proofs.markerclass`) we take every small
embedded world (:mod:`topomark.proofs.enumerate`), every placement of the
class's markers and every start, and group the placements by the robot's
*language*: what it perceives under every motion sequence.

The robot on a marked world is a deterministic Moore machine: states are robot
states ``(vertex, entry)``, input a motion ``l`` in ``range(deg)``, output the
signature sensed in a state.  Since we demand equal start signatures (§3.1.1),
two placements are indistinguishable (§3.2) iff their start states are
Moore-equivalent.  :func:`minimise` computes Moore equivalence by partition
refinement; :func:`language_code` writes the minimal machine reachable from a
start with blocks numbered breadth-first in input order, a code equal for two
placements iff they are indistinguishable.  The census stores a 128-bit
BLAKE2b digest of that code; every counterexample it reports is re-checked by
:func:`topomark.proofs.bisim.distinguishing_sequence` and
:func:`topomark.spec.isomorphism.find_isomorphism`, so a (never observed)
digest collision could not produce a false counterexample.

A language class is *ambiguous* when it holds two marked worlds that are not
extended-isomorphic with markers preserved (the start is not compared): a
counterexample to the sufficiency of the marker class.  Worlds of different
sizes can be indistinguishable (Figure 3.3), so classes span all sizes ≤ N;
the table gives, per n, counts for worlds of exactly n vertices and
cumulative counts over all worlds of ≤ n vertices.

Examples
--------
>>> r = census("none", 4, 3)
>>> [(row.n, row.worlds, row.languages_upto, row.ambiguous_upto) for row in r.rows]
[(2, 1, 1, 0), (3, 2, 4, 0), (4, 9, 28, 2)]
>>> [w.n for w in r.smallest_counterexample]
[3, 4]
"""

from __future__ import annotations

import hashlib
import itertools
import sys
import time
from collections import deque
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Iterator

from topomark.proofs.enumerate import canonical_form, embedded_worlds
from topomark.proofs.markerclass import marker_class
from topomark.spec.errors import CheckFailure
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.robot import State, sense, step
from topomark.spec.world import World

__all__ = ["Machine", "machine", "minimise", "language_code", "language_digest", "SizeRow", "CensusResult",
           "census", "placement"]

Member = tuple[int, int, int, int, bytes]  # (n, m, world index, placement index, iso key of the marked world)


# -- the robot as a Moore machine -------------------------------------------------
@dataclass(frozen=True)
class Machine:
    """States 0..k-1 for the robot states of a marked world; ``succ[s][l]``; ``out[s]`` the signature text."""

    states: tuple[State, ...]
    index: dict[State, int]
    succ: tuple[tuple[int, ...], ...]
    out: tuple[str, ...]


def machine(world: World) -> Machine:
    """The robot's Moore machine on ``world`` (markers included, start ignored)."""
    states = tuple(world.darts())
    index = {s: k for k, s in enumerate(states)}
    succ = tuple(tuple(index[step(world, s, l)] for l in range(world.degree(s[0]))) for s in states)
    out = tuple(str(sense(world, s)) for s in states)
    return Machine(states, index, succ, out)


def _renumber(keys: Iterable[Any]) -> list[int]:
    ids: dict[Any, int] = {}
    return [ids.setdefault(k, len(ids)) for k in keys]


def minimise(mach: Machine) -> list[int]:
    """Moore equivalence by partition refinement: ``block[s]`` equal iff states are equivalent."""
    block = _renumber(mach.out)
    count = max(block) + 1
    while True:
        new = _renumber((block[s], tuple(block[t] for t in mach.succ[s])) for s in range(len(block)))
        new_count = max(new) + 1
        if new_count == count:
            return new
        block, count = new, new_count


def language_code(mach: Machine, block: list[int], start: int) -> tuple:
    """The minimal machine reachable from ``start``, blocks numbered breadth-first in input order."""
    rep: dict[int, int] = {}
    for s, b in enumerate(block):
        rep.setdefault(b, s)
    number = {block[start]: 0}
    todo = deque([block[start]])
    code: list[Any] = []
    while todo:
        s = rep[todo.popleft()]
        succ = []
        for t in mach.succ[s]:
            b = block[t]
            if b not in number:
                number[b] = len(number)
                todo.append(b)
            succ.append(number[b])
        code.append((mach.out[s], tuple(succ)))
    return tuple(code)


def language_digest(code: tuple) -> bytes:
    return hashlib.blake2b(repr(code).encode(), digest_size=16).digest()


# -- one chunk of worlds (runs in a worker process) ----------------------------------
def _world_languages(class_name: str, index: int, world: World) -> Iterator[tuple[bytes, Member]]:
    """(language digest, member) for every placement of the class on ``world``."""
    mc = marker_class(class_name)
    layouts: dict[tuple, tuple[Machine, list[int], bytes]] = {}
    for k, placed in enumerate(mc.placements(world)):
        key = tuple(sorted(map(repr, placed.markers)))
        if key not in layouts:
            marked = placed.with_start(None)
            mach = machine(marked)
            iso = language_digest(canonical_form(marked, markers=True))
            layouts[key] = (mach, minimise(mach), iso)
        mach, block, iso = layouts[key]
        code = language_code(mach, block, mach.index[placed.start_state()])
        yield language_digest(code), (world.n, world.m, index, k, iso)


def _insert(best: list[Member], member: Member) -> None:
    """Keep the (at most two) smallest members with distinct iso keys, sorted."""
    for k, other in enumerate(best):
        if other[4] == member[4]:
            best[k] = min(other, member)
            break
    else:
        best.append(member)
    best.sort()
    del best[2:]


def _chunk(job: tuple[str, list[tuple[int, dict]]]) -> tuple[dict[bytes, list], dict[int, list[int]]]:
    """Languages of a chunk of worlds: digest -> [size mask, best members]; n -> [worlds, placements]."""
    class_name, worlds = job
    langs: dict[bytes, list] = {}
    sizes: dict[int, list[int]] = {}
    for index, rotation in worlds:
        world = World(rotation)
        tally = sizes.setdefault(world.n, [0, 0])
        tally[0] += 1
        for digest, member in _world_languages(class_name, index, world):
            tally[1] += 1
            entry = langs.setdefault(digest, [0, []])
            entry[0] |= 1 << world.n
            _insert(entry[1], member)
    return langs, sizes


# -- the census ----------------------------------------------------------------------
@dataclass(frozen=True)
class SizeRow:
    """Counts for worlds of exactly ``n`` vertices and cumulative counts up to ``n``."""

    n: int
    worlds: int
    placements: int
    languages: int  # distinct languages among placements on n-vertex worlds
    languages_upto: int  # distinct languages among placements on worlds of <= n vertices
    ambiguous_upto: int  # of those, languages with >= 2 non-isomorphic marked worlds of <= n vertices

    def to_json(self) -> dict[str, int]:
        return dict(self.__dict__)


@dataclass(frozen=True)
class CensusResult:
    marker: str
    max_vertices: int
    max_degree: int
    rows: tuple[SizeRow, ...]
    smallest_counterexample: tuple[World, World] | None
    seconds: float = field(compare=False, default=0.0)

    @property
    def languages(self) -> int:
        return self.rows[-1].languages_upto if self.rows else 0

    @property
    def ambiguous(self) -> int:
        return self.rows[-1].ambiguous_upto if self.rows else 0


def placement(world: World, class_name: str, k: int) -> World:
    """The ``k``-th placement of the class on ``world`` (in :meth:`MarkerClass.placements` order)."""
    return next(itertools.islice(marker_class(class_name).placements(world), k, None))


def _chunks(class_name: str, worlds: list[World], size: int) -> Iterator[tuple[str, list[tuple[int, dict]]]]:
    for start in range(0, len(worlds), size):
        yield class_name, [(k, worlds[k].rotation) for k in range(start, min(start + size, len(worlds)))]


def _merge(results: Iterable, progress: Callable[[str], None] | None, total: int):
    langs: dict[bytes, list] = {}
    sizes: dict[int, list[int]] = {}
    done = 0
    for chunk_langs, chunk_sizes in results:
        for digest, (mask, members) in chunk_langs.items():
            entry = langs.setdefault(digest, [0, []])
            entry[0] |= mask
            for member in members:
                _insert(entry[1], member)
        for n, (w, p) in chunk_sizes.items():
            tally = sizes.setdefault(n, [0, 0])
            tally[0] += w
            tally[1] += p
            done += w
        if progress:
            progress(f"census: {done}/{total} worlds, {len(langs)} languages")
    return langs, sizes


def _rows(langs: dict[bytes, list], sizes: dict[int, list[int]], min_n: int, max_n: int) -> tuple[SizeRow, ...]:
    rows = []
    for n in range(min_n, max_n + 1):
        upto = (1 << (n + 1)) - 1
        rows.append(SizeRow(
            n, sizes.get(n, [0, 0])[0], sizes.get(n, [0, 0])[1],
            sum(1 for mask, _ in langs.values() if mask >> n & 1),
            sum(1 for mask, _ in langs.values() if mask & upto),
            sum(1 for _, best in langs.values() if len(best) == 2 and best[1][0] <= n)))
    return tuple(rows)


def _smallest(langs: dict[bytes, list], worlds: list[World], class_name: str) -> tuple[World, World] | None:
    """The ambiguous class whose two smallest members are smallest (max size, then min size); re-checked."""
    pairs = [best for _, best in langs.values() if len(best) == 2]
    if not pairs:
        return None
    best = min(pairs, key=lambda b: (b[1][0], b[1][1], b[0][0], b[0][1], b[0][2:4], b[1][2:4]))
    a, b = (placement(worlds[mem[2]], class_name, mem[3]) for mem in best)
    from topomark.proofs.bisim import distinguishing_sequence  # late import: bisim is independent of the census
    if distinguishing_sequence(a, b) is not None or find_isomorphism(a, b, markers=True).isomorphic:
        raise CheckFailure(f"census: the {class_name} counterexample candidate fails the independent re-check")
    return a, b


def census(class_name: str, max_vertices: int, max_degree: int, jobs: int = 1, min_vertices: int = 2,
           progress: Callable[[str], None] | None = None, chunk_size: int = 200) -> CensusResult:
    """Group every placement of ``class_name`` on worlds of ``min..max_vertices`` vertices by language.

    The result does not depend on ``jobs`` (chunks are merged in order and
    the kept members are minima of a total order).
    """
    marker_class(class_name)  # validates the name
    t0 = time.perf_counter()
    worlds = list(embedded_worlds(max_vertices, max_degree, min_vertices))
    jobs_list = list(_chunks(class_name, worlds, chunk_size))
    if jobs > 1 and len(jobs_list) > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            langs, sizes = _merge(pool.map(_chunk, jobs_list), progress, len(worlds))
    else:
        langs, sizes = _merge(map(_chunk, jobs_list), progress, len(worlds))
    rows = _rows(langs, sizes, max(min_vertices, 2), max_vertices)
    pair = _smallest(langs, worlds, class_name)
    return CensusResult(class_name, max_vertices, max_degree, rows, pair, time.perf_counter() - t0)


def stderr_progress(message: str) -> None:
    print(message, file=sys.stderr, flush=True)

"""Census of indistinguishable worlds per marker class (thesis §3.2, §3.3, §3.7, §6.1).

For a marker class (:mod:`topomark.spec.markerclass`) we take every small
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

:func:`census` is the in-memory census (every digest in one dict, merged
serially): simple, and the reference the sharded census
(:func:`topomark.proofs.census_run.sharded_census`, used by ``topomark
census``) is compared with in ``tests/test_census_shards.py``.

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
from operator import itemgetter
from typing import Any, Callable, Iterable, Iterator

from topomark.proofs.bisim import distinguishing_sequence
from topomark.proofs.census_exec import worker_count
from topomark.proofs.enumerate import canonical_form, embedded_worlds
from topomark.spec.markerclass import marker_class
from topomark.spec.errors import CheckFailure
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.marker import VertexMarker
from topomark.spec.robot import State, sense, step
from topomark.spec.world import World

__all__ = ["Machine", "machine", "minimise", "representatives", "language_code", "language_digest", "SizeRow",
           "CensusResult", "census", "placement", "stderr_progress",
           "marker_layouts", "marker_key", "recheck_pair"]

Member = tuple[int, int, int, int, bytes]  # (n, m, world index, placement index, iso key of the marked world)


# -- the robot as a Moore machine -------------------------------------------------
@dataclass(frozen=True)
class Machine:
    """States 0..k-1 for the robot states of a marked world; ``succ[s][l]``; ``out[s]`` the signature text."""

    states: tuple[State, ...]
    index: dict[State, int]
    succ: tuple[tuple[int, ...], ...]
    out: tuple[str, ...]


def machine(world: World, base: Machine | None = None) -> Machine:
    """The robot's Moore machine on ``world`` (markers included, start ignored).

    ``base`` — the machine of the same rotation system without markers — is
    reused for the transitions; only the outputs at marked vertices are recomputed.
    """
    if base is None:
        states = tuple(world.darts())
        index = {s: k for k, s in enumerate(states)}
        succ = tuple(tuple(index[step(world, s, l)] for l in range(world.degree(s[0]))) for s in states)
        return Machine(states, index, succ, tuple(str(sense(world, s)) for s in states))
    out = list(base.out)
    for v in _marked_vertices(world):
        for i in range(world.degree(v)):
            out[base.index[(v, i)]] = str(sense(world, (v, i)))
    return Machine(base.states, base.index, base.succ, tuple(out))


def _marked_vertices(world: World) -> set[str]:
    """Vertices whose signatures a marker can change: marked vertices and ends of marked edges."""
    marked: set[str] = set()
    for m in world.markers:
        marked.update((m.at,) if isinstance(m, VertexMarker) else m.between)
    return marked


def _renumber(keys: Iterable[Any]) -> list[int]:
    ids: dict[Any, int] = {}
    return [ids.setdefault(k, len(ids)) for k in keys]


def minimise(mach: Machine) -> list[int]:
    """Moore equivalence by partition refinement: ``block[s]`` equal iff states are equivalent.

    Blocks are numbered by first occurrence; a state's key in a round is its
    block and its successors' blocks (read by one ``itemgetter`` per state).
    """
    block = _renumber(mach.out)
    count = max(block) + 1
    getters = [itemgetter(*succ) for succ in mach.succ]
    while True:
        ids: dict[Any, int] = {}
        new = [ids.setdefault((block[s], get(block)), len(ids)) for s, get in enumerate(getters)]
        if len(ids) == count:
            return new
        block, count = new, len(ids)


def representatives(block: list[int]) -> dict[int, int]:
    """One state of every block."""
    rep: dict[int, int] = {}
    for s, b in enumerate(block):
        rep.setdefault(b, s)
    return rep


def language_code(mach: Machine, block: list[int], start: int, rep: dict[int, int] | None = None) -> tuple:
    """The minimal machine reachable from ``start``, blocks numbered breadth-first in input order.

    Equal for two placements iff their start states are Moore-equivalent:
    the quotient by equivalence is the minimal machine, and a breadth-first
    numbering in input order is a canonical labelling of a deterministic
    machine whose states are all reachable from the initial one.
    """
    if rep is None:
        rep = representatives(block)
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
    """A 128-bit BLAKE2b digest of a code (see the module docstring on collisions)."""
    return hashlib.blake2b(repr(code).encode(), digest_size=16).digest()


# -- one chunk of worlds (runs in a worker process) ----------------------------------
def marker_layouts(class_name: str, world: World) -> Iterator[tuple[int, tuple, list[State]]]:
    """(index of its first placement, markers, starts) per marker layout, in ``placements`` order.

    :meth:`MarkerClass.placements` yields, for each vertex v and each layout
    at v, one world per facing in rotation order; we list each layout once
    with its starts ``(v, i)`` instead (``tests/test_census.py`` checks that
    the order and the worlds agree with ``placements``).
    """
    mc = marker_class(class_name)
    k = 0
    for v in world.vertices:
        for markers in mc.layouts(world, v):
            starts = [(v, i) for i in range(world.degree(v))]
            yield k, tuple(markers), starts
            k += len(starts)


def marker_key(markers: Iterable) -> frozenset:
    """The layout as a set (an edge marker's two spellings (u, v) and (v, u) are one layout)."""
    return frozenset((m.at, m.count, m.points_to) if isinstance(m, VertexMarker)
                     else (frozenset(m.between), m.count, m.head) for m in markers)


def _world_languages(class_name: str, index: int, world: World) -> Iterator[tuple[bytes, Member]]:
    """(language digest, member) for every placement of the class on ``world``.

    A member's iso key identifies its marked world up to extended isomorphism:
    the digest of its canonical form, or — when the class has a single layout
    on this world — the world's index (worlds of the enumeration are pairwise
    non-isomorphic, so marked worlds on different ones never are).
    """
    layouts = list(marker_layouts(class_name, world))
    single = len({marker_key(markers) for _, markers, _ in layouts}) == 1
    base = machine(world)
    cache: dict[frozenset, tuple] = {}
    for k, markers, starts in layouts:
        key = marker_key(markers)
        if key not in cache:
            marked = World(world.rotation, markers)
            mach = machine(marked, base)
            iso = b"#%d" % index if single else language_digest(canonical_form(marked, markers=True))
            block = minimise(mach)
            cache[key] = (mach, block, representatives(block), iso, {})
        mach, block, rep, iso, digests = cache[key]
        for j, start in enumerate(starts):
            b = block[mach.index[start]]
            if b not in digests:  # equivalent starts have the same language
                digests[b] = language_digest(language_code(mach, block, mach.index[start], rep))
            yield digests[b], (world.n, world.m, index, k + j, iso)


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


@dataclass(frozen=True, repr=False)
class CensusResult:
    """Every placement of a marker class on every small world, grouped by the language the robot perceives.

    ``rows`` counts worlds, placements and languages per size (:class:`SizeRow`); :attr:`languages` and
    :attr:`ambiguous` are the totals up to ``max_vertices``; ``smallest_counterexample`` is the smallest
    indistinguishable, non-isomorphic pair (re-checked), or None when the class suffices at these sizes.
    """

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

    def __repr__(self) -> str:
        """``CensusResult(marker='none', max_vertices=4, max_degree=3, 96 placements, 29 languages, 2 ambiguous,
        counterexample n=3 and n=4, 0.1 s)``."""
        pair = self.smallest_counterexample
        found = "no counterexample" if pair is None else f"counterexample n={pair[0].n} and n={pair[1].n}"
        return (f"CensusResult(marker={self.marker!r}, max_vertices={self.max_vertices}, "
                f"max_degree={self.max_degree}, {sum(r.placements for r in self.rows)} placements, "
                f"{self.languages} languages, {self.ambiguous} ambiguous, {found}, {self.seconds:.1f} s)")


def placement(world: World, class_name: str, k: int) -> World:
    """The ``k``-th placement of the class on ``world`` (in :meth:`MarkerClass.placements` order)."""
    return next(itertools.islice(marker_class(class_name).placements(world), k, None))


def _chunks(class_name: str, worlds: list[World], size: int) -> Iterator[tuple[str, list[tuple[int, dict]]]]:
    for start in range(0, len(worlds), size):
        yield class_name, [(k, worlds[k].rotation) for k in range(start, min(start + size, len(worlds)))]


def _merge(results: Iterable, progress: Callable[[str], None] | None, total: int):
    langs: dict[bytes, list] = {}
    sizes: dict[int, list[int]] = {}
    done, last = 0, time.perf_counter()
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
        now = time.perf_counter()
        if progress and (done == total or now - last >= 2.0):
            progress(f"census: {done}/{total} worlds, {len(langs)} languages")
            last = now
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


def _recheck(best: list[Member], worlds: list[World], class_name: str) -> tuple[World, World]:
    """Rebuild the two members of an ambiguous class and re-check them with bisim and find_isomorphism."""
    return recheck_pair([(worlds[mem[2]], mem[3]) for mem in best], class_name)


def recheck_pair(members: list[tuple[World, int]], class_name: str) -> tuple[World, World]:
    """Placements ``(world, k)`` of an ambiguous class, re-checked: indistinguishable, not isomorphic."""
    a, b = (placement(world, class_name, k) for world, k in members)
    if distinguishing_sequence(a, b) is not None or find_isomorphism(a, b, markers=True).isomorphic:
        raise CheckFailure(f"census: a {class_name} counterexample candidate fails the independent re-check")
    return a, b


def _smallest(langs: dict[bytes, list], worlds: list[World], class_name: str,
              verify_all: bool) -> tuple[World, World] | None:
    """The ambiguous class whose two smallest members are smallest (larger size, then smaller); re-checked."""
    pairs = [best for _, best in langs.values() if len(best) == 2]
    if verify_all:
        for best in pairs:
            _recheck(best, worlds, class_name)
    if not pairs:
        return None
    best = min(pairs, key=lambda b: (b[1][0], b[1][1], b[0][0], b[0][1], b[0][2:4], b[1][2:4]))
    return _recheck(best, worlds, class_name)


def census(class_name: str, max_vertices: int, max_degree: int, jobs: int = 1, min_vertices: int = 2,
           progress: Callable[[str], None] | None = None, chunk_size: int = 200,
           verify_all: bool = False) -> CensusResult:
    """Group every placement of ``class_name`` on worlds of ``min..max_vertices`` vertices by language.

    The result does not depend on ``jobs`` (chunks are merged in order and
    the kept members are minima of a total order).  The smallest
    counterexample is always re-checked independently; with ``verify_all``
    the two smallest members of every ambiguous class are.
    """
    marker_class(class_name)  # validates the name
    t0 = time.perf_counter()
    worlds = list(embedded_worlds(max_vertices, max_degree, min_vertices))
    jobs_list = list(_chunks(class_name, worlds, chunk_size))
    if jobs > 1 and len(jobs_list) > 1:
        with ProcessPoolExecutor(max_workers=worker_count(jobs, len(jobs_list))) as pool:
            langs, sizes = _merge(pool.map(_chunk, jobs_list), progress, len(worlds))
    else:
        langs, sizes = _merge(map(_chunk, jobs_list), progress, len(worlds))
    rows = _rows(langs, sizes, max(min_vertices, 2), max_vertices)
    pair = _smallest(langs, worlds, class_name, verify_all)
    return CensusResult(class_name, max_vertices, max_degree, rows, pair, time.perf_counter() - t0)


def stderr_progress(message: str) -> None:
    print(message, file=sys.stderr, flush=True)

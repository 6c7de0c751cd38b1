"""Port worlds consistent with plans and their records, found by Z3 (the port-labelled model, Table 2.3's labelled
graph; :mod:`topomark.spec.port_world`, :mod:`topomark.spec.port_plan`).

Given plans (marks allowed), their records, a room count ``n``, ``doors`` and ``alphabet``, :class:`ConsistentSearch`
finds a port world with ``n`` rooms whose start room 0 gives every record, and then, on request, one that is not
equivalent to worlds already found (:meth:`ConsistentSearch.find` with ``unlike``).  Every world it returns is built
by :func:`~topomark.spec.port_world.from_joins` (so it is a valid world) and every record is replayed on it with
:func:`~topomark.spec.port_plan.run_plan` before it is returned; a world that fails the replay is this encoding's
own fault (:class:`~topomark.spec.errors.TopomarkFault`).

*Variables* (Booleans, folded constants).  ``pair[e, f]`` for door-ends ``e <= f``: the passage joins ``e`` to ``f``
(``e = f``: a door joined to itself), exactly one per door-end, so joining is an involution; ``go[r, d][r2]``: door
``d`` of room ``r`` leads to ``r2`` (the disjunction of the pairs), exactly one ``r2``; ``col[r]`` one-hot over the
alphabet; per plan and position ``t`` (doors passed so far) ``at[t]`` one-hot over rooms, ``at[0]`` = room 0, and
``at[t] ∧ go ⇒ at[t+1]``.  A mark made at position ``p`` applies to every later position ``t > p`` the robot spends in
the same room, until a later mark there: with ``same(t, p) ⇔ ∨_r at[t][r] ∧ at[p][r]``, the record's colour ``o`` at
``t`` is asserted by (i) every earlier mark of another colour that is on this room is overridden by a later mark of
colour ``o`` on it, and (ii) if no earlier mark is on this room, the room's own colour is ``o``.  A mark's echo (when
records carry it) must equal the mark; a record of another length or an echo that differs is refused before Z3 runs.

*Symmetry breaking: rooms numbered in breadth-first order.*  Process rooms 0, 1, 2, ... in number order and each
room's doors 0 .. d-1 in order, giving each room not yet numbered the next number when a door first leads to it
(room 0 is the start).  The encoding asserts, with ``adj[i][j] ⇔ ∨_d go[i, d][j]`` for ``i < j``: every room
``j >= 1`` has a *parent* ``par(j)``, its smallest neighbour (which is below ``j``); ``par(j) <= par(j+1)``; and if
``par(j) = par(j+1) = i``, the first door of ``i`` to ``j`` comes before the first door of ``i`` to ``j+1``.  Write
``key(j) = (par(j), first door of par(j) to j)``; the constraints say the keys increase with ``j``.

*No solution is lost.*  Let ``W`` be any world with ``n`` rooms consistent with the records.  Renaming its rooms by
the breadth-first numbering ``β`` from its start gives an isomorphic world ``W'`` (doors, door-end pairings and
colours carried along) with start 0; records depend only on which door leads where and on colours, so ``W'`` gives
the same records.  ``W'`` meets the constraints: room ``j`` is numbered while its first neighbour in processing order
is processed, so its parent is its smallest neighbour and is below ``j``; rooms processed earlier number their
new neighbours earlier (parents never decrease), and one room's new neighbours are numbered in door order (first
doors increase).  Since every room has a parent below it, the constraints also make every world connected.

*One canonical form per rooted world.*  Let ``σ`` be any numbering of ``W`` meeting the constraints; by induction it
agrees with ``β``: both give the start 0; suppose they agree on rooms numbered ``0 .. j-1`` and let ``x = σ⁻¹(j)``,
``y = β⁻¹(j)``, ``x ≠ y``.  Breadth-first search numbers next the unnumbered room whose smallest numbered neighbour
and first door from it come first, so ``key_β(y) < key_β(x)`` (keys of two rooms differ: a door leads to one room).
Say ``σ(y) = k > j``; ``y``'s β-parent ``i < j`` is numbered the same by ``σ``, so ``par_σ(y) <= i``; and a smaller
σ-neighbour of ``y`` would be a room numbered below ``i``, hence below ``j`` in both, contradicting ``β``'s choice of
``i``; so ``key_σ(y) = key_β(y)``, and likewise ``key_σ(x) = key_β(x)`` (``x``'s smallest σ-neighbour is below
``j``).  Then ``key_σ(y) < key_σ(x)`` although ``σ(x) = j < k = σ(y)``: the keys would not increase.  So a world
has exactly one numbering meeting the constraints, and two rooted worlds are isomorphic (door targets and colours)
exactly when their canonical door-target tables and colours are equal, which is what ``unlike`` blocks.

Examples
--------
>>> from topomark.spec.port_plan import parse_plan
>>> s = ConsistentSearch(2, [parse_plan("0", doors=1, alphabet=2)], [(0, 1)], doors=1, alphabet=2)
>>> found = s.find()
>>> found.status, found.world.colours, found.world.joins
('found', (0, 1), (((1, 0),), ((0, 0),)))
>>> s.find(unlike=[found.world]).status
'none'
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Sequence

import z3

from topomark.spec.errors import InvalidInput, TopomarkFault, require_input
from topomark.spec.port_plan import Action, doors_in, run_plan
from topomark.spec.port_world import DoorEnd, PortWorld, from_joins

from topomark.proofs.z3formula import Builder, and_, not_, or_

__all__ = ["ConsistentSearch", "Found", "MAX_SOLVE_ROOMS", "record_length"]

MAX_SOLVE_ROOMS = 128
"""The most rooms asked of the solver (the encoding grows with the square of the door-ends)."""


@dataclass(frozen=True)
class Found:
    """One answer of :meth:`ConsistentSearch.find`: ``status`` ``"found"`` (with ``world``), ``"none"`` (no such
    world) or ``"unknown"`` (Z3 gave up, ``reason`` says why, usually the timeout); ``seconds`` spent in Z3."""

    status: str
    world: PortWorld | None = None
    reason: str = ""
    seconds: float = 0.0


def record_length(actions: Sequence[Action], echo_marks: bool) -> int:
    """The length of a plan's record: one colour per door, one for the start, one per mark when echoed."""
    marks = len(actions) - doors_in(actions)
    return 1 + doors_in(actions) + (marks if echo_marks else 0)


class ConsistentSearch:
    """The worlds of ``rooms`` rooms, start 0, consistent with ``records`` of ``plans`` (module docstring)."""

    def __init__(self, rooms: int, plans: Sequence[Sequence[Action]], records: Sequence[Sequence[int]], *,
                 doors: int = 6, alphabet: int = 4, echo_marks: bool = True):
        require_input(1 <= rooms <= MAX_SOLVE_ROOMS, f"rooms: 1 to {MAX_SOLVE_ROOMS}, not {rooms}")
        require_input(len(plans) == len(records), f"{len(plans)} plans but {len(records)} records")
        self.rooms, self.doors, self.alphabet, self.echo = rooms, doors, alphabet, echo_marks
        self.plans, self.records = [tuple(p) for p in plans], [tuple(r) for r in records]
        for k, (plan, record) in enumerate(zip(self.plans, self.records)):
            _check_record(k, plan, record, doors, alphabet, echo_marks)
        self.b = Builder()
        self._world()
        self._breadth_first()
        for k, (plan, record) in enumerate(zip(self.plans, self.records)):
            self._plan(k, plan, record)
        self.solver = z3.SolverFor("QF_FD")
        self.solver.from_string(self.b.text())

    # -- the world ------------------------------------------------------------------------------------------
    def _world(self) -> None:
        b, n, D = self.b, self.rooms, self.doors
        ends = [(r, d) for r in range(n) for d in range(D)]
        self.pair = {(e, f): b.var(f"j{e[0]}_{e[1]}_{f[0]}_{f[1]}") for i, e in enumerate(ends) for f in ends[i:]}
        touching: dict[DoorEnd, list[str]] = {e: [] for e in ends}
        for (x, y), v in self.pair.items():
            touching[x].append(v)
            if y != x:
                touching[y].append(v)
        for e in ends:
            lits = touching[e]
            b.add(or_(lits))
            b.asserts.append(f"(assert ((_ at-most 1) {' '.join(lits)}))")
        self.go: dict[DoorEnd, dict[int, object]] = {}
        for r, d in ends:
            self.go[r, d] = {}
            for r2 in range(n):
                v = b.var(f"go{r}_{d}_{r2}")
                ps = [self.pair[min((r, d), (r2, d2)), max((r, d), (r2, d2))] for d2 in range(D)]
                b.add(f"(= {v} {or_(ps)})")
                self.go[r, d][r2] = v
        self.col = {r: b.onehot(f"col{r}", range(self.alphabet)) for r in range(n)}

    def _breadth_first(self) -> None:
        b, n, D = self.b, self.rooms, self.doors
        adj = {(i, j): b.var(f"adj{i}_{j}") for j in range(n) for i in range(j)}
        for (i, j), v in adj.items():
            b.add(f"(= {v} {or_([self.go[i, d][j] for d in range(D)])})")
        par = {(j, i): b.var(f"par{j}_{i}") for j in range(1, n) for i in range(j)}
        for (j, i), v in par.items():
            b.add(f"(= {v} {and_([adj[i, j]] + [not_(adj[k, j]) for k in range(i)])})")
        for j in range(1, n):
            b.add(or_([par[j, i] for i in range(j)]))
            if j + 1 >= n:
                continue
            for i in range(j):
                for k in range(i):
                    b.implies([par[j, i]], not_(par[j + 1, k]))
                for d in range(D):  # the first door of i to j is d: no door of i before or at d leads to j+1
                    first = and_([self.go[i, d][j]] + [not_(self.go[i, e][j]) for e in range(d)])
                    for e in range(d + 1):
                        b.implies([par[j, i], par[j + 1, i], first], not_(self.go[i, e][j + 1]))

    # -- the records ----------------------------------------------------------------------------------------
    def _plan(self, k: int, plan: Sequence[Action], record: Sequence[int]) -> None:
        b, n = self.b, self.rooms
        at: list[dict[int, object]] = [{r: r == 0 for r in range(n)}]
        marks: list[tuple[int, int]] = []  # (position, colour), in plan order
        observed: list[tuple[int, int]] = [(0, record[0])]
        entry = 1
        for action in plan:
            if action.kind == "mark":
                marks.append((len(at) - 1, action.value))
                entry += 1 if self.echo else 0
                continue
            t = len(at)
            here = b.onehot(f"at{k}_{t}", range(n))
            for r in range(n):
                for r2 in range(n):
                    b.implies([at[t - 1][r], self.go[r, action.value][r2]], here[r2])
            at.append(here)
            observed.append((t, record[entry]))
            entry += 1
        for t, colour in observed:
            self._observe(k, at, t, colour, [m for m in marks if m[0] < t])

    def _observe(self, k: int, at: list[dict[int, object]], t: int, colour: int, marks: list[tuple[int, int]]) -> None:
        b, n = self.b, self.rooms
        same: list[object] = []
        for p, _ in marks:
            s = b.var(f"same{k}_{t}_{p}_{len(same)}")
            for r in range(n):
                b.implies([at[t][r], at[p][r]], s)
                b.implies([s, at[t][r]], at[p][r])
            same.append(s)
        for m, (_, c) in enumerate(marks):
            if c != colour:  # a mark of another colour on this room is overridden later by one of this colour
                b.add(or_([not_(same[m])] + [same[m2] for m2 in range(m + 1, len(marks)) if marks[m2][1] == colour]))
        for r in range(n):
            b.add(or_([not_(at[t][r]), self.col[r].get(colour, False)] + same))

    # -- answers ---------------------------------------------------------------------------------------------
    def find(self, *, unlike: Sequence[PortWorld] = (), timeout: float | None = None) -> Found:
        """A world consistent with the records and not isomorphic to any world of ``unlike`` (each in the
        canonical numbering this search gives its worlds); ``timeout`` in seconds bounds this call."""
        for world in unlike:
            require_input(world.rooms == self.rooms and world.doors == self.doors,
                          "unlike: a world of another size")
            self.solver.add(z3.Or([z3.Not(z3.Bool(str(self.go[r, d][world.target(r, d)])))
                                   for r in range(self.rooms) for d in range(self.doors)]
                                  + [z3.Not(z3.Bool(str(self.col[r][world.colours[r]]))) for r in range(self.rooms)
                                     if world.colours[r] in self.col[r]]))
        self.solver.set("timeout", 0 if timeout is None else max(1, int(timeout * 1000)))
        started = time.monotonic()
        verdict = self.solver.check()
        seconds = time.monotonic() - started
        if verdict == z3.unsat:
            return Found("none", seconds=seconds)
        if verdict != z3.sat:
            why = self.solver.reason_unknown()
            return Found("unknown", reason="timeout" if "timeout" in why or "canceled" in why else why,
                         seconds=seconds)
        world = self._decode(self.solver.model())
        for k, (plan, record) in enumerate(zip(self.plans, self.records)):
            if run_plan(world, plan, echo_marks=self.echo) != record:
                raise TopomarkFault(f"the solver's world does not give record {k} when replayed", "port_consistent")
        return Found("found", world, seconds=seconds)

    def _decode(self, model: z3.ModelRef) -> PortWorld:
        def true(lit: object) -> bool:
            return lit if isinstance(lit, bool) else z3.is_true(model.eval(z3.Bool(str(lit)), model_completion=True))

        passages = [pair for pair, v in self.pair.items() if true(v)]
        colours = []
        for r in range(self.rooms):
            hits = [c for c, v in self.col[r].items() if true(v)]
            if len(hits) != 1:
                raise TopomarkFault(f"the solver gave room {r} {len(hits)} colours", "port_consistent")
            colours.append(hits[0])
        try:
            return from_joins(colours, passages, 0, doors=self.doors, alphabet=self.alphabet)
        except InvalidInput as e:
            raise TopomarkFault(f"the solver's world is not a port world: {e}", "port_consistent") from None


def _check_record(k: int, plan: Sequence[Action], record: Sequence[int], doors: int, alphabet: int,
                  echo: bool) -> None:
    want = record_length(plan, echo)
    require_input(len(record) == want, f"record {k} has {len(record)} colours, but its plan has "
                  f"{doors_in(plan)} doors and {len(plan) - doors_in(plan)} marks, so {want} "
                  f"({'with' if echo else 'without'} the marks' echo)")
    for i, c in enumerate(record):
        require_input(isinstance(c, int) and not isinstance(c, bool) and 0 <= c < alphabet,
                      f"record {k}, entry {i}: {c!r} is not a colour 0..{alphabet - 1}")
    entry = 1
    for action in plan:
        require_input(action.kind == "mark" or 0 <= action.value < doors, f"plan {k}: door {action.value} is not a "
                      f"door 0..{doors - 1}")
        if action.kind == "mark" and echo:
            require_input(record[entry] == action.value, f"record {k}, entry {entry}: the echo of mark "
                          f"[{action.value}] is {record[entry]}; a mark's echo is the colour it writes")
        entry += 1 if action.kind == "door" or echo else 0

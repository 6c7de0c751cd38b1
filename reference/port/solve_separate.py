"""Telling two port worlds apart, for the solver's own cross-check (the port-labelled model,
:mod:`topomark.spec.port_world`; Table 2.3's labelled graph with rewritable colours).

Two deciders of the contest's equivalence (no plan, marks included, tells the worlds apart), independent of each
other and of Z3:

* :func:`canonical_form` numbers rooms in breadth-first order from the start (doors in order) and gives the
  door-target table and colours; two worlds are equivalent exactly when their forms are equal (rooted isomorphism
  of door targets and colours; door-end pairings are never seen, since a record shows colours only).
* :func:`separating_plan` searches the product of the two worlds from their starts.  A reachable pair of rooms with
  different colours gives the shortest plan without marks that separates them.  Otherwise the reachable pairs form a
  relation ``R``; if ``R`` is a bijection it respects doors and colours, so the worlds are isomorphic.  If not, some
  room ``a`` is paired with two rooms ``b ≠ b'`` (by walks ``p``, ``q``; or the same with the worlds' roles
  swapped).  Let ``r`` walk from ``a`` back to the start in the first world.  Either ``p·r·q`` ends in ``B`` away
  from ``b``: then the plan ``p [c] r q`` with ``c`` not ``a``'s colour ends on the marked room in the first world
  and on an unmarked room of ``a``'s colour (no plan without marks separates them) in the second; or it ends at
  ``b``, so ``p·r`` does not end at the second world's start, and ``[c] p r`` (``c`` not the start's colour)
  separates them.  One mark, and walks of at most about ``3n`` doors.  Every plan returned has been replayed on both
  worlds.  With a one-colour alphabet no mark shows anything, so only colours (never different) could separate.

Examples
--------
>>> from topomark.spec.port_world import from_joins
>>> one = from_joins([0], [((0, 0), (0, 0)), ((0, 1), (0, 1))], 0, doors=2, alphabet=2)
>>> two = from_joins([0, 0], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=2)
>>> plan_text(separating_plan(one, two))
'[1]0'
>>> canonical_form(one) == canonical_form(two), separating_plan(two, two)
(False, None)
"""

from __future__ import annotations

from collections import deque
from typing import Sequence

from topomark.spec.errors import TopomarkFault
from topomark.spec.port_plan import Action, plan_text, run_plan
from topomark.spec.port_world import PortWorld

__all__ = ["canonical_form", "separating_plan", "plan_text"]


def canonical_form(world: PortWorld) -> tuple[tuple[int, ...], tuple[tuple[int, ...], ...]]:
    """The colours and door-target table of ``world`` with rooms numbered in breadth-first order from the start."""
    number = {world.start: 0}
    order = [world.start]
    for room in order:  # grows while it is read: breadth-first
        for door in range(world.doors):
            t = world.target(room, door)
            if t not in number:
                number[t] = len(order)
                order.append(t)
    colours = tuple(world.colours[r] for r in order)
    table = tuple(tuple(number[world.target(r, d)] for d in range(world.doors)) for r in order)
    return colours, table


def _walks(a: PortWorld, b: PortWorld) -> dict[tuple[int, int], tuple[int, ...]]:
    """The shortest door walk to every pair of rooms reachable in the product, in breadth-first order."""
    first = (a.start, b.start)
    walks: dict[tuple[int, int], tuple[int, ...]] = {first: ()}
    queue = deque([first])
    while queue:
        x, y = queue.popleft()
        for d in range(min(a.doors, b.doors)):
            nxt = (a.target(x, d), b.target(y, d))
            if nxt not in walks:
                walks[nxt] = walks[x, y] + (d,)
                queue.append(nxt)
    return walks


def _home(world: PortWorld, room: int) -> tuple[int, ...]:
    """A shortest walk from ``room`` back to the start."""
    walks: dict[int, tuple[int, ...]] = {room: ()}
    queue = deque([room])
    while queue:
        x = queue.popleft()
        if x == world.start:
            return walks[x]
        for d in range(world.doors):
            y = world.target(x, d)
            if y not in walks:
                walks[y] = walks[x] + (d,)
                queue.append(y)
    raise TopomarkFault(f"room {room} has no walk back to the start", "solve_separate")


def _end(world: PortWorld, walk: Sequence[int]) -> int:
    room = world.start
    for d in walk:
        room = world.target(room, d)
    return room


def _plan(walk: Sequence[int], mark: int | None = None, then: Sequence[int] = ()) -> tuple[Action, ...]:
    marked = () if mark is None else (Action("mark", mark),)
    return tuple(Action("door", d) for d in walk) + marked + tuple(Action("door", d) for d in then)


def _marked(a: PortWorld, b: PortWorld, walks: dict[tuple[int, int], tuple[int, ...]]) -> tuple[Action, ...] | None:
    """A one-mark plan separating ``a`` from ``b`` when ``a`` has a room paired with two rooms of ``b``."""
    seen: dict[int, tuple[int, int]] = {}
    for pair in walks:
        x = pair[0]
        if x not in seen:
            seen[x] = pair
            continue
        p, q = walks[seen[x]], walks[pair]
        r = _home(a, x)
        other = next(c for c in range(a.alphabet) if c != a.colours[x])
        if _end(b, p + r + q) != seen[x][1]:
            return _plan(p, other, r + q)
        other = next(c for c in range(a.alphabet) if c != a.colours[a.start])
        return _plan((), other, p + r)
    return None


def separating_plan(a: PortWorld, b: PortWorld, *, echo_marks: bool = True) -> tuple[Action, ...] | None:
    """A plan whose records on ``a`` and ``b`` differ (the shortest without marks when one exists), or ``None``
    when no plan separates them (module docstring)."""
    walks = _walks(a, b)
    plain = [w for (x, y), w in walks.items() if a.colours[x] != b.colours[y]]
    if plain:
        plan = _plan(min(plain, key=len))
    elif min(a.alphabet, b.alphabet) < 2:
        return None
    else:
        found = _marked(a, b, walks)
        if found is None:
            swapped = _marked(b, a, {(y, x): w for (x, y), w in walks.items()})
            found = swapped
        if found is None:
            return None
        plan = found
    if run_plan(a, plan, echo_marks=echo_marks) == run_plan(b, plan, echo_marks=echo_marks):
        raise TopomarkFault(f"the separating plan {plan_text(plan)} gives both worlds the same record",
                            "solve_separate")
    return plan

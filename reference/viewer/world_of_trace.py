"""The world a trace mapped: its own final map S, for viewing a trace given without its world (thesis §3.1.3).

A verified run of Algorithm 3.1's family ends with S extended-isomorphic to
the world (§3.1.3), and the iterations' joins are all of S: each non-loop
join adds v_u with the degree its ``signature`` shows, and once every dart is
joined the rotation at each map vertex, read from exit 0, is the world's up
to where the count starts.  :func:`world_of_trace` rebuilds that rotation
(vertices ``s0``, ``s1``, ... as :meth:`~topomark.spec.mapstate.PartialMap.name`
names them) with the start at v0 facing map exit 0 — where the trace's robot
stood when it dropped the lighthouse, §3.3.  The viewer then replays the
trace on it like on any world, so every claim is still checked.

Not every trace determines its world: one of another family (no iterations),
one whose run stopped before its map was complete, or one whose lighthouse
moved before v0 was established (v0 is then not where the robot started).
Each is bad input naming the trace and asking for the world (``--world``).
"""

from __future__ import annotations

from pathlib import Path

from topomark.spec.errors import InvalidInput, InvalidWorld
from topomark.spec.mapstate import PartialMap
from topomark.spec.world import Start, World

from topomark.reference.replay.replay import load_trace
from topomark.reference.trace.reader import signature

__all__ = ["world_of_trace"]


def _refuse(path: str | Path, why: str) -> InvalidInput:
    return InvalidInput(f"{path}: {why}, so it does not give its world: give the world with --world W")


def world_of_trace(path: str | Path) -> World:
    """The world the trace at ``path`` mapped (see the module's docstring); bad input as replay reads it."""
    records = load_trace(path)
    header = next(records)
    if header.get("family", "algorithm-3.1") != "algorithm-3.1":
        raise _refuse(path, f"the trace's family {header['family']} records no map")
    degree: dict[int, int] = {}
    joins: dict[tuple[int, int], tuple[int, int]] = {}
    moved = False
    for rec in records:
        if rec["event"] == "move" and not joins and rec["purpose"] in ("establish", "probe", "drop"):
            moved = True
        if rec["event"] == "iteration":
            a, b = (tuple(d) for d in rec["joined"])
            joins[a], joins[b] = b, a
            if rec["augmentation"] == "non-loop":
                degree[b[0]] = signature(rec["signature"], f"{path}: iteration {rec['iteration']}").degree
        if rec["event"] == "end" and "outcome" in rec:
            raise _refuse(path, f"the run stopped before its map was complete ({rec['outcome']})")
    if moved:
        raise _refuse(path, "the lighthouse moved the robot before v0 was established")
    degree[0] = 1 + max((i for v, i in joins if v == 0), default=-1)
    return _rotation_world(path, degree, joins)


def _rotation_world(path: str | Path, degree: dict[int, int], joins: dict[tuple[int, int], tuple[int, int]]) -> World:
    name = PartialMap.name
    n = len(degree)
    open_darts = [(v, i) for v in range(n) for i in range(degree.get(v, 0)) if (v, i) not in joins]
    if set(degree) != set(range(n)) or open_darts or any(w >= n for w, _ in joins.values()):
        raise _refuse(path, f"its map is not complete (open darts {open_darts[:3]})")
    rotation = {name(v): [name(joins[(v, i)][0]) for i in range(degree[v])] for v in range(n)}
    try:
        return World(rotation, [], Start(name(0), rotation[name(0)][0]))
    except (InvalidWorld, InvalidInput) as exc:
        raise _refuse(path, f"its map is not a world ({exc})") from None

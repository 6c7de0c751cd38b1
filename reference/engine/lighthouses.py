"""The compiled lighthouses: establishing v0 by a script of marker operations (thesis §3.3, §6.1–6.2, §6.3.1).

The engine's counterpart of :class:`~topomark.reference.explorers.lighthouses.Lighthouse`
for the deterministic lighthouses whose v0 is recognised without probing —
v0's signatures from its entries differ, so the signature just sensed names
the place and the back-link at once (§3.2.2, §3.3):

=========================  ================================================  =====================
name                       the script (from the start, facing exit 0)        thesis
=========================  ================================================  =====================
directional-vertex         a directional vertex marker pointing at exit 0    §3.3, Algorithm 3.1
directional-edge           a directional edge marker on exit 0, head at v0   §6.1, Figure 6.1(b)
vertex-and-edge            a vertex marker, an edge marker on exit 0         §6.2
three-undirected-edge      an edge marker on exit 0, two on exit 1           §6.2
thread                     the ε thread tied toward exit 0, its end left     §6.3.1
=========================  ================================================  =====================

:func:`script` turns the reference's lighthouse (its ``script`` or ``ops``)
into rows the robot's :func:`~.robot.operate` carries out, each with the
action code the reference's trace gives it (:mod:`.digest`), so both log the
same actions.  ``three-undirected-vertex`` (Figure 3.21(b)) is not here: its
v0 reads the same from every entry, and the reference recognises it by
probing for the marked neighbour (:mod:`~topomark.reference.explorers.probing`),
which the engine does not compile; nor are the searched lighthouses (§5.1,
§5.2.1, §6.1's undirected edge), whose v0 a random walk chooses.

:func:`explore_lighthouse` is Algorithm 3.1 (:mod:`.algorithm31`) with line 1
carried out by the script: S = {v0} records the marks sensed there (§6.1: "the
markers at the incident edges of each visited vertex"), and each new vertex
records the marks sensed on entering it — the far end of a marked edge.

Examples
--------
>>> script("directional-edge").tolist() == [[OP_EDGE, 0, 1, 1, op_code("drop", "edge", 1, 0, "H")]]
True
>>> ENGINE_LIGHTHOUSES[0], operations("thread")
('directional-vertex', {'leave': 1, 'tie': 1})
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from topomark.spec.kit import MarkerOp

from topomark.reference.engine import ENGINE_LIGHTHOUSES
from topomark.reference.engine.algorithm31 import OK, ROBOT, iterate
from topomark.reference.engine.compiled import kernel
from topomark.reference.engine.digest import op_code
from topomark.reference.engine.mapstate import ULEN, start_map
from topomark.reference.engine.robot import OP_EDGE, OP_LEAVE, OP_MOVE, OP_TIE, OP_VERTEX, fault, operate, sense
from topomark.reference.explorers.lighthouses import LIGHTHOUSES

__all__ = ["ENGINE_LIGHTHOUSES", "script", "operations", "establish", "explore_lighthouse"]



def _row(item) -> list[int]:
    """One script item as (kind, a, b, c, action code): a motion (an int) or a marker or thread operation."""
    if isinstance(item, int):
        return [OP_MOVE, item, 0, 0, 0]
    op = item.to_json()
    code = op_code(op["op"], op["kind"], op.get("count", 1), op.get("exit"), op.get("direction"))
    if isinstance(item, MarkerOp):
        assert not item.pick_up, "a lighthouse only drops its markers (§3.3)"
        if item.kind == "vertex":
            return [OP_VERTEX, item.count, -1 if item.direction is None else int(item.direction), 0, code]
        assert item.direction in (None, "H"), "a directional edge marker has its head at v0 (§6.1)"
        return [OP_EDGE, int(item.exit or 0), item.count, 1 if item.direction == "H" else 0, code]
    if item.op == "tie":
        return [OP_TIE, 0 if item.direction is None else item.direction, 0, 0, code]
    assert item.op == "leave", f"an ε thread lighthouse ties and leaves its thread (§6.3.1), not {item.op}"
    return [OP_LEAVE, 0, 0, 0, code]


def script(name: str | None) -> np.ndarray:
    """The rows of lighthouse ``name``'s script (None: Algorithm 3.1's directional vertex marker)."""
    name = name or "directional-vertex"
    if name not in ENGINE_LIGHTHOUSES:
        raise ValueError(f"the engine does not run the {name} lighthouse (it runs {', '.join(ENGINE_LIGHTHOUSES)})")
    light = LIGHTHOUSES[name]
    return np.array([_row(item) for item in light.script or light.ops], dtype=np.int64).reshape(-1, 5)


def operations(name: str | None) -> dict[str, int]:
    """The marker and thread operations lighthouse ``name`` makes, as the reference's outcome counts them."""
    light = LIGHTHOUSES[name or "directional-vertex"]
    return dict(sorted(Counter(op.to_json()["op"] for op in light.ops).items()))


@kernel
def establish(robot: np.ndarray, rows: np.ndarray) -> None:
    """Line 1: carry out the lighthouse's script from the start, the robot facing exit 0."""
    for k in range(rows.shape[0]):
        operate(robot, rows[k, 0], rows[k, 1], rows[k, 2], rows[k, 3], rows[k, 4])
        if fault(robot):
            return


@kernel
def explore_lighthouse(robot: np.ndarray, S: tuple, W: tuple, rows: np.ndarray, edge_policy: int,
                       hypothesis_policy: int, path_policy: int, counts: np.ndarray) -> int:
    """Algorithm 3.1 with the lighthouse of ``rows``: establish v0, S = {v0} with the marks sensed there from exit
    0, U = its exits (lines 1–3); iterate until U is empty (line 4); an outcome code."""
    counts[:] = 0
    degree = sense(robot)[0]
    establish(robot, rows)
    if fault(robot):
        return ROBOT
    code = start_map(S, degree, sense(robot)[1])
    while code == OK and S[5][ULEN] > 0:
        code = iterate(robot, S, W, edge_policy, hypothesis_policy, path_policy, counts)
    return code

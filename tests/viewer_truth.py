"""What a viewer page must show at each trace line, worked out from the trace and the world by the specification
alone (``spec/robot.py``'s step, ``spec/markerlayer.py``'s operations), not by the viewer or replay.

Shared by ``test_viewer.py`` (the frames) and ``test_viewer_browser.py`` (what the browser shows)."""

from __future__ import annotations

from dataclasses import dataclass

from topomark.spec.kit import MarkerOp
from topomark.spec.marker import VertexMarker
from topomark.spec.markerlayer import MarkerLayer, apply_op
from topomark.spec.robot import step
from topomark.spec.world import World


@dataclass(frozen=True)
class Truth:
    vertex: str  # the robot's true vertex after the line
    markers: str  # the markers lying in the world, as the page words them
    map_vertices: int | None  # 1 + the non-loop joins so far, once the robot has moved (None before)
    cost: int  # traversals so far


def marker_words(layer: MarkerLayer) -> str:
    out = []
    for m in layer.markers():
        if isinstance(m, VertexMarker):
            out.append(f"vertex {m.at}" + (f" x{m.count}" if m.count > 1 else "") +
                       (f" -> {m.points_to}" if m.points_to is not None else ""))
        else:
            u, v = m.between
            out.append(f"edge {u}-{v}" + (f" x{m.count}" if m.count > 1 else "") +
                       (f" head {m.head}" if m.head is not None else ""))
    return "; ".join(out) or "none"


def truths(world: World, records: list[dict]) -> list[Truth]:
    """One :class:`Truth` per trace line (threads left aside: no thread trace is drawn here)."""
    bare = World(world.rotation, (), world.start)
    layer, state = MarkerLayer(bare), bare.start_state()
    cost, joins, moved, out = 0, 0, False, []
    for rec in records:
        event = rec["event"]
        if event == "move":
            state, cost, moved = step(layer, state, rec["motion"]), cost + 1, True
        elif event == "drop":
            apply_op(layer, state, MarkerOp("vertex", None, rec["direction"]))
        elif event == "op" and rec["op"] in ("drop", "pick_up"):
            apply_op(layer, state, MarkerOp(rec["kind"], rec.get("exit"), rec.get("direction"), rec["count"],
                                            rec["op"] == "pick_up"))
        elif event == "iteration" and rec["augmentation"] == "non-loop":
            joins += 1
        out.append(Truth(state[0], marker_words(layer), 1 + joins if moved else None, cost))
    return out

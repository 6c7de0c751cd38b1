"""The marker layer (spec/markerlayer.py) and the simulator's kit-gated marker operations."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.reference.worlds.generators import lattice_hole, wheel_a
from topomark.reference.run.simulator import Simulator
from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.markerlayer import MarkerLayer, apply_op
from topomark.spec.robot import sense
from topomark.spec.world import Start, World


def test_an_unchanged_layer_is_the_world_itself():
    w = wheel_a()
    assert MarkerLayer(w).world() is w


def test_layer_world_equals_a_world_built_with_the_same_markers():
    """The layer's queries and the World built from them agree, vertex by vertex and entry by entry."""
    w = lattice_hole(4, 4, seed=1)
    layer = MarkerLayer(w)
    v, u = w.vertices[0], w.vertices[5]
    layer.drop_vertex(v, 1, head=0)
    layer.drop_edge(u, 1, 2, end="H")
    layer.drop_vertex(u, 3, head=None)
    built = layer.world()
    for x in w.vertices:
        for entry in range(w.degree(x)):
            assert sense(layer, (x, entry)) == sense(built, (x, entry))


@settings(max_examples=60, deadline=None)
@given(st.data())
def test_drops_then_pick_ups_restore_the_world(data):
    w = World(lattice_hole(3, 4, seed=2).rotation)
    layer = MarkerLayer(w)
    ops = []
    for _ in range(data.draw(st.integers(1, 6))):
        v = data.draw(st.sampled_from(w.vertices))
        entry = data.draw(st.integers(0, w.degree(v) - 1))
        if data.draw(st.booleans()):
            op = MarkerOp("vertex", count=data.draw(st.integers(1, 3)))
        else:
            op = MarkerOp("edge", exit=data.draw(st.integers(0, w.degree(v) - 1)), count=data.draw(st.integers(1, 3)),
                          direction=data.draw(st.sampled_from((None, "H", "T"))))
        try:
            apply_op(layer, (v, entry), op)
        except InvalidInput:  # markers pointing another way than those already there: refused, nothing changed
            _marks_as_built(layer, w)
            continue
        ops.append(((v, entry), op))
        _marks_as_built(layer, w)
    for state, op in reversed(ops):
        apply_op(layer, state, MarkerOp(op.kind, op.exit, op.direction, op.count, pick_up=True))
        _marks_as_built(layer, w)
    assert layer.world().markers == ()


def _marks_as_built(layer: MarkerLayer, w: World) -> None:
    """The layer's marks, kept per change, are those of a world built and validated from its markers; what
    it keeps as sensed is what that world shows."""
    built = World(w.rotation, tuple(layer.markers()))
    assert all(layer.vertex_mark(x) == built.vertex_mark(x) and layer.dart_marks(x) == built.dart_marks(x)
               for x in w.vertices)
    assert all(layer.sensed((x, e)) == sense(built, (x, e)) for x in w.vertices for e in range(w.degree(x)))


@pytest.mark.parametrize("first, second", [
    (MarkerOp("vertex", direction=0), MarkerOp("vertex", direction=1)),
    (MarkerOp("vertex", direction=0), MarkerOp("vertex")),
    (MarkerOp("edge", exit=0, direction="H"), MarkerOp("edge", exit=0, direction="T")),
])
def test_markers_pointing_two_ways_cannot_share_a_place(first, second):
    layer = MarkerLayer(wheel_a())
    layer = MarkerLayer(World(layer.base.rotation))
    apply_op(layer, ("0", 0), first)
    with pytest.raises(InvalidInput, match="cannot join"):
        apply_op(layer, ("0", 0), second)


def test_an_edge_marker_reads_head_at_one_end_and_tail_at_the_other():
    w = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})
    layer = MarkerLayer(w)
    apply_op(layer, ("a", 0), MarkerOp("edge", exit=0, direction="H"))  # head at a, on edge a-b
    assert str(sense(layer, ("a", 0))) == "[2,A,E-0-H]"
    assert str(sense(layer, ("b", 1))) == "[2,A,E-0-T]"


def _sim(kit):
    w = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, start=Start("a", "b"))
    return Simulator(World(w.rotation, (), w.start), w.start_state(), kit)


@pytest.mark.parametrize("kit, op, reason", [
    (Kit(vertex=1, directional=True), MarkerOp("vertex"), "directional markers only"),
    (Kit(vertex=1, directional=True), MarkerOp("edge", exit=0, direction="H"), "no edge marker"),
    (Kit(vertex=1), MarkerOp("vertex", count=2), "1 left, 2 asked for"),
    (Kit(vertex=1), MarkerOp("vertex", pick_up=True), "immovable"),
    (Kit(vertex=1, movable=True), MarkerOp("vertex", pick_up=True), "0 there"),
])
def test_the_simulator_refuses_what_the_kit_forbids_and_names_the_kit(kit, op, reason):
    sim = _sim(kit)
    with pytest.raises(CheckFailure, match=reason):
        sim.operate(op)
    assert sim.operations.total() == 0 and sim.world.markers == ()


def test_a_movable_marker_goes_down_and_comes_back_uncounted_as_cost():
    sim = _sim(Kit(vertex=1, movable=True))
    sim.operate(MarkerOp("vertex"))
    assert sim.world.vertex_mark("a").count == 1 and sim.held["vertex"] == 0
    sim.robot().move(0)
    sim.robot().move(0)
    sim.operate(MarkerOp("vertex", pick_up=True))
    assert sim.world.markers == () and sim.held["vertex"] == 1
    assert sim.cost == 2 and dict(sim.operations) == {"drop": 1, "pick_up": 1}
    assert [e["op"] for e in sim.events] == ["drop", "pick_up"] and [e["step"] for e in sim.events] == [0, 2]


@pytest.mark.parametrize("algorithm", ["case-1a", "case-3b", "case-dv-sum", "extension-2", "dudek"])
def test_the_layers_snapshot_is_the_validated_world(algorithm):
    """MarkerLayer.world() copies the layer's marks without re-validating them (World.of_layer): after every
    drop of a whole run they are what a world built and checked from the same markers has, and the layer's
    running count (``lying``, what the marker-budget check reads) is the sum of their counts."""
    from topomark.reference.worlds import generators
    from topomark.reference.run.explore import explore
    from topomark.spec.world import World
    checked = []

    class Watch(Simulator):
        def operate(self, op):
            super().operate(op)
            snap = self.world
            full = World(snap.rotation, snap.markers, snap.start)
            checked.append(all(snap.vertex_mark(v) == full.vertex_mark(v) and snap.dart_marks(v) == full.dart_marks(v)
                               for v in full.vertices) and self.layer.lying == sum(m.count for m in full.markers))
    import topomark.reference.run.explore as ex
    real, ex.Simulator = ex.Simulator, Watch
    try:
        assert explore(generators.complete_hole(6, 0.2, 3), algorithm, record=False).outcome == "correct"
    finally:
        ex.Simulator = real
    assert checked and all(checked)


@pytest.mark.parametrize("algorithm", ["case-2", "case-5-v2", "dudek", "thread-explore", "thread-knots",
                                       "thread-carried"])
def test_what_the_robot_senses_is_what_the_layer_shows_now(algorithm):
    """The layer keeps what was sensed per vertex until its marks or the thread change (MarkerLayer.sensed):
    after every move of a whole run — drops, pick-ups, a thread laid and rewound — the signature the robot
    got is the one computed afresh from the layer."""
    from topomark.reference.worlds import generators
    from topomark.reference.run.explore import explore
    from topomark.spec.signature import signature_at
    checked = []

    class Watch(Simulator):
        def _move(self, motion, purpose):
            sig = super()._move(motion, purpose)
            checked.append(sig == signature_at(self.layer, *self.state))
            return sig
    import topomark.reference.run.explore as ex
    real, ex.Simulator = ex.Simulator, Watch
    try:
        assert explore(generators.complete_hole(6, 0.2, 3), algorithm, record=False).outcome == "correct"
    finally:
        ex.Simulator = real
    assert len(checked) > 20 and all(checked)

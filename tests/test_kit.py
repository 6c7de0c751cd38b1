"""The marker kit (spec/kit.py, thesis §3.1.1, §6.1–6.3).  The docstring examples of every module run from
tests/test_docstring_examples.py."""

from __future__ import annotations

import importlib

import pytest

from topomark.spec.errors import InvalidInput
from topomark.spec.kit import Kit
from topomark.spec.markerclass import MARKER_CLASSES, marker_class


@pytest.mark.parametrize("name", sorted(MARKER_CLASSES))
def test_every_class_kit_round_trips_through_the_protocol_form(name):
    kit = MARKER_CLASSES[name].kit
    assert Kit.from_json(kit.to_json()) == kit


@pytest.mark.parametrize("name", sorted(MARKER_CLASSES))
def test_a_class_places_exactly_its_kit(name):
    """Every placement carries as many vertex and edge markers as the class's kit, of its directionality."""
    from topomark.reference.worlds.generators import wheel_a
    cls = MARKER_CLASSES[name]
    for world in cls.placements(wheel_a()):
        vertex = sum(m.count for m in world.markers if hasattr(m, "at"))
        edge = sum(m.count for m in world.markers if hasattr(m, "between"))
        assert (vertex, edge) == (cls.kit.vertex, cls.kit.edge)
        assert all(m.directional == cls.kit.directional for m in world.markers)


def test_refusals_name_the_kit():
    kit = Kit(vertex=1, directional=True)
    assert kit.refusal("vertex", True, 1, 0) is None
    assert "1 directional vertex marker" in kit.refusal("vertex", True, 1, 1)
    assert "none left" in kit.refusal("vertex", True, 1, 1)
    assert "directional markers only" in kit.refusal("vertex", False, 1, 0)
    assert "no edge marker" in kit.refusal("edge", True, 1, 0)
    assert Kit(vertex=3).refusal("vertex", False, 2, 1) is None
    assert Kit(vertex=3).refusal("vertex", False, 2, 2) is not None


@pytest.mark.parametrize("obj, message", [
    ([], "must be an object"), ({"sideways-vertex": 1}, "unknown key"),
    ({"directional-vertex": 1, "undirected-edge": 1}, "cannot be mixed"),
    ({"directional-vertex": -1}, "non-negative"), ({"undirected-edge": "2"}, "non-negative"),
    ({"movable": "yes"}, "movable"), ({"thread": -3}, "thread"),
])
def test_bad_kits_are_bad_input(obj, message):
    with pytest.raises(InvalidInput, match=message):
        Kit.from_json(obj)


def test_unknown_class_lists_the_known():
    with pytest.raises(InvalidInput, match="directional-vertex"):
        marker_class("sideways")


@pytest.mark.parametrize("path, message", [("a\x00b", "NUL byte"), ("x" * 5000, "5000 characters")])
def test_unopenable_paths_are_bad_input_with_a_short_message(path, message):
    from topomark.spec.jsontext import read_text_file
    with pytest.raises(InvalidInput, match=message) as info:
        read_text_file(path)
    assert len(str(info.value)) < 400


# -- §6.2.1 Case 1b's pool of vertex-or-edge markers (footnote 16) --------------------------------

@pytest.mark.parametrize("kit, obj, text", [
    (Kit(either=5), {"undirected-either": 5}, "5 undirected vertex-or-edge markers"),
    (Kit(vertex=1, edge=2, directional=True, either=1),
     {"directional-vertex": 1, "directional-edge": 2, "directional-either": 1},
     "1 directional vertex marker, 2 directional edge markers, 1 directional vertex-or-edge marker"),
])
def test_a_pool_round_trips_and_describes_itself(kit, obj, text):
    assert kit.to_json() == obj and Kit.from_json(obj) == kit and kit.describe() == text


def test_a_kit_without_a_pool_has_no_either_key():
    """Every existing kit's protocol form is unchanged: the key appears only for a pool."""
    assert all("either" not in key for cls in MARKER_CLASSES.values() for key in cls.kit.to_json())
    assert Kit(vertex=2, edge=1).to_json() == {"undirected-vertex": 2, "undirected-edge": 1}


@pytest.mark.parametrize("obj, message", [
    ({"undirected-either": -1}, "either markers must be a non-negative"),
    ({"directional-either": 1, "undirected-vertex": 1}, "cannot be mixed"),
    ({"undirected-either": 2, "movable": True}, "cannot be movable"),
])
def test_bad_pools_are_bad_input(obj, message):
    with pytest.raises(InvalidInput, match=message):
        Kit.from_json(obj)


def test_a_pool_of_two_serves_one_vertex_and_one_edge_drop_and_refuses_a_third():
    kit = Kit(either=2)
    assert kit.count("vertex") == kit.count("edge") == 0  # count is the kind's own
    assert kit.refusal("vertex", False, 1, held=0, pooled=0) is None
    assert kit.refusal("edge", False, 1, held=0, pooled=1) is None
    assert "none left, 1 asked for" in kit.refusal("vertex", False, 1, held=0, pooled=2)
    assert "undirected markers only" in kit.refusal("edge", True, 1, 0)
    assert Kit(vertex=1, either=1).draw("vertex", 1, held=0) == (1, 0)  # its own first
    assert Kit(vertex=1, either=1).draw("vertex", 1, held=1) == (0, 1)  # then the pool
    assert Kit(vertex=1, either=1).draw("edge", 1, held=0) == (0, 1)


def _sim(kit):
    from topomark.reference.run.simulator import Simulator
    from topomark.spec.world import Start, World
    return Simulator(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, start=Start("a", "b")),
                     ("a", 0), kit)


def test_the_simulator_draws_the_kinds_own_markers_before_the_pool_and_then_runs_out():
    from topomark.spec.errors import OutOfMarkers
    from topomark.spec.kit import MarkerOp
    sim = _sim(Kit(edge=1, either=2))
    sim.operate(MarkerOp("edge", exit=1))
    assert (sim.held["edge"], sim.held["either"]) == (0, 2)  # the edge's own marker first
    sim.operate(MarkerOp("vertex"))
    sim.operate(MarkerOp("edge", exit=0))
    assert (sim.held["vertex"], sim.held["edge"], sim.held["either"]) == (0, 0, 0)
    assert sim.world.vertex_mark("a").count == 1 and len(sim.world.markers) == 3
    with pytest.raises(OutOfMarkers, match="none left"):  # the failed outcome, not a violation
        sim.operate(MarkerOp("vertex"))
    assert dict(sim.operations) == {"drop": 3}


def test_a_kit_without_a_pool_still_refuses_the_other_kind_as_a_violation():
    from topomark.spec.errors import CheckFailure, OutOfMarkers
    from topomark.spec.kit import MarkerOp
    with pytest.raises(CheckFailure, match="no edge marker") as info:
        _sim(Kit(vertex=1)).operate(MarkerOp("edge", exit=0))
    assert not isinstance(info.value, OutOfMarkers)


def test_the_example_provider_draws_a_pool_after_the_kinds_own_markers():
    """reference/oracle/examples/provider.py (what external providers copy) reads the ``*-either`` pool as the
    simulator does: the kind's own markers first, then the pool, and refuses a drop past both."""
    import importlib.util
    from pathlib import Path
    import topomark.reference as ref
    path = Path(ref.__file__).parent / "oracle" / "examples" / "provider.py"
    spec = importlib.util.spec_from_file_location("example_provider", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    world = {"rotation": {"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}}
    w = mod.World(world, {"undirected-vertex": 1, "undirected-either": 1})
    assert w.operate({"type": "drop", "kind": "vertex"}) is None and w.held["vertex"] == 0 and w.pool == 1
    assert w.operate({"type": "drop", "kind": "edge", "exit": 1}) is None and w.pool == 0
    assert w.operate({"type": "drop", "kind": "edge", "exit": 0}) is not None

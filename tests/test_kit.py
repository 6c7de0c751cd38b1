"""The marker kit (spec/kit.py, thesis §3.1.1, §6.1–6.3) and the docstring examples of every spec module."""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import topomark.spec
from topomark.spec.errors import InvalidInput
from topomark.spec.kit import Kit
from topomark.spec.markerclass import MARKER_CLASSES, marker_class


@pytest.mark.parametrize("name", sorted(m.name for m in pkgutil.iter_modules(topomark.spec.__path__)))
def test_spec_docstring_examples(name):
    module = importlib.import_module(f"topomark.spec.{name}")
    assert doctest.testmod(module).failed == 0


@pytest.mark.parametrize("name", sorted(MARKER_CLASSES))
def test_every_class_kit_round_trips_through_the_protocol_form(name):
    kit = MARKER_CLASSES[name].kit
    assert Kit.from_json(kit.to_json()) == kit


@pytest.mark.parametrize("name", sorted(MARKER_CLASSES))
def test_a_class_places_exactly_its_kit(name):
    """Every placement carries as many vertex and edge markers as the class's kit, of its directionality."""
    from topomark.reference.generators import wheel_a
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

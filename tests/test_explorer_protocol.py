"""Every registered algorithm's explorer keeps the one explorer contract (reference/explorers/contract.py).

The registry's entries are found by iterating it (so an algorithm registered
later is covered without editing this file).  Each explorer class offers the
contract's methods; each explorer, built as the run builds it, has the
contract's attributes before and after ``start``; ``done`` has no side
effects; one ``step`` records exactly one :class:`IterationRecord` and shows
it to the observer; ``models`` holds (map, pose) pairs.  The explorers folder
keeps the house rules its modules' docstrings promise.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from topomark.reference.algorithms.registry import REGISTRY
from topomark.reference.explorers.contract import Explorer, IterationRecord, conforms
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import prepare_world
from topomark.reference.run.simulator import Simulator
from topomark.reference.worlds import generators
from topomark.spec.errors import InvalidInput
from topomark.spec.mapstate import PartialMap
from topomark.spec.world import Start, World

EXPLORERS = Path(__file__).resolve().parents[1] / "reference" / "explorers"


def build(spec, world):
    """The simulator and the explorer as ``explore`` builds them (lighthouse or kit), the observer recording."""
    seen: list = []
    if spec.uses_lighthouse:
        light = LIGHTHOUSES["directional-vertex"]
        bare, state = prepare_world(world, light, spec.name)
        sim, extra = Simulator(bare, state, light.kit), light
    else:
        extra = spec.parse_options({})
        sim = Simulator(world, world.start_state(), spec.kit_for(world.n, world.m, extra))
    explorer = spec.factory(sim.robot(), Policies(), lambda ex, it: seen.append((ex, it)), extra)
    return sim, explorer, seen


@pytest.mark.parametrize("name", list(REGISTRY))
def test_every_registered_explorer_class_offers_the_contract(name):
    assert conforms(REGISTRY[name].factory), name


def small_world(spec):
    """K4, or for an algorithm whose registration refuses it (a class of worlds: ``single-leaf``'s one leaf) K4
    with a pendant vertex, started away from it."""
    k4 = generators.complete(4)
    try:
        if spec.check_world is not None:
            spec.check_world(k4, spec.parse_options({}))
        return k4
    except InvalidInput:
        rotation = {v: tuple(ws) + (("4",) if v == "0" else ()) for v, ws in k4.rotation.items()}
        return World({**rotation, "4": ("0",)}, (), Start("1", rotation["1"][0]))


@pytest.mark.parametrize("name", list(REGISTRY))
def test_every_registered_explorer_keeps_the_contract_on_a_small_world(name):
    spec = REGISTRY[name]
    sim, explorer, seen = build(spec, small_world(spec))
    assert isinstance(explorer, Explorer)
    explorer.start()
    assert isinstance(explorer, Explorer) and explorer.iterations == []
    before = (sim.cost, len(explorer.S.journal), sim.world.markers)
    for _ in range(2):
        assert explorer.done() is False  # K4 is not mapped by a start
    assert (sim.cost, len(explorer.S.journal), sim.world.markers) == before  # done() has no side effects
    explorer.step()
    assert len(explorer.iterations) == 1 and seen == [(explorer, explorer.iterations[0])]
    record = explorer.iterations[0]
    assert isinstance(record, IterationRecord) and record.number == 1 and isinstance(record.to_json(), dict)
    models = explorer.models()
    assert models and all(isinstance(S, PartialMap) and len(pose) == 2 for S, pose in models)


def _module_rules(path: Path) -> list[str]:
    source = path.read_text()
    tree = ast.parse(source)
    bad = []
    if len(source.splitlines()) > 400:
        bad.append(f"{path.name}: over 400 lines")
    if not ast.get_docstring(tree):
        bad.append(f"{path.name}: no module docstring")
    if path.name != "__init__.py" and not any(isinstance(node, ast.Assign) and any(
            getattr(t, "id", None) == "__all__" for t in node.targets) for node in tree.body):
        bad.append(f"{path.name}: no __all__")
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.end_lineno - node.lineno >= 60:
            bad.append(f"{path.name}: {node.name} over 60 lines")
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("topomark"):
            bad += [f"{path.name}: imports the private {a.name}" for a in node.names if a.name.startswith("_")]
    return bad


@pytest.mark.parametrize("path", sorted(EXPLORERS.glob("*.py")), ids=lambda p: p.name)
def test_explorer_modules_keep_the_house_rules(path):
    assert _module_rules(path) == []


@pytest.mark.parametrize("module", ["contract", "walker"])
def test_docstring_examples(module):
    import doctest
    import importlib
    assert doctest.testmod(importlib.import_module(f"topomark.reference.explorers.{module}")).failed == 0

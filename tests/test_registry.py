"""The algorithm registry (reference/algorithms/registry.py) and ``topomark algorithms``."""

from __future__ import annotations

import doctest
import json

import pytest

from topomark.reference.algorithms import explorer_classes as algorithms, bounds, registry
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate
from topomark.reference.algorithms.registry import CHECKS, REGISTRY
from topomark.spec.world import World

REQUIRED = {"name", "thesis", "kit", "bound", "markers", "deterministic", "options", "checks"}


def test_json_lists_every_explorer_with_the_required_fields(capsys):
    assert main(["algorithms", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert [a["name"] for a in listed] == list(REGISTRY)
    assert set(algorithms.ALGORITHMS) <= set(REGISTRY)  # Algorithm 3.1's family, and every other registered one
    for entry in listed:
        assert ("lighthouses" in entry) == (entry["name"] in algorithms.ALGORITHMS)
        assert REQUIRED <= set(entry), entry["name"]
        assert entry["thesis"].startswith("§")
        assert set(entry["checks"]) <= set(CHECKS)


def test_text_listing_names_each_thesis_reference(capsys):
    assert main(["algorithms"]) == 0
    out = capsys.readouterr().out
    for spec in REGISTRY.values():
        assert spec.thesis in out


@pytest.mark.parametrize("name", [n for n, s in REGISTRY.items() if s.deterministic])  # §5.2.2 may not map
@pytest.mark.parametrize("world", ["lattice-hole:rows=4,cols=4,seed=2", "random:n=7,fraction=0.5,seed=3",
                                   "complete-hole:n=6,seed=1", "wheel-a", "wheel-b"])
def test_every_registered_algorithm_maps_generated_worlds(name, world):
    gen, _, params = world.partition(":")
    kwargs = dict(p.split("=") for p in params.split(",")) if params else {}
    w = generate(gen, **kwargs)
    w = World(w.rotation, (), w.start)  # the Figure 3.4 wheels carry the undirected marker the robot replaces
    outcome = explore(w, name)
    assert outcome.verified, outcome.violation
    bound = REGISTRY[name].bound_for(w.n, w.m)
    assert bound is None or outcome.cost <= bound


def test_unknown_algorithm_is_bad_input(capsys):
    assert main(["explore", "cycle:n=4", "--algorithm", "nope"]) == 2
    assert "unknown algorithm 'nope'" in capsys.readouterr().err


@pytest.mark.parametrize("module", [registry, bounds])
def test_docstring_examples(module):
    assert doctest.testmod(module).failed == 0

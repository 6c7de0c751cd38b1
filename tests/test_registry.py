"""The algorithm registry (reference/algorithms/registry.py) and ``topomark algorithms``."""

from __future__ import annotations

import json

import pytest

from topomark.reference.algorithms import explorer_classes as algorithms
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.algorithms.registry import CHECKS, REGISTRY

from conftest import SMALL_WORLDS, bare, make_world

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
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_every_registered_algorithm_maps_generated_worlds(name, text):
    w = bare(make_world(text))  # the Figure 3.4 wheels carry the undirected marker the robot replaces
    outcome = explore(w, name)
    assert outcome.verified, outcome.violation
    bound = REGISTRY[name].bound_for(w.n, w.m)
    assert bound is None or outcome.cost <= bound


def test_unknown_algorithm_is_bad_input(capsys):
    assert main(["explore", "cycle:n=4", "--algorithm", "nope"]) == 2
    assert "unknown algorithm 'nope'" in capsys.readouterr().err

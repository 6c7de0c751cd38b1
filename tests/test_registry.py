"""The algorithm registry (reference/algorithms/registry.py) and ``topomark algorithms``."""

from __future__ import annotations

import importlib
import json
import pkgutil
from dataclasses import replace

import pytest

from topomark.reference.algorithms import registrations, registry
from topomark.reference.algorithms.registry import in_family, register, unregister
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.compositions import EXPLORERS
from topomark.reference.cli.main import main
from topomark.reference.run.explore import check_run, explore
from topomark.reference.algorithms.registry import CHECKS, LISTED, REGISTRY, STATUSES
from topomark.reference.algorithms.algorithm_spec import ALGORITHM_3_1_CHECKS
from topomark.reference.algorithms.registrations.algorithm31 import lighthouse_algorithm
from topomark.spec.errors import InvalidInput

from conftest import SMALL_WORLDS, bare, make_world

REQUIRED = {"name", "thesis", "kit", "bound", "markers", "deterministic", "options", "checks"}


def test_json_lists_every_explorer_with_the_required_fields(capsys):
    assert main(["algorithms", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert [a["name"] for a in listed if a["name"] not in LISTED] == list(REGISTRY)
    for entry in listed:
        assert entry["status"] in STATUSES
        assert ("status_reason" in entry) == (entry["status"] != "implemented"), entry["name"]
        if entry["name"] in LISTED:
            assert entry == LISTED[entry["name"]].to_json() and entry["status"] == "not implementable from the thesis"
            continue
        assert ("lighthouses" in entry) == (entry["name"] in in_family("algorithm-3.1"))
        assert REQUIRED <= set(entry), entry["name"]
        assert entry["thesis"].startswith("§")
        assert set(entry["checks"]) <= set(CHECKS)


def test_text_listing_names_each_thesis_reference(capsys):
    assert main(["algorithms"]) == 0
    out = capsys.readouterr().out
    for spec in REGISTRY.values():
        assert spec.thesis in out


@pytest.mark.slow
@pytest.mark.parametrize("name", [n for n, s in REGISTRY.items() if s.deterministic  # §5.2.2 may not map
                                  and s.status == "implemented"])
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_every_registered_algorithm_maps_generated_worlds(name, text):
    w = bare(make_world(text))  # the Figure 3.4 wheels carry the undirected marker the robot replaces
    if REGISTRY[name].check_world is not None:
        try:
            check_run(w, REGISTRY[name])
        except InvalidInput:  # an algorithm for a class of worlds (docs/adding-an-algorithm.md) refuses the rest
            return
    outcome = explore(w, name)
    assert outcome.verified, outcome.violation
    bound = REGISTRY[name].bound_for(w.n, w.m)
    assert bound is None or outcome.cost <= bound


def test_unknown_algorithm_is_bad_input(capsys):
    assert main(["explore", "cycle:n=4", "--algorithm", "nope"]) == 2
    assert "unknown algorithm 'nope'" in capsys.readouterr().err


def test_every_algorithm_comes_from_a_registration_module():
    """One registry: each entry is the very spec some module of registrations/ lists in its SPECS."""
    listed = {}
    for info in pkgutil.iter_modules(registrations.__path__):
        for spec in getattr(importlib.import_module(f"{registrations.__name__}.{info.name}"), "SPECS", ()):
            listed[spec.name] = spec
    assert listed.keys() == REGISTRY.keys() and all(listed[name] is REGISTRY[name] for name in REGISTRY)
    assert_algorithm_3_1_family()


def assert_algorithm_3_1_family() -> None:
    """What makes Algorithm 3.1's family, whatever its members: ``basic`` and every Chapter 4 enhancement with
    their explorers, all listed first; every member a lighthouse algorithm held to Algorithm 3.1's checks, its
    explorer Algorithm 3.1's (a subclass of LighthouseExplorer)."""
    family = in_family("algorithm-3.1")
    assert list(family) == list(REGISTRY)[:len(family)] and list(family)[0] == "basic"  # listed first, basic first
    assert family["basic"].factory is LighthouseExplorer
    assert all(family[name].factory is cls for name, cls in EXPLORERS.items())
    for name, spec in family.items():
        assert spec.uses_lighthouse and set(ALGORITHM_3_1_CHECKS) <= set(spec.checks), name
        assert isinstance(spec.factory, type) and issubclass(spec.factory, LighthouseExplorer), name


def test_a_new_member_of_algorithm_3_1s_family_keeps_its_properties():
    """Another member of the family (Algorithm 3.1 with its line-5 edge choice fixed, as a registration module
    may add) joins the family, listed after Chapter 4, and the family's properties hold with it."""
    spec = lighthouse_algorithm("basic-oldest", "§3.3, Algorithm 3.1, the oldest edge of U first",
                                LighthouseExplorer, edge_policy="fifo")
    register(spec)
    try:
        assert "basic-oldest" in in_family("algorithm-3.1")
        assert_algorithm_3_1_family()
    finally:
        unregister("basic-oldest")


def test_register_lists_a_new_algorithm_in_thesis_order_and_unregister_takes_it_out():
    before = list(REGISTRY)
    spec = replace(REGISTRY["dudek"], name="dudek-again", thesis="§6.2.1, a copy")
    assert register(spec) is spec and registry.algorithm_spec("dudek-again") is spec
    try:
        names = list(REGISTRY)
        assert names[names.index("case-5-edge"):names.index("case-5-edge") + 3] == ["case-5-edge", "dudek-again", "case-dv-sum"]
        with pytest.raises(ValueError, match="'dudek-again' is registered twice"):
            register(spec)
    finally:
        assert unregister("dudek-again") is spec
    assert list(REGISTRY) == before


def test_specs_are_built_by_keyword():
    with pytest.raises(TypeError):
        registry.AlgorithmSpec("x", "§1", *REGISTRY["basic"].to_json().values())


def _unmeasured(registry, experiments):
    """The entries whose asymptotic bound names a bench experiment that does not run them."""
    runs = {name: {a for part in e.parts for a in part.algorithms} for name, e in experiments.items()}
    return sorted(n for n, s in registry.items() if s.bound_bench and n not in runs.get(s.bound_bench, ()))


def test_an_asymptotic_bound_names_a_bench_experiment_that_runs_the_entry():
    """``bound_bench`` is what a run's report cites ("measured by bench table-6.2"): the experiment must run the
    entry, or the citation is untrue.  Seeded: an entry dropped from its experiment is caught."""
    from dataclasses import replace

    from topomark.reference.algorithms.registry import REGISTRY
    from topomark.reference.bench.plan import EXPERIMENTS

    assert _unmeasured(REGISTRY, EXPERIMENTS) == []
    table = EXPERIMENTS["table-6.2"]
    dropped = replace(table, parts=tuple(replace(p, algorithms=tuple(a for a in p.algorithms if a != "extension-2-listing"))
                                         for p in table.parts))
    assert _unmeasured(REGISTRY, {**EXPERIMENTS, "table-6.2": dropped}) == ["extension-2-listing"]

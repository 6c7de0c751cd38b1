"""The ``cost-bound`` check: every exact cost bound of the registry is held at the end of every checked run, and
every bound that is only asymptotic says so (``docs/checks.md``, "What cost-bound counts")."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from seeded_faults_by_check import EDGE, OneTraversalTooMany
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec, register, unregister, variant
from topomark.reference.bench.experiments import EXPERIMENTS
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore


@pytest.mark.parametrize("name", list(REGISTRY))
def test_every_exact_bound_is_checked_and_every_asymptotic_one_says_it_is_not(name):
    spec = REGISTRY[name]
    listed = spec.to_json()
    if spec.bound_fn is not None:
        assert "cost-bound" in spec.checks and listed["bound_checked"] is True and spec.bound_formula
        assert listed["bound_note"].startswith(f"exact: {spec.bound_formula}; {spec.bound_whose}; checked at the end of every")
    else:
        assert "cost-bound" not in spec.checks and listed["bound_checked"] is False
        if spec.bound:  # asymptotic: never claimed as checked, and measured by an experiment that exists
            assert spec.bound_bench in EXPERIMENTS
            assert listed["bound_note"] == f"asymptotic: measured by bench {spec.bound_bench}, not checked per run"


def test_an_entry_cannot_name_cost_bound_without_an_exact_bound_nor_state_one_without_its_formula():
    basic = algorithm_spec("basic")
    with pytest.raises(ValueError, match="'cost-bound' needs an exact bound"):
        replace(basic, bound_fn=None, bound_bench="tables")
    with pytest.raises(ValueError, match="needs its bound_formula"):
        replace(basic, bound_formula=None)
    with pytest.raises(ValueError, match=r"names the bench experiment"):
        replace(algorithm_spec("enh4"), bound_bench=None)


@pytest.mark.parametrize("lighthouse, purpose", [("three-undirected-vertex", "drop"),
                                                 ("undirected-vertex", "probe")])
def test_a_lighthouse_s_setup_and_probes_are_outside_3_1_plus_3_2(lighthouse, purpose):
    """On one edge (3.1)+(3.2) = 1: Figure 3.21(b)'s lighthouse walks 2 to drop its third marker, §5.1's probes 2 to tell its
    back-link; the run is held to the loop's own traversals (§3.5.2) and passes, and counting those moves too
    would fail it."""
    out = explore(EDGE, "basic", lighthouse=lighthouse, record=False)
    assert out.verified and out.bound_checked and out.upper_bound == upper_bound(2, 1) == 1
    assert out.cost == 3 and out.by_purpose[purpose] == 2
    counted = replace(algorithm_spec("basic"), bound_excludes=())
    strict = explore(EDGE, counted, lighthouse=lighthouse, record=False)
    assert strict.violation.check == "cost bound" and strict.violation.found == "3"


def test_enhancements_4_and_5_report_no_exact_bound_and_are_not_held_to_one():
    """Their expansion traversals are outside (3.1)+(3.2) (§4.2): only O(m²n) (Chapter 4), asymptotic."""
    for name in ("enh4", "enh5-d1", "enh3+5"):
        out = explore(EDGE, name, record=False)
        assert out.verified and out.upper_bound is None and not out.bound_checked
        assert out.summary()["bound_checked"] is False
    basic = explore(EDGE, "basic", record=False)
    assert basic.summary()["upper_bound"] == 1 and basic.summary()["bound_checked"] is True
    assert not explore(EDGE, "basic", record=False, check=False).bound_checked


def test_the_cli_says_which_bound_was_held(capsys):
    assert main(["explore", "cycle:n=5", "--algorithm", "basic"]) == 0
    assert f"{upper_bound(5, 5)} (checked: cost-bound)" in capsys.readouterr().out
    assert main(["explore", "cycle:n=5", "--algorithm", "enh4"]) == 0
    assert "(asymptotic: measured by bench tables, not checked per run)" in capsys.readouterr().out
    assert main(["explore", "cycle:n=5", "--algorithm", "case-3b"]) == 0
    assert "O(m) (asymptotic: measured by bench table-6.1, not checked per run)" in capsys.readouterr().out
    assert main(["algorithms", "--json"]) == 0
    listed = {a["name"]: a for a in json.loads(capsys.readouterr().out)}
    assert listed["basic"]["bound_checked"] and "cost-bound" in listed["basic"]["checks"]
    assert not listed["case-dv-sum"]["bound_checked"] and "cost-bound" not in listed["case-dv-sum"]["checks"]


def test_a_run_past_its_bound_exits_1_naming_the_bound(capsys):
    register(variant("too-far", OneTraversalTooMany))
    try:
        assert main(["explore", "chain:n=2", "--algorithm", "too-far", "--json"]) == 1
    finally:
        unregister("too-far")
    captured = capsys.readouterr()
    data = json.loads(captured.out)
    assert data["outcome"] == "wrong-map" and data["violation"]["check"] == "cost bound"
    assert "cost bound violated at edge traversals (§3.1.2): expected at most 1 = (3.1)+(3.2)" in captured.err
    assert "(§3.5.2), at n = 2, m = 1, found 2" in captured.err

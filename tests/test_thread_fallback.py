"""§6.3.3's phase-I/phase-II thread fallback (reference/explorers/threads_fallback.py): Algorithm 6.7
while the thread lasts, then Algorithm 3.1 with the tied v0 as lighthouse."""

from __future__ import annotations

import pytest

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore

from conftest import FIGURE_3_4, SMALL_WORLDS, bare, make_world

FAMILIES = [t for t in SMALL_WORLDS if t.split(":")[0] in ("lattice-hole", "complete-hole", "random", "small-world")]


@pytest.mark.parametrize("text", [*FAMILIES[::2], *FIGURE_3_4])
@pytest.mark.parametrize("length", [1, 3])
def test_the_fallback_maps_every_family_checked_within_its_bound(text, length):
    w = bare(make_world(text))
    out = explore(w, "thread-fallback", options={"thread-length": length})
    assert out.outcome == "correct" and out.verified, out.violation
    assert out.cost <= algorithm_spec("thread-fallback").bound_for(w.n, w.m)
    phases = [it.phase for it in out.explorer.iterations]
    assert phases == sorted(phases) and 2 in phases  # phase I, then phase II to the end


@pytest.mark.parametrize("text", ["complete-hole:n=6,seed=1", "random:n=8,fraction=0.4,seed=1", "wheel-a"])
def test_phase_two_validates_hypotheses_by_motion_and_leaves_the_thread_laid(text):
    w = bare(make_world(text))
    out = explore(w, "thread-fallback", options={"thread-length": 1})
    two = [it for it in out.explorer.iterations if it.phase == 2]
    assert any(h.outcome in ("case 1", "case 2") for it in two for h in it.hypotheses)  # some rejected by motion
    assert {it.how for it in two} >= {"new", "hypothesis"} or {it.how for it in two} >= {"new", "lighthouse"}
    assert out.by_purpose["validation"] > 0
    assert out.marker_operations["leave"] == 1 and not out.marker_operations.get("untie")
    assert out.explorer.S.thread_mark(0).tied  # the final map shows the thread tied at v0, as the world has it


def test_a_thread_long_enough_never_falls_back_and_costs_what_algorithm_6_7_costs():
    w = bare(make_world("lattice-hole:rows=4,cols=5,seed=1"))
    out = explore(w, "thread-fallback", options={"thread-length": w.n})
    assert out.outcome == "correct" and {it.phase for it in out.explorer.iterations} == {1}
    assert out.cost == explore(w, "thread-circumference").cost


def test_the_cli_runs_the_fallback_and_refuses_a_thread_of_no_length(capsys):
    assert main(["explore", "wheel-b", "--algorithm", "thread-fallback", "--thread-length", "1", "--quiet"]) == 0
    assert main(["explore", "wheel-b", "--algorithm", "thread-fallback", "--thread-length", "0"]) == 2
    assert "--thread-length must be an integer >= 1" in capsys.readouterr().err

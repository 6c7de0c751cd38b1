"""Every check can fail: each named check has a seeded fault that only it catches (``docs/checks.md``).

For every check in :data:`~topomark.reference.algorithms.algorithm_spec.CHECKS`
``tests/seeded_faults_by_check.py`` holds a fault that violates exactly that
check.  Here:

1. the checker reports that check — its violation's name, the iteration and a
   message saying what was expected and found — in every check mode;
2. disabling that check (its condition as good as ``True``) lets the fault
   through: the run is verified, or ends with the later check the table names;
   disabling any *other* check changes nothing.  So each check is the one that
   catches its fault, and a checker with any check disabled fails this file;
3. the worlds are fine: the registered algorithm is verified on each.

Three checks were once replaced by ``True`` with every test passing
(``bound-function``, ``marker``, ``iterations``); the tests named after them
below fail if that happens again.
"""

from __future__ import annotations

import pytest

from seeded_faults_by_check import REPORTS, SEEDED, Seeded, disable
from topomark.reference.algorithms.algorithm_spec import CHECKS
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec
from topomark.reference.run.explore import explore

IDS = [f"{s.check}-{s.name}" for s in SEEDED]


def _caught(out, seeded: Seeded) -> None:
    """``out`` ends with ``seeded``'s violation, named as its check reports, at its iteration, saying why."""
    v = out.violation
    assert v is not None and not out.verified and out.outcome == "wrong-map", f"{seeded.name} went undetected"
    assert (v.check, v.data.get("iteration")) == (seeded.reports, seeded.iteration), str(v)
    text = str(v)
    assert f"iteration {seeded.iteration}" in text
    for words in seeded.says:
        assert words in text, f"{words!r} not in {text!r}"


def test_every_check_has_a_seeded_fault_named_as_it_reports():
    assert set(REPORTS) == set(CHECKS) == {s.check for s in SEEDED}
    names = [name for reported in REPORTS.values() for name in reported]
    assert len(names) == len(set(names)), "two checks report under one name"
    for s in SEEDED:
        assert s.reports in REPORTS[s.check]
        assert s.check in algorithm_spec(s.like).checks, f"{s.like} does not name {s.check}"
        assert s.unchecked is None or s.unchecked not in REPORTS[s.check]


def test_every_check_is_named_by_a_registered_algorithm():
    named = {check for spec in REGISTRY.values() for check in spec.checks}
    assert named == set(CHECKS)


@pytest.mark.parametrize("mode", ["incremental", "full", "both"])
@pytest.mark.parametrize("seeded", SEEDED, ids=IDS)
def test_the_checker_reports_exactly_the_seeded_check(seeded, mode):
    out = seeded.run(mode)
    _caught(out, seeded)
    assert out.trace[-1]["violation"]["check"] == seeded.reports  # the trace names it too


@pytest.mark.parametrize("seeded", SEEDED, ids=IDS)
def test_the_correct_explorer_is_verified_on_each_world(seeded):
    out = explore(seeded.world, seeded.like, options=seeded.options, record=False, check_mode="both",
                  lighthouse=seeded.lighthouse if algorithm_spec(seeded.like).uses_lighthouse else None)
    assert out.verified and out.violation is None, str(out.violation)


@pytest.mark.parametrize("disabled", list(CHECKS))
@pytest.mark.parametrize("seeded", SEEDED, ids=IDS)
def test_disabling_a_check_lets_through_its_own_fault_and_no_other(monkeypatch, seeded, disabled):
    """The pairing: with ``disabled`` always passing, the seeded fault of that check goes undetected (verified,
    or the later check its table row names); every other check's fault is still caught as before."""
    disable(monkeypatch, disabled)
    out = seeded.run(record=False)
    if disabled != seeded.check:
        _caught(out, seeded)
    elif seeded.unchecked is None:
        assert out.verified and out.violation is None and out.outcome == "correct", str(out.violation)
    else:
        assert out.violation is not None and out.violation.check == seeded.unchecked, str(out.violation)


def _pair(monkeypatch, check: str) -> list:
    """The outcomes of ``check``'s seeded faults, as caught and with ``check`` disabled."""
    faults = [s for s in SEEDED if s.check == check]
    caught = [s.run(record=False) for s in faults]
    disable(monkeypatch, check)
    return [(s, out, s.run(record=False)) for s, out in zip(faults, caught)]


def test_bound_function_fails_when_t_does_not_decrease(monkeypatch):
    """Once replaced by ``True`` unnoticed: an iteration that adds nothing to S must be a violation."""
    [(seeded, out, unchecked)] = _pair(monkeypatch, "bound-function")
    _caught(out, seeded)
    assert unchecked.verified and unchecked.iterations == 6  # the idle iteration passes only without the check


def test_marker_fails_when_a_marker_is_dropped_after_the_lighthouse(monkeypatch):
    """Once replaced by ``True`` unnoticed: a marker dropped after the start must be a violation."""
    [(seeded, out, unchecked)] = _pair(monkeypatch, "marker")
    _caught(out, seeded)
    assert unchecked.verified and unchecked.marker_operations == {"drop": 2}


def test_iterations_fail_when_the_counts_are_wrong(monkeypatch):
    """Once replaced by ``True`` unnoticed: n − 1 non-loop and m − n + 1 loop iterations, or a violation."""
    [(seeded, out, unchecked)] = _pair(monkeypatch, "iterations")
    _caught(out, seeded)
    assert unchecked.verified and (unchecked.nonloop_iterations, unchecked.loop_iterations) == (4, 1)

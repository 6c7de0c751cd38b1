"""What a run of an algorithm is expected to end with: ``correct``, ``may-fail`` or ``fails-by-design``.

``topomark bench`` judges every run against its algorithm's expectation on that world family with that lighthouse
(:func:`run_expectation`), so a sweep in which every run behaved as the thesis predicts exits 0 — Case 0's failed
runs and §5.2.1's wrong maps included — and one run that did not exits 1.

* ``correct``: every run must end ``correct`` — the thesis proves the algorithm maps every world it accepts.
* ``may-fail``: ``correct``, ``failed``, ``wrong-map`` and ``limit`` are all acceptable — the thesis says the
  approach is probabilistic and lists these outcomes (§5.2: "Without a marker, the robot cannot map a world
  deterministically"; §5.2.1: "No potential lighthouse may be identified, and the algorithm reports failure
  ... or, never terminates ... or terminates with an incorrect world model").
* ``fails-by-design``: the thesis shows the idea fails (an entry with the status ``implemented, expected to fail``:
  its ``status_reason`` cites the lines).  *Decision:* a run ending ``correct`` is acceptable too, besides
  ``failed`` and ``wrong-map``: the thesis says such an idea "does not work in general" (Case 0) and shows
  the flaw on one world (Figure 6.3), so it fails where that situation arises and maps a world where it cannot
  (a tree, for one).  A run that ends at a ``limit`` is not acceptable: none of these ideas is said to run on
  without end (the robot "is not able to determine" where it is, §6.2.1 Case 0 / Figure 6.3, and stops, or it takes a
  marked place for a new one, §6.2.2).

A crashed run (``error``) is never as expected.  An unchecked run (``bench --no-check``) ends ``unchecked`` or
as the algorithm stopped it; nothing is judged of it, so it is as expected whatever its expectation.

The expectation of a run is the broadest (:data:`ORDER`) of its algorithm's, for the run's world family (an
entry's ``expected_by_family`` where it differs, else its own), and its lighthouse's (:func:`lighthouse_expectation`:
§5.2.1's marker-less lighthouses may pick a place whose signature repeats; a lighthouse that is searched for
by a walk may find none within the threshold, and "the algorithm terminates reporting failure", §5.1).

Examples
--------
>>> as_expected("fails-by-design", "failed"), as_expected("fails-by-design", "limit")
(True, False)
>>> as_expected("correct", "wrong-map"), as_expected("may-fail", "wrong-map"), as_expected("may-fail", "error")
(False, True, False)
>>> broadest("correct", "may-fail", "fails-by-design")
'may-fail'
>>> lighthouse_expectation("local-pair")[0], lighthouse_expectation("directional-vertex")[0]
('may-fail', 'correct')
"""

from __future__ import annotations

from topomark.reference.explorers.lighthouses import LIGHTHOUSES

__all__ = ["CORRECT", "MAY_FAIL", "FAILS_BY_DESIGN", "EXPECTATIONS", "ACCEPTED", "ORDER", "as_expected",
           "broadest", "lighthouse_expectation", "UNJUDGED"]

CORRECT, MAY_FAIL, FAILS_BY_DESIGN = "correct", "may-fail", "fails-by-design"
EXPECTATIONS = (CORRECT, MAY_FAIL, FAILS_BY_DESIGN)
ACCEPTED: dict[str, frozenset[str]] = {
    CORRECT: frozenset({"correct"}),
    MAY_FAIL: frozenset({"correct", "failed", "wrong-map", "limit"}),
    FAILS_BY_DESIGN: frozenset({"correct", "failed", "wrong-map"}),
}
"""The run outcomes (``spec.errors.OUTCOMES``; a crashed bench run is ``error``) each expectation accepts."""
ORDER = (CORRECT, FAILS_BY_DESIGN, MAY_FAIL)
"""From the narrowest expectation to the broadest (each accepts every outcome the one before it accepts)."""
UNJUDGED = "unchecked"
"""The outcome of a run made without the checker: nothing is judged of it (module docstring)."""

SEARCH_REASON = ("a lighthouse searched for by a random walk may not be found: \"if the robot cannot find a "
                 "lighthouse within the threshold, the algorithm terminates reporting failure\" (§5.1)")
UNCERTAIN_REASON = ("a marker-less lighthouse of §5.2.1 \"cannot guarantee the explicitness of place or back-link\": "
                    "it may report failure, never terminate or end with an incorrect world model (§5.2.1)")


def as_expected(expectation: str, outcome: str, checked: bool = True) -> bool:
    """Whether a run that ended with ``outcome`` is what ``expectation`` accepts (an unchecked run always is)."""
    if not checked or outcome == UNJUDGED:
        return True
    return outcome in ACCEPTED[expectation]


def broadest(*expectations: str) -> str:
    """The broadest of ``expectations`` (:data:`ORDER`)."""
    return max(expectations, key=ORDER.index)


def lighthouse_expectation(name: str) -> tuple[str, str]:
    """What running with the lighthouse ``name`` allows, and why: ``may-fail`` for §5.2.1's marker-less
    lighthouses and for those found by a walk (§5.1), else ``correct`` (no reason)."""
    light = LIGHTHOUSES.get(name)
    if light is None:  # a kit algorithm's run ("none"): the algorithm's own expectation decides
        return CORRECT, ""
    if not light.certain:
        return MAY_FAIL, UNCERTAIN_REASON
    if light.search is not None:
        return MAY_FAIL, SEARCH_REASON
    return CORRECT, ""

"""Outcomes over generated worlds (issue 11, "Must show"): never a silent wrong map, and the checker's judgement
agrees with an independent one.

* §5.1 (``undirected-vertex``) and §6.1 (``undirected-edge``) either map the world or report ``failed``: on a
  world with no aperiodic place the walk gives up, it never guesses.
* Whatever a run reports, the judged outcome agrees with topomark's *other* isomorphism implementation
  (networkx's VF2 on the dart graphs, :mod:`topomark.spec.dartgraph`), applied to the map the run returned —
  the checker's verdict rests on :func:`topomark.spec.isomorphism.anchored`, so the two are independent.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from topomark.reference.run.explore import explore
from topomark.spec.dartgraph import find_isomorphism_nx
from topomark.spec.errors import OUTCOMES
from topomark.spec.world import World

from families import family_worlds

SETTINGS = settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _bare(world: World) -> World:
    return World(world.rotation, (), world.start)


@SETTINGS
@given(world=family_worlds(small=True), lighthouse=st.sampled_from(["undirected-vertex", "undirected-edge"]))
def test_searched_lighthouses_map_or_fail_never_a_wrong_map(world, lighthouse):
    out = explore(_bare(world), "basic", lighthouse=lighthouse, record=False)
    assert out.outcome in ("correct", "failed"), (out.outcome, out.violation)
    assert out.claimed == out.outcome
    if out.outcome == "failed":
        assert "walk" in out.reason or "no " in out.reason


@SETTINGS
@given(world=family_worlds(small=True),
       how=st.sampled_from([("basic", {"lighthouse": "local-pair"}), ("basic", {"lighthouse": "local-degree-list"}),
                            ("model-tree", {"options": {"max-steps": 60, "max-models": 200, "window": 5}}),
                            ("model-tree", {"options": {"signatures": "local", "max-steps": 60, "max-models": 200,
                                                        "window": 3}})]))
def test_a_marker_less_runs_outcome_matches_an_independent_judgement(world, how):
    algorithm, kw = how
    bare = _bare(world)
    out = explore(bare, algorithm, record=False, **kw)
    assert out.outcome in OUTCOMES
    if out.claimed != "correct":  # the algorithm stopped: the judged outcome is what it said, with its reason
        assert out.outcome == out.claimed and out.reason
        return
    S = out.explorer.S  # no marker anywhere: the map and the world are compared as embedded graphs
    other = S.complete() and find_isomorphism_nx(S.to_world(), bare, markers=True).isomorphic
    assert (out.outcome == "correct") == bool(other), (out.outcome, out.violation)

"""§6.2's unique-count marker algorithms (reference/explorers/counted_markers.py, registrations/markers_62.py):
Case 3a (Algorithm 6.2), Case 3b and Σ k directional vertex markers, each under the checker (pose, I-1, I-2 and
the marker budget after every step, extended isomorphism with every dropped marker at the end)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers.counted_markers import DirectionalVertexCounts, EdgeCounts, sum_to
from topomark.reference.worlds.generators import generate
from topomark.reference.algorithms.registry import REGISTRY, variant
from topomark.spec.world import Start, World
from topomark.spec.worldfile import world_from_json

from conftest import SMALL_WORLDS, bare, make_world

ALGORITHMS = ("case-3a", "case-3b", "case-dv-sum")
LATTICE_HOLE, RANDOM = "lattice-hole:rows=4,cols=5,seed=1", "random:n=10,fraction=0.3,seed=2"  # need more than 6
SAVING = (LATTICE_HOLE, RANDOM, "complete-hole:n=7,seed=1", "small-world:n=12,k=4,p=0.2,seed=3")
"""Worlds where both extensions use fewer markers than Case 3b (§6.2.2: they "may"; on Figure 3.4's wheel-a
extension-1 marks every non-loop edge, as many)."""


def used(out) -> int:
    """Markers lying in the world at the end (the map shows the same, or the isomorphism check fails)."""
    return sum(m.count for m in out.explorer.S.to_world().markers)


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_each_algorithm_maps_each_world_with_exactly_the_assured_markers(name, text):
    w = bare(make_world(text))
    out = explore(w, name)
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    assert out.checks > 3 * w.m  # pose/I-1/I-2 and the budget after every one of the m iterations
    assert used(out) == sum_to(w.n - 1) <= REGISTRY[name].marker_bound_fn(w.n, w.m)
    assert out.marker_operations == {"drop": w.n - 1}
    assert (out.nonloop_iterations, out.loop_iterations) == (w.n - 1, w.m - w.n + 1)
    assert out.by_purpose["new"] == w.m


@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_case_3b_validates_nothing_by_motion_and_pays_two_traversals_per_marked_edge(text):
    w = bare(make_world(text))
    out = explore(w, "case-3b")
    assert set(out.by_purpose) <= {"new", "drop", "travel"}  # §6.2.1 Case 3b: "Physical motion ... is avoided"
    assert out.drop_trips == out.by_purpose["drop"] == 2 * (w.n - 1)  # back over e and back, §6.2.1 Case 3b


@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_directional_vertex_markers_make_every_place_a_lighthouse_when_all_are_marked(text):
    w = bare(make_world(text))
    out = explore(w, "case-dv-sum", options={"markers": sum_to(w.n)})
    assert out.outcome == "correct" and used(out) == sum_to(w.n) == REGISTRY["case-dv-sum"].marker_bound_fn(w.n, w.m)
    assert set(out.by_purpose) <= {"new", "travel"}  # place and back-link at once, no probe (§6.2.2)


# K4 without the edge 0-1, started at 1 facing 3: the smallest world whose blank last vertex is re-entered over a
# loop edge (closest-first, the last vertex explores its own edges first: no 3-vertex world and no start of C4 does)
K4_E = World({v: tuple(w for w in ns if {v, w} != {"0", "1"}) for v, ns in generate("complete", n=4).rotation.items()},
             (), Start("1", "3"))


@pytest.mark.parametrize("name", ["case-3a", "case-dv-sum"])
def test_sigma_n_minus_1_leaves_the_last_vertex_blank_and_sigma_n_marks_it(name):
    """Case 3a's text and Figure 6.6 use Σ^n; Case 3a's title and Algorithm 6.2 Σ^{n−1}: with
    Σ_{k=1}^{n−1} k the last new vertex stays blank and is recognised by its blank label on re-entry; with
    Σ_{k=1}^{n} k all n are marked."""
    out = explore(K4_E, name)
    ex = out.explorer
    assert out.outcome == "correct" and used(out) == sum_to(3) and ex.blank == 3
    entered = [it for it in ex.iterations if it.kind == "loop" and it.joined[1][0] == ex.blank]
    if name == "case-3a":  # re-entered over a loop edge: known by its blank label, its back-link probed
        assert entered and entered[0].signature.vertex_count == 0 and entered[0].probes >= 1
    else:  # the blank's edges are explored from the blank, each into a lighthouse: never entered, no probe
        left = [it for it in ex.iterations if it.kind == "loop" and it.edge[0] == ex.blank]
        assert not entered and left and not any(it.probes for it in ex.iterations)
    full = explore(K4_E, name, options={"markers": sum_to(4)})
    assert full.outcome == "correct" and used(full) == sum_to(4) and full.explorer.blank is None


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("text", [LATTICE_HOLE, RANDOM])
def test_fewer_markers_than_assured_is_the_failed_outcome(name, text):
    out = explore(make_world(text), name, options={"markers": 6})
    assert (out.outcome, out.verified) == ("failed", False)
    assert "out of markers" in out.reason


K4_BLANK_TWICE = {"format": "topomark/world@1", "start": {"at": "1", "facing": "2"}, "rotation": {
    "0": ["2", "1", "3"], "1": ["0", "2", "3"], "2": ["0", "3", "1"], "3": ["1", "2", "0"]}}
"""K4 where Case 3a with one marker takes the second unmarked place for the blank and its probe finds the place
it came from: the join would be a self-loop."""


@pytest.mark.parametrize("markers", [1, 6])
def test_a_join_that_would_make_a_self_loop_with_too_few_markers_is_running_out_of_them(markers):
    out = explore(world_from_json(K4_BLANK_TWICE), "case-3a", options={"markers": markers})
    if markers == 6:  # the assured Σ_{k=1}^{3} k: mapped
        assert out.outcome == "correct"
    else:
        assert out.outcome == "failed" and "out of markers" in out.reason and "self-loop" in out.reason


def test_a_misidentified_loop_edge_is_caught_by_the_checker():
    class Wrong(EdgeCounts):
        def identify(self, it, sig):
            right = super().identify(it, sig)
            return next((d for d in self.M.unexplored if d != right and d[0] != it.edge[0]), right)

    out = explore(make_world(LATTICE_HOLE), variant("wrong-3b", Wrong, like="case-3b"))
    assert out.outcome == "wrong-map" and out.violation.check in ("I-1", "position")


def test_the_cli_runs_case_3b_and_refuses_a_count_below_one(capsys):
    run = subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", "explore", "lattice-hole:rows=4,cols=4,seed=2",
                          "--algorithm", "case-3b", "--json"], capture_output=True, text=True, timeout=120)
    data = json.loads(run.stdout)
    assert run.returncode == 0 and (data["outcome"], data["verified"]) == ("correct", True)
    assert main(["explore", "cycle:n=5", "--algorithm", "case-3b", "--markers", "3", "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["outcome"] == "failed"
    assert main(["explore", "cycle:n=5", "--algorithm", "case-3b", "--markers", "0"]) == 2
    assert "--markers must be an integer >= 1" in capsys.readouterr().err


EXTENSIONS = ("extension-1", "extension-2")


@pytest.mark.parametrize("name", EXTENSIONS)
@pytest.mark.parametrize("text", SAVING)
def test_the_extensions_map_each_world_within_their_bound_and_below_case_3b(name, text):
    w = bare(make_world(text))
    out = explore(w, name)
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    bound = REGISTRY[name].marker_bound_fn(w.n, w.m)
    drops = out.marker_operations["drop"]
    assert used(out) == sum_to(drops) <= bound  # counts 1, 2, ..., one per marked edge
    assert used(out) < sum_to(w.n - 1)  # fewer than Case 3b's Σ_{k=1}^{n−1} k
    if name == "extension-1":  # dropped in transit at v_k: no trip
        assert set(out.by_purpose) <= {"new", "travel"}
    else:  # Algorithm 6.6 line 10: back on e and back, per marked edge
        assert drops <= (w.n - 1 + 1) // 2 and out.drop_trips == out.by_purpose["drop"] == 2 * drops


def test_extension_2_needs_rule_3_the_naive_extension_maps_k4_minus_an_edge_wrong():
    """§6.2.2, Figure 6.15(b)-(c): a loop edge from an unmarked v_k, then closest-first from v_k' leaves v_k
    unmarked and a later entry takes it for a new place.  ``figure-6.15`` (K4 without an edge, from vertex 2
    facing 0) is the smallest world that shows it (no start of C3 or C4 does); with rule (3) it maps correctly."""
    k4_e = generate("figure-6.15")
    assert k4_e.rotation == K4_E.rotation and explore(k4_e, "extension-2").outcome == "correct"
    out = explore(k4_e, "extension-naive")
    # I-1 fails: with the world's live markers the checker sees first that a marked place is mapped unmarked
    assert out.outcome == "wrong-map" and out.violation.check == "I-1"
    for w in (make_world("cycle:n=3"), make_world("cycle:n=4")):
        for v in w.vertices:
            for facing in w.rotation[v]:
                assert explore(World(w.rotation, (), Start(v, facing)), "extension-naive").outcome == "correct"


@pytest.mark.parametrize("name", EXTENSIONS)
def test_the_extensions_fail_when_short_of_markers(name):
    out = explore(make_world(LATTICE_HOLE), name, options={"markers": 2})
    assert out.outcome == "failed" and "out of markers" in out.reason


@pytest.mark.parametrize("algorithm", ["case-1a", "case-1b", "case-2-edgeinfo", "case-4", "case-5-v2",
                                       "case-3a", "extension-2"])
def test_the_signatures_a_marker_walk_keeps_are_what_its_map_shows(algorithm, monkeypatch):
    """MarkerWalk.map_signature keeps M's signatures until M records a mark at the vertex: every one it returns
    over a whole run is the one computed afresh from M."""
    from topomark.reference.worlds import generators
    from topomark.reference.run.explore import explore
    from topomark.reference.explorers.marker_walk import MarkerWalk
    from topomark.spec.signature import signature_at
    kept, checked = MarkerWalk.map_signature, []

    def map_signature(self, v, entry):
        sig = kept(self, v, entry)
        checked.append(sig == signature_at(self.M, v, entry))
        return sig
    monkeypatch.setattr(MarkerWalk, "map_signature", map_signature)
    assert explore(generators.complete_hole(7, 0.2, 3), algorithm, record=False).outcome == "correct"
    assert len(checked) > 10 and all(checked)


def test_the_directional_vertex_markers_stay_within_o_m_on_a_wheel_whose_hub_is_left_blank():
    """Table 6.2 registers O(m) for Σ_{k=1}^{n−1} k directional V-markers.  On ``wheel-hub-last`` the
    hub, of degree d_max = n − 1, is the last new place and so the blank one (§6.2.1 Case 3a).  Exploring the blank's edges
    from the blank (counted_markers' decision) costs the rim walk (n − 1 edges), the first spoke, then out over
    each other spoke into a marked rim place and back over it, the last one not back: m + (n − 1) − 2 = 3m/2 − 2
    in all, so cost/m stays under 3/2 as m grows 40 → 160.  Without that choice (the edge policy alone), the
    spokes are entered at the blank hub and each back-link probed (Algorithm 6.2 lines 19–35): cost/m grows
    with d_max, past 10 at m = 160."""
    for n in (21, 41, 61, 81):
        w = generate("wheel-hub-last", n=n)
        out = explore(w, "case-dv-sum", record=False)
        hub = out.explorer.blank
        assert out.outcome == "correct" and used(out) == sum_to(n - 1)
        assert hub is not None and out.explorer.S.degree(hub) == n - 1  # the hub is the blank
        assert out.cost <= 3 * out.m / 2 and "validation" not in out.by_purpose, (n, out.cost, out.by_purpose)

    class PolicyAlone(DirectionalVertexCounts):
        @property
        def edge_policy(self):
            return self.policies

    probed = explore(w, variant("policy-alone", PolicyAlone, like="case-dv-sum"), record=False)
    assert probed.outcome == "correct" and probed.cost / probed.m > 10 and probed.by_purpose["validation"] > 0


@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_the_directional_vertex_markers_never_probe_even_with_a_blank_place(text):
    """Every marked place is a directional lighthouse (§6.2.2) and the blank's edges are explored from the blank,
    so the default kit (one place blank) needs no back-link probe anywhere."""
    out = explore(bare(make_world(text)), "case-dv-sum", record=False)
    assert out.outcome == "correct" and out.explorer.blank is not None
    assert set(out.by_purpose) <= {"new", "travel"} and not any(it.probes for it in out.explorer.iterations)


@pytest.mark.parametrize("name", ["extension-1", "extension-2", "extension-2-listing", "extension-naive"])
def test_the_extensions_of_case_3b_take_no_edge_policy(name, capsys):
    """§6.2.2 rule (1): the extensions explore closest-first, so ``--policy edge=...`` is refused (exit 2)."""
    assert "policy edge" not in REGISTRY[name].options
    assert main(["explore", "lattice:rows=3,cols=3", "--algorithm", name, "--policy", "edge=fifo"]) == 2
    assert "takes no edge policy" in capsys.readouterr().err


def test_closest_first_is_what_keeps_extension_2_s_places_marked(monkeypatch):
    """Why the extensions fix the edge policy (rule (1)): a policy given is ignored, and with closest-first replaced
    by ``fifo`` inside the explorer, extension-2 reaches a place with no marked edge and the checker's I-1 stops it."""
    from topomark.reference.explorers.policies import Policies
    from topomark.reference.explorers.saving_markers import SavingEdgeCounts

    world = generate("lattice", rows=3, cols=3)
    assert explore(world, "extension-2").outcome == "correct"
    assert explore(world, "extension-2", policies=Policies(edge="fifo")).outcome == "correct"  # ignored
    monkeypatch.setattr(SavingEdgeCounts, "edge_policy", Policies(edge="fifo"))
    run = explore(world, "extension-2")
    assert run.violation is not None and "I-1" in str(run.violation)

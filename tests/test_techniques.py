"""Chapter 4 as composable techniques on Algorithm 3.1's template (thesis §3.3, §4.1–4.3; issue 10 item 5).

Every registered algorithm runs the one loop body of
``reference/explorers/algorithm31.py``; the Chapter 4 algorithms are
compositions of technique objects (``reference/explorers/compositions.py``).
These tests pin the compositions to the thesis, the hooks to their listing
lines, and show that compositions the thesis never ran still map correctly.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from families import family_worlds
from topomark.reference.algorithms.registry import in_family
from topomark.reference.algorithms.registry import variant
from topomark.reference.run.explore import explore
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.compositions import ENHANCEMENTS, EXPLORERS
from topomark.reference.explorers.enhanced import EnhancedExplorer, Enhancement, Technique
from topomark.reference.explorers.expansion import ExpandedSignaturesOfCurrentPlace, ExpandedSignaturesOfNewVertices
from topomark.reference.explorers.overlap import OverlapStage1, OverlapStage2
from topomark.reference.explorers.tracing import ExecutedPathsOnS, ExecutedPathsOnSAndUnknownPlaces
from topomark.reference.worlds.generators import generate
from topomark.reference.explorers.policies import EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES, Policies
from topomark.reference.run.simulator import Simulator
from topomark.spec.world import World

policies = st.builds(Policies, st.sampled_from(EDGE_POLICIES), st.sampled_from(HYPOTHESIS_POLICIES),
                     st.sampled_from(PATH_POLICIES))

ALGORITHMS = {name: spec.factory for name, spec in in_family("algorithm-3.1").items()}
"""Algorithm 3.1's family, as registered: ``basic`` and the Chapter 4 enhancements, name ↦ explorer class."""

ENH3 = (OverlapStage2(), ExecutedPathsOnSAndUnknownPlaces())


def test_each_named_algorithm_is_the_composition_the_thesis_describes():
    E = {name: enh.techniques for name, enh in ENHANCEMENTS.items()}
    assert E["enh1"] == (OverlapStage1(), OverlapStage2())  # Algorithm 4.1: stages 1 and 2
    assert E["enh2"] == (OverlapStage2(), ExecutedPathsOnS())  # Algorithm 4.2: stage 2 + tracing on S
    assert E["enh3"] == ENH3  # Algorithm 4.3: ... on S and unknown places (T)
    assert E["enh4"] == (ExpandedSignaturesOfNewVertices(d=1),)  # Algorithm 4.4
    assert E["enh5-d1"] == (ExpandedSignaturesOfCurrentPlace(d=1),)  # Algorithm 4.5, d = 1
    assert E["enh5-d2"] == (ExpandedSignaturesOfCurrentPlace(d=2),)  # Algorithm 4.5, d = 2
    assert E["enh3+4"] == ENH3 + E["enh4"]  # Table 4.8
    assert E["enh3+5"] == ENH3 + E["enh5-d2"]  # Table 4.7: d = 2
    assert ExecutedPathsOnS() != ExecutedPathsOnSAndUnknownPlaces()
    assert ExpandedSignaturesOfCurrentPlace(d=1) != ExpandedSignaturesOfCurrentPlace(d=2)


def test_the_description_readers_see_follows_from_the_techniques():
    """replay/hypcheck and the registry read trace/stage2/prune/expand_new/expand_place off the composition."""
    seen = {name: (e.trace, e.stage2, e.prune, e.expand_new, e.expand_place) for name, e in ENHANCEMENTS.items()}
    assert seen == {
        "enh1": ("path", True, False, False, 0), "enh2": ("map", True, False, False, 0),
        "enh3": ("map+T", True, False, False, 0), "enh4": ("", False, True, True, 0),
        "enh5-d1": ("", False, True, False, 1), "enh5-d2": ("", False, True, False, 2),
        "enh3+4": ("map+T", True, True, True, 0), "enh3+5": ("map+T", True, True, False, 2),
    }
    none = Enhancement("basic")
    assert (none.trace, none.stage2, none.prune, none.expand_new, none.expand_place) == ("", False, False, False, 0)
    for enh in ENHANCEMENTS.values():
        assert enh.section.startswith("§4.") and all(t.section.startswith("§4.") for t in enh.techniques)


def test_every_algorithm_runs_the_one_template():
    """No explorer carries a loop body of its own: Chapter 4 only fills hooks."""
    assert ALGORITHMS["basic"] is LighthouseExplorer and {"basic"} | set(EXPLORERS) <= set(ALGORITHMS)
    for name, cls in ALGORITHMS.items():  # the family's members, whatever registration added them
        assert cls.iterate is LighthouseExplorer.iterate, name
        assert not any("iterate" in vars(k) for k in cls.__mro__ if k is not LighthouseExplorer), name
    for name in EXPLORERS:
        assert issubclass(ALGORITHMS[name], EnhancedExplorer) and ALGORITHMS[name].enhancement is ENHANCEMENTS[name]


def _bare(world: World) -> World:
    return World(world.rotation, (), world.start)


class _Logged(LighthouseExplorer):
    """Algorithm 3.1 logging each template hook with the purpose of the robot's last move."""

    def __init__(self, robot, moves, *args):
        super().__init__(robot, *args)
        self.moves, self.log = moves, []

    def _note(self, hook):
        self.log.append((hook, self.moves[-1] if self.moves else None))

    def on_enter(self, it, sig):
        self._note("on_enter")

    def validate(self, it, sig):
        self._note("validate")
        return super().validate(it, sig)

    def arrival(self, h):
        self._note("arrival")
        return super().arrival(h)

    def after_non_loop(self, it):
        assert it.kind == "non-loop" and it.joined[1] == (self.S.n - 1, 0)
        self._note("after_non_loop")

    def after_join(self, it):
        assert it.joined is not None and it.joined[0] == it.edge
        self._note("after_join")


def test_template_hooks_run_at_their_listing_lines_in_order():
    world = _bare(generate("lattice-hole", rows=5, cols=5, seed=2))
    moves, per_iteration = [], []
    sim = Simulator(world, world.start_state(), {"directional-vertex": 1},
                    listener=lambda motion, purpose, sig, state: moves.append(purpose))

    def observer(explorer, it):
        per_iteration.append((it.kind, it.by_marker, [h for h, _ in explorer.log], explorer.log[0][1]))
        explorer.log = []

    _Logged(sim.robot(), moves, None, observer).explore()
    kinds = {(kind, marker): (hooks, first) for kind, marker, hooks, first in per_iteration}
    assert kinds[("loop", True)] == (["after_join"], "new")  # line 7, then the marker's join
    assert kinds[("loop", False)] == (["on_enter", "validate", "arrival", "after_join"], "new")
    assert kinds[("non-loop", False)] == (["on_enter", "validate", "after_non_loop", "after_join"], "new")
    assert len(kinds) == 3 and len(per_iteration) == world.m


class _Spy(Technique):
    """A technique that changes nothing and logs each technique hook."""

    def __init__(self, log):
        self.log = log

    def known_on_entering(self, explorer, it):
        self.log.append(("known_on_entering", it.number))

    def on_enter(self, explorer, it):
        self.log.append(("on_enter", it.number))

    def prune(self, explorer, it, found):
        self.log.append(("prune", it.number))
        return found

    def choose(self, explorer, remaining):
        self.log.append(("choose", None))
        return None

    def after_non_loop(self, explorer, it):
        self.log.append(("after_non_loop", it.number))

    def recorded_depth(self, new):
        self.log.append(("recorded_depth", new))
        return 0


def _moves(cls, world, pol=None, observer=None):
    moves = []
    sim = Simulator(world, world.start_state(), {"directional-vertex": 1},
                    listener=lambda motion, purpose, sig, state: moves.append((motion, purpose, str(sig))))
    explorer = cls(sim.robot(), pol, observer)
    explorer.explore()
    return moves, explorer


def test_technique_hooks_run_in_order_and_a_no_op_technique_changes_nothing():
    world = _bare(generate("complete-hole", n=7, seed=3))
    log, per_iteration = [], []
    techniques = (_Spy(log),) + ENH3 + (ExpandedSignaturesOfCurrentPlace(2),)
    spied = type("Spied", (EnhancedExplorer,), {"enhancement": Enhancement("spied", techniques)})

    def observer(explorer, it):
        per_iteration.append((it, list(log)))
        log.clear()

    moves, _ = _moves(spied, world, None, observer)
    assert moves == _moves(ALGORITHMS["enh3+5"], world)[0]
    assert {it.kind for it, _ in per_iteration} == {"loop", "non-loop"} and any(it.by_marker for it, _ in per_iteration)
    for it, calls in per_iteration:
        if it.by_marker:  # line 7 shows the marker: no validation, nothing recorded
            assert calls == []
            continue
        attempted = [h for h in it.hypotheses if h.rejected_by == "motion" or h.outcome == "case 3"]
        want = [("known_on_entering", it.number), ("on_enter", it.number), ("prune", it.number)]
        want += [("choose", None)] * len(attempted)
        want += [("after_non_loop", it.number)] if it.kind == "non-loop" else []
        assert calls == want + [("recorded_depth", it.kind == "non-loop")], it.number


def _ends(cls, world, pol):
    """Per iteration: e, the join, the confirmed hypothesis, and the map vertex the robot ends at."""
    out = []
    bare = _bare(world)
    sim = Simulator(bare, bare.start_state(), {"directional-vertex": 1})

    def observer(explorer, it):
        confirmed = [h.dart for h in it.hypotheses if h.outcome == "case 3"]
        out.append((it.edge, it.kind, it.joined, it.by_marker, confirmed, explorer.position[0]))

    cls(sim.robot(), pol, observer).explore()
    return out


@settings(max_examples=25, deadline=None)
@given(family_worlds(small=True), policies)
def test_section_4_1_techniques_confirm_what_basic_confirms_and_end_where_it_ends(world, pol):
    """Enhancements 1-3 change only how hypotheses are rejected: every iteration joins the same edge,
    confirms the same hypothesis and leaves the robot at the same place of S as Algorithm 3.1."""
    basic = _ends(LighthouseExplorer, world, pol)
    for name in ("enh1", "enh2", "enh3"):
        assert _ends(ALGORITHMS[name], world, pol) == basic, name


UNREGISTERED = {
    "stage1-only": (OverlapStage1(),),
    "enh1+4": (OverlapStage1(), OverlapStage2(), ExpandedSignaturesOfNewVertices(1)),
    "enh2+5-d1": (OverlapStage2(), ExecutedPathsOnS(), ExpandedSignaturesOfCurrentPlace(1)),
    "T-without-stage2": (ExecutedPathsOnSAndUnknownPlaces(),),
    "enh4+5-d1": (ExpandedSignaturesOfNewVertices(1), ExpandedSignaturesOfCurrentPlace(1)),
}


@settings(max_examples=40, deadline=None)
@given(family_worlds(small=True), st.sampled_from(sorted(UNREGISTERED)), policies)
def test_compositions_the_thesis_never_ran_still_map_every_world_with_every_check(world, name, pol):
    """The techniques are independent: any combination keeps Algorithm 3.1's invariants (I-1, I-2, t,
    Lemma 1, marker, believed position) and ends with S ≅ G and T absorbed into S."""
    cls = type(f"_{name}", (EnhancedExplorer,), {"enhancement": Enhancement(name, UNREGISTERED[name]), "name": name})
    out = explore(world, variant(f"_{name}", cls), pol, record=False)
    assert out.violation is None, out.violation
    assert out.verified and out.nonloop_iterations == world.n - 1
    assert out.explorer.T == {}
    if not any(t.expands_new or t.expands_place for t in UNREGISTERED[name]):
        assert out.by_purpose.get("expansion", 0) == 0  # §4.1's techniques make no extra traversals


def test_stage_2_alone_is_refused():
    """Algorithm 4.1 executes only the non-overlapped part of M: the overlapped part must have been compared
    with P^E (stage 1, or tracing that subsumes it), else a wrong hypothesis could be confirmed."""
    with pytest.raises(ValueError, match="stage 2"):
        Enhancement("stage2-only", (OverlapStage2(),))
    assert Enhancement("ok", (ExecutedPathsOnS(), OverlapStage2())).stage2


def test_only_enhancement_3_and_expansions_record_into_T():
    world = _bare(generate("lattice-hole", rows=6, cols=6, seed=1))
    for name in ("enh1", "enh2"):
        assert _moves(ALGORITHMS[name], world)[1].stats["recorded"] == 0
    for name in ("enh3", "enh4", "enh5-d1"):
        assert _moves(ALGORITHMS[name], world)[1].stats["recorded"] > 0

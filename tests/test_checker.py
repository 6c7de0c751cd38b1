"""The checker catches broken explorers, and its incremental and full modes agree (§3.4)."""

from __future__ import annotations

import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import given, settings

from families import family_worlds
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.worlds import generators as g
from topomark.reference.run.explore import explore
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.spec.invariants import correspondence, explored_subgraph, lighthouse_anchor
from topomark.spec.marker import VertexMarker
from topomark.spec.world import Start, World


class KeepsLoopDartInU(LighthouseExplorer):
    """Forgets to remove e' from U on a loop closure."""

    def loop_augment(self, it, far, by_marker=False):
        super().loop_augment(it, far, by_marker)
        self.S.unexplored.append(far)


class NoRealign(LighthouseExplorer):
    """Does not re-align to e after retracing: the heading stays 0."""

    def validate(self, it, sig):
        confirmed, heading = super().validate(it, sig)
        return confirmed, 0


class TrustsFirstHypothesis(LighthouseExplorer):
    """Confirms the first hypothesis without validating it."""

    def validate(self, it, sig):
        it.hypotheses = self.hypotheses(it, sig)
        if not it.hypotheses:
            return None, 0
        h = it.hypotheses[0]
        h.outcome = "case 3"
        # pretend the robot is at v0 (it is not): walk there physically is skipped
        return h, 0


class CounterClockwiseNewVertex(LighthouseExplorer):
    """Numbers a new vertex's exits counter-clockwise."""

    def non_loop_augment(self, it, sig, heading):
        super().non_loop_augment(it, sig, heading)
        u, d = self.S.n - 1, sig.degree
        if d > 2:
            self.S._adj[u][1:] = self.S._adj[u][1:][::-1]  # only safe while exits 1.. are unjoined
            self.position = (u, (-heading) % d)


FAULTS = {
    KeepsLoopDartInU: "I-2",
    NoRealign: None,
    TrustsFirstHypothesis: None,
    CounterClockwiseNewVertex: None,
}


@pytest.mark.parametrize("fault", list(FAULTS))
@pytest.mark.parametrize("mode", ["incremental", "full", "both"])
def test_faults_are_caught(fault, mode):
    world = g.lattice_hole(5, 5, 0.1, seed=2).with_start(None)
    out = explore(world, replace(algorithm_spec("basic"), explorer=fault), check_mode=mode)
    assert out.violation is not None and not out.verified
    assert out.violation.check != "checker agreement"
    if FAULTS[fault]:
        assert out.violation.check == FAULTS[fault]
    assert "iteration" in out.violation.detail
    assert out.trace[-1]["violation"]["check"] == out.violation.check


def test_an_unchecked_run_is_never_called_verified():
    out = explore(g.cycle(5).with_start(Start("0", "1")), check=False)
    assert not out.verified and out.violation is None and out.checks == 0


@settings(max_examples=60, deadline=None)
@given(family_worlds(small=True))
def test_incremental_and_full_checks_agree_on_correct_runs(world):
    a = explore(world, check_mode="incremental")
    b = explore(world, check_mode="full")
    assert a.verified and b.verified and a.cost == b.cost


def test_violation_names_the_first_broken_iteration():
    world = g.cycle(4).with_start(Start("0", "1"))
    out = explore(world, replace(algorithm_spec("basic"), explorer=KeepsLoopDartInU))
    loops = [it.number for it in out.explorer.iterations if it.kind == "loop"]
    assert out.violation.data["iteration"] == loops[0]
    assert "listed" in out.violation.found or "explored" in out.violation.found


def test_checks_survive_python_O():
    """Checks are not bare asserts: under ``python -O`` a broken explorer is still caught."""
    code = (
        f"import sys; sys.path.insert(0, {str(Path(__file__).parent)!r})\n"
        "from faults_min import KeepsLoopDartInU\n"
        "from dataclasses import replace\n"
        "from topomark.reference.algorithms.registry import algorithm_spec\n"
        "from topomark.reference.worlds import generators\n"
        "from topomark.reference.run.explore import explore\n"
        "basic = replace(algorithm_spec('basic'), explorer=KeepsLoopDartInU)\n"
        "print(explore(generators.cycle(5), basic).violation.check)\n"
    )
    proc = subprocess.run([sys.executable, "-O", "-c", code], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "I-2"


def test_explored_subgraph_grows_to_the_world():
    world = g.lattice(3, 3)
    S = explore(world).explorer.S
    v, facing = world.start_state()
    marked = World(world.rotation, [VertexMarker(v, 1, world.neighbour(v, facing))])
    phi = correspondence(S, marked, lighthouse_anchor(S, marked)).witness
    vertices, edges = explored_subgraph(S, phi)
    assert vertices == set(world.vertices)
    assert edges == {frozenset(e) for e in world.edges()}

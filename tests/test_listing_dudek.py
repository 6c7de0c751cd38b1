"""§2.3.1's description of Dudek et al.'s movable marker algorithm as a reference (and its directional variant):
the conformance oracle fails a program only for what the thesis forbids, and a cost above topomark's improved
explorer is a difference.

* ``dudek-listing`` and ``dudek-directional-listing`` follow the description as written; their bounds
  (``docs/bounds.md``) hold on every embedded world of up to four vertices from every start under every edge
  policy, are reached, and topomark's explorers never cost more than the description on the same run;
* an independent client written from the description (``reference/oracle/examples/client_dudek_listing.py``)
  passes the listing suites with the reference's costs, passes topomark's explorers' suites with differences,
  and a wrong or wasteful copy fails;
* replay's re-run accepts a trace of either explorer under either name and says which it followed.
"""

from __future__ import annotations

import ast
import copy
import json
import sys
from pathlib import Path

import pytest

from conftest import SMALL_WORLDS, bare, make_world
from topomark.proofs.enumerate import embedded_worlds
from topomark.spec.world import Start
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec, variant
from topomark.reference.cli.main import main
from topomark.reference.algorithms.registrations.movable import directional_listing_bound, dudek_listing_bound
from topomark.reference.explorers.edge_choices import EDGE_CHOICES
from topomark.reference.explorers.movable_marker import ListingMovableMarkerExplorer
from topomark.reference.explorers.policies import Policies
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.replay.replay import replay
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators as g

CLIENT = Path(__file__).resolve().parents[1] / "reference" / "oracle" / "examples" / "client_dudek_listing.py"
PAIRS = {"dudek": ("dudek-listing", dudek_listing_bound),
         "dudek-directional": ("dudek-directional-listing", directional_listing_bound)}
NAMES = [name for ours, (literal, _) in PAIRS.items() for name in (ours, literal)]


def _starts(world):
    for v in world.vertices:
        for facing in dict.fromkeys(world.rotation[v]):
            yield world.with_start(Start(v, facing))


def _every_small_run(ours: str, edges: tuple[str, ...]) -> tuple[int, int]:
    """Both explorers on every embedded world of up to four vertices, from every start, under ``edges``: the
    description within its bound and topomark's explorer never above it; how many runs, how many at the bound."""
    literal_name, bound_fn = PAIRS[ours]
    literal, improved = algorithm_spec(literal_name), algorithm_spec(ours)
    runs = reached = 0
    for world in embedded_worlds(4, 3):
        bound = bound_fn(world.n, world.m)
        for started in _starts(world):
            for edge in edges:
                policies = Policies(edge=edge)
                as_written = explore(started, literal, policies, check_mode="incremental")
                mine = explore(started, improved, policies, check=False)
                assert as_written.outcome == "correct" and as_written.cost <= bound, (started, edge, bound)
                assert mine.cost <= as_written.cost, (started, edge)  # it leaves moves out, on every run here
                runs += 1
                reached += as_written.cost == bound
    return runs, reached


@pytest.mark.parametrize("ours", sorted(PAIRS))
def test_the_description_s_bound_holds_on_every_small_world_and_is_reached(ours):
    runs, reached = _every_small_run(ours, ("nearest",))
    assert runs == 96 and reached > 0  # every start of the 12 worlds; the bound is tight


@pytest.mark.slow
@pytest.mark.parametrize("ours", sorted(PAIRS))
def test_the_description_s_bound_holds_under_every_edge_policy(ours):
    runs, reached = _every_small_run(ours, tuple(EDGE_CHOICES))
    assert runs == 3 * 96 and reached > 0


def test_the_description_drops_at_every_step_and_searches_every_known_vertex():
    """The smallest worlds that tell the description from topomark's explorer: one edge (topomark's drops
    nothing: no known vertex can be v_u) and the triangle (its one loop step: v_k' has one unexplored exit)."""
    edge = g.chain(2)
    assert [explore(edge, a).cost for a in ("dudek", "dudek-listing")] == [1, 3]  # drop, come back, fetch it
    triangle = g.cycle(3)
    ours, literal = explore(triangle, "dudek"), explore(triangle, "dudek-listing")
    assert (ours.cost, literal.cost) == (6, 17)
    assert literal.marker_operations == {"drop": 4, "pick_up": 4}  # three steps, the loop one drops twice
    assert ours.marker_operations == {"drop": 1, "pick_up": 1}  # only the loop step drops, at v_u


def test_the_registry_names_the_listing_and_whose_each_bound_is():
    for ours, (literal_name, bound_fn) in PAIRS.items():
        improved, literal = algorithm_spec(ours), algorithm_spec(literal_name)
        assert improved.listing_entry == literal.name and improved.changes and not improved.follows_listing
        assert literal.follows_listing and literal.listing_entry is None
        assert improved.bound_fn is literal.bound_fn is bound_fn
        assert improved.bound_source == literal.bound_source == "listing" and improved.bound_binds
        assert improved.kit == literal.kit
    assert algorithm_spec("thread-carried").bound_source == "variant"  # the same search, its own bound
    assert all(s.listing_entry in REGISTRY for s in REGISTRY.values() if s.listing_entry is not None)


def _trace(world, made: str, named: str) -> list[dict]:
    trace = copy.deepcopy(explore(world, algorithm_spec(made), check_mode="incremental").trace)
    trace[0]["algorithm"] = named
    return trace


@pytest.mark.parametrize("ours", sorted(PAIRS))
@pytest.mark.parametrize("made_literal", [False, True])
@pytest.mark.parametrize("named_literal", [False, True])
def test_replay_accepts_either_explorer_under_either_name_and_says_which(ours, made_literal, named_literal):
    world = g.complete(4)
    literal = PAIRS[ours][0]
    made, named = (literal if made_literal else ours), (literal if named_literal else ours)
    result = replay(world, _trace(world, made, named))
    assert result.ok and result.rerun is not None and result.rerun["algorithm"] == made
    assert result.to_json()["rerun"]["follows"] == ("the thesis's listing" if made_literal else "topomark's variant")
    assert made in result.message


class _FarthestFirst(ListingMovableMarkerExplorer):
    """The description as written, but the known vertices visited farthest first: a valid search neither
    re-run makes."""

    def places(self, vk, degree):
        return super().places(vk, degree)[::-1]


def test_replay_rejects_a_trace_that_follows_neither():
    world = g.complete(4)
    trace = copy.deepcopy(explore(world, variant("mine", _FarthestFirst, like="dudek-listing")).trace)
    trace[0]["algorithm"] = "dudek"
    result = replay(world, trace)
    assert not result.ok and result.divergence is not None and result.divergence.check == "algorithm"
    assert "(dudek-listing, re-run)" in result.divergence.expected  # the one it follows longest is reported
    assert "follows neither this explorer nor dudek (topomark's variant)" in result.divergence.detail


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("listing-dudek") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(NAMES))
    return root


def _client(tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    text = CLIENT.read_text()
    if old:
        assert text.count(old) == 1
        text = text.replace(old, new)
    path = tmp_path / "client.py"
    path.write_text(text)
    return [sys.executable, str(path)]


def test_the_literal_client_is_standalone():
    tree = ast.parse(CLIENT.read_text())
    imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
    imported |= {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
    assert imported == {"json", "sys", "collections"}  # the standard library only: nothing of topomark


def test_the_literal_client_matches_the_description_and_differs_from_topomark_s_explorers(suite, tmp_path):
    rows = {r.algorithm: r.to_json() for r in run_algorithms(suite, _client(tmp_path), NAMES, select="triangle")}
    assert set(rows) == set(NAMES) and all(j["verdict"] == "pass" for j in rows.values()), rows
    assert [rows[n]["cost"] for n in NAMES] == [17, 17, 12, 12]  # the description's costs on the triangle
    assert [rows[n]["reference"]["cost"] for n in NAMES] == [6, 17, 6, 12]
    assert [rows[n]["reason"] == "difference" for n in NAMES] == [True, False, True, False]


@pytest.mark.slow
def test_the_literal_client_passes_every_suite_with_differences_from_topomark_s_explorers(suite, tmp_path):
    rows = run_algorithms(suite, _client(tmp_path), NAMES)
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == set(NAMES)
    for row in rows:
        j = row.to_json()
        assert j["bound_binds"] and j["bound_source"]["source"] == "listing" and j["cost"] <= j["bound"]
        if row.algorithm.endswith("-listing"):  # the description's own reference: the same costs
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
    differences = [r.to_json() for r in rows if r.reason == "difference"]
    assert {d["algorithm"] for d in differences} == set(PAIRS)
    d = differences[0]
    assert d["verdict"] == "pass" and d["difference"]["variant_figure"] == d["reference"]["cost"] < d["cost"]
    assert d["difference"]["listing_bound"] == d["bound"] >= d["cost"]
    assert f"{d['algorithm']} (topomark's variant)" in d["message"]


def test_a_client_with_a_wrong_map_fails(suite, tmp_path):
    mirrored = _client(tmp_path, "[names[w] for w, _ in row]", "[names[w] for w, _ in reversed(row)]")
    rows = run_algorithms(suite, mirrored, NAMES, select="chiral-5")
    assert len(rows) == 4 and not any(r.passed for r in rows) and {r.reason for r in rows} == {"not-isomorphic"}


def test_a_client_over_the_description_s_bound_fails(suite, tmp_path):
    wasteful = _client(tmp_path, '        self.operate("drop")  # "placing the marker at v_u"\n',
                       '        self.operate("drop")  # "placing the marker at v_u"\n'
                       '        self.back()\n        self.back()\n')  # over e and back once more, every step
    rows = run_algorithms(suite, wasteful, NAMES, select="triangle")
    assert len(rows) == 4 and not any(r.passed for r in rows) and {r.reason for r in rows} == {"bound"}
    assert all("topomark's bound for the thesis's listing" in r.message for r in rows)


@pytest.mark.parametrize("name", ["dudek-listing", "dudek-directional-listing"])
@pytest.mark.parametrize("world", ["wheel-a", "lattice-hole:rows=4,cols=4,seed=1"])
def test_the_literal_client_makes_the_description_s_moves(capsys, name, world):
    """Written from §2.3.1 alone, the client makes the choices the explorer module states, and so costs
    exactly what ``name`` costs on the same world."""
    unmarked = bare(make_world(world))
    spec = algorithm_spec(name)
    kit = json.dumps(spec.kit_for(unmarked.n, unmarked.m, {}).to_json())
    code = main(["run-external", world, "--kit", kit, "--json", "--", sys.executable, str(CLIENT)])
    report = json.loads(capsys.readouterr().out)
    assert (code, report["verdict"]) == (0, "pass"), report["message"]
    ours = explore(unmarked, spec)
    assert ours.outcome == "correct" and report["cost"] == ours.cost <= spec.bound_for(unmarked.n, unmarked.m)


@pytest.mark.parametrize("name", ["dudek-listing", "dudek-directional-listing"])
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_the_description_drops_once_per_step_and_searches_back_at_every_loop(name, text):
    """On the thesis's small worlds: the map is right, the cost within the bound, and the marker is dropped at
    every v_u — and, undirected, once more at v_k for the back-link search of every loop step, which tries at
    least one exit — and picked up again each time."""
    w = bare(make_world(text))
    out = explore(w, name)
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    loops = w.m - w.n + 1
    assert (out.nonloop_iterations, out.loop_iterations) == (w.n - 1, loops)
    assert out.cost <= algorithm_spec(name).bound_for(w.n, w.m)
    directional = algorithm_spec(name).kit.directional
    drops = w.m + (0 if directional else loops)
    assert out.marker_operations == {"drop": drops, "pick_up": drops}
    probes = [it.probes for it in out.explorer.iterations if it.kind == "loop"]
    assert all(p == 0 for p in probes) if directional else all(p >= 1 for p in probes)

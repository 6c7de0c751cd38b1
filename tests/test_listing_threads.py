"""The thesis's listings as references for the thread entries of §6.3 (Algorithm 6.8, §6.3.3; the fallback's
phase I, Algorithm 6.7, §6.3.2): the conformance oracle fails a program only for what the thesis forbids.

* ``thread-explore-listing`` runs Algorithm 6.8 as listed and ``thread-fallback-listing`` the fallback with
  phase I as Algorithm 6.7 is listed; their bounds (``docs/bounds.md``) hold on every embedded world of up to
  four vertices from every start for thread lengths 1–3, and topomark's variants never cost more there;
* replay's re-run accepts a trace of either explorer of a pair under either name and says which it followed;
* an independent client written from Algorithm 6.8 (``client_thread_listing.py --explore``) makes the listing's
  own reference costs and passes topomark's variant's suite with differences, never a FAIL; so does one written
  from the fallback's text with phase I as Algorithm 6.7 is listed (``--fallback``);
* §6.3.1's carried thread and §6.3.2's knots have no listing: their bounds are topomark's for its explorer, so a
  cost above them is a difference, never a FAIL.
"""

from __future__ import annotations

import copy
import sys
from pathlib import Path

import pytest

from topomark.proofs.enumerate import embedded_worlds
from topomark.spec.world import Start
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec
from topomark.reference.algorithms.registrations.threads import explore_bound, fallback_bound
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.conformance.judgement import binding_bound, difference
from topomark.reference.replay.replay import replay
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators as g

EXAMPLES = Path(__file__).resolve().parents[1] / "reference" / "oracle" / "examples"
CLIENT = EXAMPLES / "client_thread_listing.py"
EXPLORE = ["thread-explore", "thread-explore-listing"]
FALLBACK = ["thread-fallback", "thread-fallback-listing"]
BOUNDS = {"thread-explore": explore_bound, "thread-fallback": fallback_bound}


def _starts(world):
    for v in world.vertices:
        for facing in dict.fromkeys(world.rotation[v]):
            yield world.with_start(Start(v, facing))


@pytest.mark.parametrize("length", [1, 2, 3])
@pytest.mark.parametrize("pair", [EXPLORE, FALLBACK], ids=lambda p: p[0])
def test_the_listing_s_bound_holds_on_every_small_world_and_the_variant_never_costs_more(pair, length):
    ours, literal = map(algorithm_spec, pair)
    options = {"thread-length": length}
    runs = cheaper = 0
    for world in embedded_worlds(4, 3):
        bound = BOUNDS[pair[0]](world.n, world.m)
        for started in _starts(world):
            listed = explore(started, literal, check_mode="incremental", options=options)
            variant = explore(started, ours, check=False, options=options)
            assert listed.outcome == "correct" and listed.cost <= bound, (started, listed.cost)
            assert variant.cost <= listed.cost, (started, variant.cost, listed.cost)
            runs += 1
            cheaper += variant.cost < listed.cost
    assert runs == 96  # every start of the 12 worlds
    if pair == EXPLORE or length == 3:  # the two differ there (the fallback reaches phase II early otherwise)
        assert cheaper > 0


def test_the_registry_names_each_listing_and_only_a_listing_bound_binds():
    for ours, literal in (EXPLORE, FALLBACK):
        spec, listed = algorithm_spec(ours), algorithm_spec(literal)
        assert spec.listing_entry == literal and spec.changes and not spec.follows_listing
        assert listed.follows_listing and listed.listing_entry is None and listed.explorer.literal
        assert spec.bound_source == listed.bound_source == "listing" and spec.bound_fn is listed.bound_fn
    for name in ("thread-carried", "thread-knots"):  # the thesis lists neither (§6.3.1, §6.3.2)
        spec = algorithm_spec(name)
        assert spec.bound_source == "variant" and not spec.bound_binds and spec.listing_entry is None
        assert "no listing" in spec.changes and f"{name}-listing" not in REGISTRY


def _trace(world, made: str, named: str, options: dict) -> list[dict]:
    trace = copy.deepcopy(explore(world, algorithm_spec(made), check_mode="incremental", options=options).trace)
    trace[0]["algorithm"] = named
    return trace


@pytest.mark.parametrize("pair, length", [(EXPLORE, 2), (FALLBACK, 4)], ids=["explore", "fallback"])
@pytest.mark.parametrize("made", [0, 1])
@pytest.mark.parametrize("named", [0, 1])
def test_replay_accepts_either_explorer_under_either_name_and_says_which(pair, length, made, named):
    world, options = g.complete(4), {"thread-length": length}
    costs = {name: explore(world, algorithm_spec(name), check=False, options=options).cost for name in pair}
    assert costs[pair[0]] < costs[pair[1]]  # the two runs differ on this world, so the re-run must choose
    result = replay(world, _trace(world, pair[made], pair[named], options))
    assert result.ok and result.rerun is not None and result.rerun["algorithm"] == pair[made]
    assert result.to_json()["rerun"]["follows"] == ("topomark's variant" if made == 0 else "the thesis's listing")
    assert pair[made] in result.message


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("listing-threads") / "suite"
    export(root, cases=[], algorithms=suite_algorithms([*EXPLORE, *FALLBACK, "thread-carried", "thread-knots"]))
    return root


def _client(tmp_path: Path, path: Path, old: str = "", new: str = "", *args: str) -> list[str]:
    text = path.read_text()
    if old:
        assert text.count(old) == 1
        text = text.replace(old, new)
    copied = tmp_path / path.name
    copied.write_text(text)
    return [sys.executable, str(copied), *args]


@pytest.mark.parametrize("name", EXPLORE)
def test_the_literal_client_makes_the_listing_s_costs_and_differences_from_the_variant(suite, tmp_path, name):
    rows = run_algorithms(suite, _client(tmp_path, CLIENT, "", "", "--explore"), [name])
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    for row in rows:
        j = row.to_json()
        assert j["bound_binds"] and j["bound_source"]["source"] == "listing"
        if name == "thread-explore-listing":  # the listing's own reference: the same costs
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
    if name == "thread-explore":
        differences = [r.to_json() for r in rows if r.reason == "difference"]
        assert differences
        d = differences[0]
        assert d["difference"]["variant_figure"] == d["reference"]["cost"] < d["cost"] <= d["bound"]
        assert "thread-explore (topomark's variant)" in d["message"]


@pytest.mark.parametrize("name", FALLBACK)
def test_the_literal_client_plays_the_fallback_with_the_listing_s_costs_and_no_fail(suite, tmp_path, name):
    rows = run_algorithms(suite, _client(tmp_path, CLIENT, "", "", "--fallback"), [name])
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    for row in rows:
        j = row.to_json()
        assert j["bound_binds"] and j["cost"] <= j["bound"]
        if row.algorithm == "thread-fallback-listing":
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
        elif j["cost"] > j["reference"]["cost"]:  # topomark's phase I skipped a search: a difference
            assert row.reason == "difference" and "thread-fallback (topomark's variant)" in j["message"]


def test_a_fallback_client_that_leaves_the_thread_off_its_map_fails(suite, tmp_path):
    forgetful = _client(tmp_path, CLIENT, "        if self.phase == 2:  # the fallback leaves the thread",
                        "        if self.phase == 0:  # the fallback leaves the thread", "--fallback")
    rows = run_algorithms(suite, forgetful, ["thread-fallback-listing"])
    failed = [r for r in rows if not r.passed]  # the cases that reach phase II, where the thread stays laid
    assert failed and {r.reason for r in failed} == {"not-isomorphic"}
    assert all("thread-phase-ii" in r.case["ways"] for r in failed)


def test_a_literal_client_that_searches_no_neighbour_of_v_k_is_not_the_listing(suite, tmp_path):
    """The seeded fault of the check above: line 11 without v_k's neighbours is topomark's variant's search,
    not the listing's, and the listing's suite sees other costs (still no FAIL: within the listing's bound)."""
    narrowed = _client(tmp_path, CLIENT, "if v not in on and len(self.exits[v]) == degree}",
                       "if v not in on and len(self.exits[v]) == degree and v not in "
                       "{w for w, _ in filter(None, self.exits[vk])}}", "--explore")
    rows = run_algorithms(suite, narrowed, ["thread-explore-listing"])
    assert rows and all(r.passed for r in rows)
    assert any(r.to_json()["cost"] < r.to_json()["reference"]["cost"] for r in rows)


def test_a_client_over_the_listing_s_bound_fails(suite, tmp_path):
    wasteful = _client(tmp_path, CLIENT, '        self.op("untie")\n        names',
                       '        self.op("untie")\n        for _ in range(40):\n            self.move(0)\n'
                       '            self.move_back(*self.pos)\n        names', "--explore")
    rows = run_algorithms(suite, wasteful, EXPLORE, select="triangle")
    assert len(rows) == 2 and not any(r.passed for r in rows) and {r.reason for r in rows} == {"bound"}


def test_costs_of_the_carried_thread_and_the_knots_are_only_ever_a_difference(suite, tmp_path):
    """No listing, no binding bound (§6.3.1, §6.3.2): a correct map costing more than topomark's explorer
    passes with a difference, even above topomark's bound."""
    wasteful = _client(tmp_path, EXAMPLES / "client_thread.py", "    def run(self):\n",
                       "    def run(self):\n        for _ in range(200):\n            self.step(0)\n")
    rows = run_algorithms(suite, wasteful, ["thread-carried"])
    assert rows and all(r.passed and r.reason == "difference" for r in rows), [r.to_json() for r in rows]
    assert any(r.to_json()["cost"] > r.to_json()["bound"] for r in rows)
    assert all(r.to_json()["difference"]["listing_bound"] is None for r in rows)
    import json
    manifest = json.loads((suite / "manifest.json").read_text())
    knots = next(s for s in manifest["suites"] if s["algorithm"] == "thread-knots")
    for case in knots["cases"]:
        assert binding_bound(case) is None and case["variant"]["follows"] == "topomark's variant"
        over = difference(case, "thread-knots", case["bound"] + 1)
        assert over is not None and over["listing_bound"] is None

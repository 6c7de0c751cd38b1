"""The thesis's listing as a reference (Algorithm 6.7, §6.3.2, Table 6.3): the conformance oracle fails a program
only for what the thesis forbids, and a cost above topomark's improved variant is a difference.

* ``thread-circumference-listing`` runs Algorithm 6.7 as listed; its bound 2(n − 1) + (m − n + 1)(n + 2)
  (``docs/bounds.md``) holds on every embedded world of up to four vertices from every start, is reached there,
  and topomark's variant never costs more than the listing;
* an independent client written from the listing (``reference/oracle/examples/client_thread_listing.py``)
  passes both Algorithm 6.7 suites — with a *difference* against topomark's variant — and a wrong copy fails;
* replay's re-run accepts a trace of either explorer under either name and says which it followed;
* every exact bound says whose it is; thread lengths are capped like marker counts.
"""

from __future__ import annotations

import ast
import copy
import json
import sys
from pathlib import Path

import pytest

from topomark.proofs.enumerate import embedded_worlds
from topomark.spec.world import Start
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec, variant
from topomark.reference.algorithms.registrations.threads import LENGTH, MAX_THREAD, circumference_bound
from topomark.reference.cli.main import main
from topomark.reference.explorers.threads_explore import ListingThreadExplorer
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.conformance.judgement import binding_bound, difference
from topomark.reference.oracle.conformance.manifest import check_manifest
from topomark.reference.oracle.marker_messages import MAX_COUNT
from topomark.reference.replay.replay import replay
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators as g

CLIENT = Path(__file__).resolve().parents[1] / "reference" / "oracle" / "examples" / "client_thread_listing.py"
PAIR = ["thread-circumference", "thread-circumference-listing"]


def _starts(world):
    for v in world.vertices:
        for facing in dict.fromkeys(world.rotation[v]):
            yield world.with_start(Start(v, facing))


def test_the_listing_s_bound_holds_on_every_small_world_and_is_reached():
    listing, ours = algorithm_spec("thread-circumference-listing"), algorithm_spec("thread-circumference")
    runs = reached = 0
    for world in embedded_worlds(4, 3):
        bound = circumference_bound(world.n, world.m)
        for started in _starts(world):
            literal = explore(started, listing, check_mode="incremental")
            variant = explore(started, ours, check=False)
            assert literal.outcome == "correct" and literal.cost <= bound, (started, literal.cost, bound)
            assert variant.cost <= literal.cost  # the variant leaves searches out, so the same bound holds it
            runs += 1
            reached += literal.cost == bound
    assert runs == 96 and reached > 0  # every start of the 12 worlds; the bound is tight


def test_the_registry_names_the_listing_and_whose_each_bound_is():
    ours, literal = algorithm_spec("thread-circumference"), algorithm_spec("thread-circumference-listing")
    assert ours.listing_entry == literal.name and ours.changes and not ours.follows_listing
    assert literal.follows_listing and literal.listing_entry is None
    assert ours.bound_source == literal.bound_source == "listing" and ours.bound_binds and literal.bound_binds
    assert algorithm_spec("basic").bound_source == "thesis" and algorithm_spec("basic").bound_binds
    assert algorithm_spec("thread-knots").bound_source == "variant" and not algorithm_spec("thread-knots").bound_binds
    for spec in REGISTRY.values():  # every exact bound says whose it is, in the listing too
        if spec.bound_fn is not None:
            assert spec.bound_whose in spec.bound_note and spec.to_json()["bound_whose"] == spec.bound_whose


def _trace(world, made: str, named: str) -> list[dict]:
    trace = copy.deepcopy(explore(world, algorithm_spec(made), check_mode="incremental").trace)
    trace[0]["algorithm"] = named
    return trace


@pytest.mark.parametrize("made", PAIR)
@pytest.mark.parametrize("named", PAIR)
def test_replay_accepts_either_explorer_under_either_name_and_says_which(made, named):
    world = g.complete(4)
    result = replay(world, _trace(world, made, named))
    assert result.ok and result.rerun is not None and result.rerun["algorithm"] == made
    assert result.to_json()["rerun"]["follows"] == ("topomark's variant" if made == PAIR[0] else "the thesis's listing")
    assert made in result.message


class _HighestFirst(ListingThreadExplorer):
    """Algorithm 6.7 as listed, but "a closest edge" is the highest-numbered one: a valid run neither re-run makes."""

    def open_exit(self, v):
        exits = self.open_exits(v)
        return exits[-1] if exits else None


def test_replay_rejects_a_trace_that_follows_neither():
    world = g.complete(4)
    trace = copy.deepcopy(explore(world, variant("mine", _HighestFirst, like="thread-circumference-listing")).trace)
    trace[0]["algorithm"] = "thread-circumference"
    result = replay(world, trace)
    assert not result.ok and result.divergence is not None and result.divergence.check == "algorithm"
    assert "(thread-circumference, re-run)" in result.divergence.expected  # a tie: the named one is reported
    assert "follows neither this explorer nor thread-circumference-listing (the thesis's listing)" \
        in result.divergence.detail



@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("listing") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(PAIR))
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


def test_the_literal_client_passes_both_suites_with_differences_from_the_variant(suite, tmp_path):
    rows = run_algorithms(suite, _client(tmp_path), PAIR)
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    for row in rows:
        j = row.to_json()
        assert j["bound_binds"] and j["bound_source"]["source"] == "listing"
        if row.algorithm == "thread-circumference-listing":  # the listing's own reference: the same costs
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
    differences = [r.to_json() for r in rows if r.reason == "difference"]
    assert differences and all(d["algorithm"] == "thread-circumference" for d in differences)
    d = differences[0]
    assert d["verdict"] == "pass" and d["difference"]["variant_figure"] == d["reference"]["cost"] < d["cost"]
    assert d["difference"]["listing_bound"] == d["bound"] >= d["cost"]
    assert "thread-circumference (topomark's variant)" in d["message"]


def test_a_client_with_a_wrong_map_fails(suite, tmp_path):
    mirrored = _client(tmp_path, "[names[w] for w, _ in row]", "[names[w] for w, _ in reversed(row)]")
    rows = run_algorithms(suite, mirrored, PAIR, select="chiral-5")
    assert rows and not any(r.passed for r in rows) and {r.reason for r in rows} == {"not-isomorphic"}


def test_a_client_over_the_listing_s_bound_fails(suite, tmp_path):
    wasteful = _client(tmp_path, '        self.op("untie")\n        names',
                       '        self.op("untie")\n        for _ in range(2):\n            self.move(0)\n'
                       '            self.move_back(*self.pos)\n        names')
    rows = run_algorithms(suite, wasteful, PAIR, select="triangle")
    assert len(rows) == 2 and not any(r.passed for r in rows)
    assert {r.reason for r in rows} == {"bound"}
    assert "bound of the thesis's listing" in rows[0].message and "topomark's bound for the thesis's listing" \
        in rows[0].message


def _case(source: str | None, bound: int = 10, reference: int = 6, follows: str = "the thesis's listing") -> dict:
    case = {"bound": bound, "reference": {"cost": reference}, "variant": {"follows": follows}}
    if source is not None:
        case["bound_source"] = {"source": source, "binds": source != "variant", "whose": source}
    return case


def test_only_a_bound_of_the_listing_binds_and_a_variant_s_figure_is_a_difference():
    assert binding_bound(_case("thesis")) == binding_bound(_case("listing")) == 10
    assert binding_bound(_case("variant")) is None and binding_bound(_case(None)) is None  # 2.0: not recorded
    assert difference(_case("listing"), "a", 11) is None  # above a binding bound: a failure, not a difference
    assert difference(_case("listing"), "a", 8) is None  # the listing's own reference: no difference
    over = difference(_case("variant"), "a", 11)
    assert over is not None and over["variant_figure"] == 10 and over["listing_bound"] is None
    ours = difference(_case("listing", follows="topomark's variant"), "a", 8)
    assert ours is not None and (ours["variant_figure"], ours["listing_bound"]) == (6, 10)


def test_a_2_0_suite_without_provenance_stays_readable(suite):
    manifest = json.loads((suite / "manifest.json").read_text())
    assert manifest["version"] == "2.2.0"
    check_manifest(suite, manifest)
    manifest["version"] = "2.0.0"
    for s in manifest["suites"]:
        del s["ways"]  # new in 2.2
        for case in s["cases"]:
            del case["bound_source"], case["variant"], case["ways"]
    check_manifest(suite, manifest)
    manifest["suites"][0]["cases"][0]["bound_source"] = {"source": "mine"}
    with pytest.raises(Exception, match="bound_source"):
        check_manifest(suite, manifest)


def test_thread_lengths_are_capped_like_marker_counts(capsys):
    assert MAX_THREAD == MAX_COUNT == LENGTH.maximum
    for name in ("thread-circumference", "thread-explore", "thread-fallback", "thread-circumference-listing"):
        param = next(p for p in algorithm_spec(name).parameters if p.name == "thread-length")
        assert param.maximum == MAX_THREAD
    assert main(["explore", "cycle:n=3", "--algorithm", "thread-explore", "--thread-length",
                 str(MAX_THREAD + 1)]) == 2
    assert "at most 1,000,000" in capsys.readouterr().err
    assert main(["run-external", "cycle:n=3", "--kit", json.dumps({"thread": MAX_THREAD + 1}), "--",
                 sys.executable, str(CLIENT)]) == 2
    assert "a thread is at most 1,000,000 edges" in capsys.readouterr().err


def test_each_option_s_help_names_every_algorithm_taking_it(capsys):
    with pytest.raises(SystemExit):
        main(["explore", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    start = text.index("--thread-length VALUE the thread")
    help_ = text[start:start + 500].replace("- ", "-")
    for name in ("thread-circumference (default n)", "thread-circumference-listing (default n)",
                 "thread-explore (default 2)", "thread-fallback (default 2)", "1,000,000"):
        assert name in help_, help_


def test_the_docs_list_every_entry_and_what_it_changes():
    text = (Path(__file__).resolve().parents[1] / "docs" / "bounds.md").read_text(encoding="utf-8")
    rows = {line.split("|")[1].strip().strip("`"): line for line in text.splitlines() if line.startswith("| `")}
    assert set(REGISTRY) <= set(rows)
    for spec in REGISTRY.values():
        assert ("| none found:" in rows[spec.name]) == (spec.changes is None), spec.name


def test_lint_refuses_a_case_that_misnames_whose_its_bound_is(suite, tmp_path):
    import shutil

    from topomark.reference.oracle.conformance import lint
    from topomark.spec.errors import InvalidInput

    copied = tmp_path / "suite"
    shutil.copytree(suite, copied)
    manifest = json.loads((copied / "manifest.json").read_text())
    manifest["suites"][0]["cases"][0]["bound_source"]["source"] = "thesis"  # the thesis states no such bound
    (copied / "manifest.json").write_text(json.dumps(manifest))
    with pytest.raises(InvalidInput, match="bound_source 'thesis' but thread-circumference's bound is topomark's"):
        lint(copied, replay_traces=False)

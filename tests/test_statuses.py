"""Every algorithm the thesis describes is listed with a status (``implemented``, ``implemented, expected to
fail``, ``not implementable from the thesis``); the failing variants fail on their figure's world."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from topomark.reference.algorithms.algorithm_spec import Listed
from topomark.reference.algorithms.registry import LISTED, REGISTRY, listing, register
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate

from conftest import make_world

LISTINGS = ("3.1", "3.2", "4.1", "4.2", "4.3", "4.4", "4.5", "5.1",
            "6.1", "6.2", "6.3", "6.4", "6.5", "6.6", "6.7", "6.8", "6.9")
"""Every numbered listing of the thesis ("Algorithm 3.1: ..." to "Algorithm 6.9: ...")."""

EXPECTED_TO_FAIL = {"case-0": "complete:n=4", "case-3b-saving": "figure-6.10", "extension-naive": "figure-6.15",
                    "case-5-v1-listing": "cycle:n=3", "case-5-directional-listing": "cycle:n=3",
                    "case-5-v2-listing": "lattice:rows=2,cols=3"}
"""Each algorithm the thesis shows fails, and the world (named in its status reason) where it does."""
OPTIONS = {"case-5-v2-listing": {"markers": 4}}
"""The options its status reason names, where it fails only with them (Algorithm 6.5's phase II needs few markers)."""


def test_every_listing_of_the_thesis_is_registered_or_listed():
    theses = [entry.thesis for entry in listing()]
    for number in LISTINGS:
        assert any(f"Algorithm {number}" in t and not t.split(f"Algorithm {number}")[1][:1].isdigit()
                   for t in theses), number


def test_the_not_implementable_listings_are_refused_with_their_reason(capsys):
    assert set(LISTED) == {"path-execution", "explore-merge"}
    assert main(["explore", "figure-6.15", "--algorithm", "explore-merge"]) == 2
    err = capsys.readouterr().err
    assert "not implementable from the thesis" in err and "[59, 61]" in err and "§6.3.3" in err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert main(["explore", "cycle:n=4", "--algorithm", "path-execution", "--json"]) == 2
    assert "panoramic" in capsys.readouterr().err
    with pytest.raises(ValueError, match="listed as not implementable"):
        register(replace(REGISTRY["case-3b"], name="explore-merge"))


def test_the_listing_shows_every_status(capsys):
    assert main(["algorithms", "--json"]) == 0
    listed = {e["name"]: e for e in json.loads(capsys.readouterr().out)}
    failing = {n for n, e in listed.items() if e["status"] == "implemented, expected to fail"}
    assert failing == set(EXPECTED_TO_FAIL)
    assert listed["explore-merge"] == {"name": "explore-merge", "thesis": LISTED["explore-merge"].thesis,
                                       "status": "not implementable from the thesis",
                                       "status_reason": LISTED["explore-merge"].reason}
    assert main(["algorithms"]) == 0
    text = capsys.readouterr().out
    assert text.count("status: implemented, expected to fail: ") == len(EXPECTED_TO_FAIL)
    assert text.count("status: not implementable from the thesis: ") == len(LISTED)
    assert text.count("status: implemented\n") == len(REGISTRY) - len(EXPECTED_TO_FAIL)


@pytest.mark.parametrize("name", sorted(EXPECTED_TO_FAIL))
def test_each_failing_variant_fails_on_the_world_its_reason_names(name):
    spec = REGISTRY[name]
    assert EXPECTED_TO_FAIL[name] in spec.status_reason
    assert all(f"--{k} {v}" in spec.status_reason for k, v in OPTIONS.get(name, {}).items())
    out = explore(make_world(EXPECTED_TO_FAIL[name]), name, options=OPTIONS.get(name))
    assert out.outcome in ("failed", "wrong-map") and not out.verified


def test_the_undirected_saving_cannot_tell_two_neighbours_apart_on_figure_6_10(capsys):
    """§6.2.1 Case 4: the place entered and its neighbour show one signature, their only marked edge the one
    joining them (Figure 6.10(a), impossible in Case 3b): the marks fit two edges and the run fails."""
    w = generate("figure-6.10")
    assert explore(w, "case-3b").outcome == "correct"
    out = explore(w, "case-3b-saving")
    assert out.outcome == "failed" and "fit 2 unexplored edges" in out.reason
    S = out.explorer.M
    a, b = 0, 1  # v0 and the first new place: the two fits the reason names, (a, 2) and (b, 2)
    assert "[(0, 2), (1, 2)]" in out.reason and S.degree(a) == S.degree(b) == 3
    joined = [t for t in range(3) if S.arc((a, t)) is not None and S.arc((a, t))[0] == b]
    assert len(joined) == 1 and [len(S.dart_marks(v)) for v in (a, b)] == [1, 1]  # only their shared edge
    assert main(["explore", "figure-6.10", "--algorithm", "case-3b-saving", "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["outcome"] == "failed"


def test_the_naive_extension_maps_figure_6_15_wrong_through_the_checker(capsys):
    assert main(["explore", "figure-6.15", "--algorithm", "extension-naive", "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["outcome"] == "wrong-map"
    assert main(["explore", "figure-6.15", "--algorithm", "extension-2", "--json"]) == 0


def test_a_status_is_one_of_three_and_a_failing_one_says_why():
    with pytest.raises(ValueError, match="status"):
        replace(REGISTRY["case-3b"], status="works, mostly")
    with pytest.raises(ValueError, match="status_reason"):
        replace(REGISTRY["case-3b"], status="implemented, expected to fail")
    with pytest.raises(ValueError, match="status_reason"):
        replace(REGISTRY["case-3b"], status_reason="no reason to give")
    with pytest.raises(ValueError, match="reason"):
        Listed(name="x", thesis="§1", reason="")

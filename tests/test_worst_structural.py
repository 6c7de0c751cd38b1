"""The structural moves and family restarts of the worst-case search (§7.2): a switch splices two paths and keeps
every degree, a transpose and a marker move re-embed one place, a restart starts from the family's own world, and
the compiled engine scores a candidate exactly as the reference does."""

from __future__ import annotations

import os
import random
from collections import Counter

import networkx as nx
import pytest

from topomark.reference.engine import available
from topomark.reference.run.explore import explore
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.worlds.expensive import strip
from topomark.reference.worstcase.moves import graph_of
from topomark.reference.worstcase.search import _problem, adversarial_search
from topomark.reference.worstcase.structural import family_text, family_world, structural_move
from topomark.spec.errors import InvalidInput


def _degrees(w):
    return Counter({v: w.degree(v) for v in w.vertices})


def _edges(w):
    return set(map(frozenset, w.edges()))


def test_a_switch_replaces_two_edges_by_two_and_keeps_every_degree_and_connection():
    rng, w = random.Random(1), strip(16, cap=1)
    switched = 0
    for _ in range(200):
        moved = structural_move(w, "switch", 4, rng)
        if moved is None:
            continue
        switched += 1
        gone, new = _edges(w) - _edges(moved), _edges(moved) - _edges(w)
        assert len(gone) == len(new) == 2
        assert set().union(*gone) == set().union(*new)  # the same four places, joined crosswise
        assert _degrees(moved) == _degrees(w) and nx.is_connected(graph_of(moved))
        w = moved
    assert switched >= 50


@pytest.mark.parametrize("kind", ["transpose", "marker"])
def test_a_transpose_reorders_one_rotation_and_a_marker_move_one_at_or_beside_the_start(kind):
    rng, w = random.Random(2), strip(12, cap=1)
    for _ in range(100):
        moved = structural_move(w, kind, 4, rng)
        assert moved is not None and _edges(moved) == _edges(w) and moved.start == w.start
        changed = [v for v in w.vertices if moved.rotation[v] != w.rotation[v]]
        assert len(changed) == 1 and sorted(moved.rotation[changed[0]]) == sorted(w.rotation[changed[0]])
        if kind == "marker":
            assert changed[0] == w.start.at or changed[0] in w.rotation[w.start.at]


def test_an_unknown_move_or_family_or_size_is_bad_input_naming_it():
    with pytest.raises(InvalidInput, match="unknown structural move 'fold'"):
        structural_move(strip(8), "fold", 4, random.Random(0))
    with pytest.raises(InvalidInput, match="unknown restart family 'ladder'"):
        family_text("ladder", 20)
    with pytest.raises(InvalidInput, match="multiple of 5, not 21"):
        family_world("k5e-chain", 21)
    for n in (44, 47):
        with pytest.raises(InvalidInput, match=f"rewired-strip needs an even n >= 46, not {n}"):
            family_world("rewired-strip", n)
    for n in (14, 21):
        with pytest.raises(InvalidInput, match=f"split-strip needs an even n >= 16, not {n}"):
            family_world("split-strip", n)
    with pytest.raises(InvalidInput, match="pendant-strip needs n >= 13, not 12"):
        family_world("pendant-strip", 12)
    with pytest.raises(InvalidInput, match="max_degree must be >= 4, got 3"):
        adversarial_search("basic", 20, 3, evaluations=5, restart="strip", baseline=False)
    with pytest.raises(InvalidInput, match="not the lattice-hole family"):
        adversarial_search("basic", 16, 4, evaluations=5, restart="strip", family="lattice-hole", baseline=False)


@pytest.mark.parametrize("family,n", [("strip", 20), ("strip", 21), ("circulant", 20), ("k5e-chain", 20),
                                               ("rewired-strip", 46), ("split-strip", 16),
                                               ("pendant-strip", 13), ("pendant-strip", 20)])
def test_a_family_world_has_n_places_and_is_what_its_text_generates(family, n):
    from topomark.reference.worlds.argument import parse_generator
    from topomark.reference.worlds.generators import generate
    w, text = family_world(family, n)
    name, params = parse_generator(text)
    assert w.n == n and generate(name, **params).rotation == w.rotation


def test_a_restarted_search_is_never_worse_than_its_family_world():
    """The family's own world is in the first generation, and (μ+λ) keeps the best: a restart can only gain."""
    spec = algorithm_spec("basic")
    own = explore(family_world("strip", 14)[0], spec, check=False, record=False).cost
    found = adversarial_search("basic", 14, 4, evaluations=40, seed=3, restart="strip", baseline=False)
    assert found.best is not None and found.best.cost >= own and found.restart == "strip"
    assert found.to_json()["restart"] == "strip"
    rerun = explore(found.best.world, spec, check=True, record=False)
    assert rerun.claimed == "correct" and rerun.cost == found.best.cost


@pytest.mark.skipif(not available() and not os.environ.get("CI"),
                    reason="numba is not installed: the compiled engine cannot run")
@pytest.mark.parametrize("algorithm", ["basic", "case-1a", "case-4"])
def test_the_engine_scores_candidates_as_the_reference_does(algorithm):
    """Every algorithm the engine runs is scored by its own compiled search, never by another's (a footprint
    search scored as Algorithm 3.1 would rank worlds by the wrong costs)."""
    rng = random.Random(4)
    fast = _problem(algorithm, 12, 4, "ratio", 10, 0, None, None, None, "strip", "compiled")
    slow = _problem(algorithm, 12, 4, "ratio", 10, 0, None, None, None, "strip", "reference")
    assert fast.engine and not slow.engine
    for _ in range(12):
        cand = fast.move(fast.draw(rng), rng)
        assert fast.run(cand) == slow.run(cand)


def test_the_report_names_each_found_world_by_its_generator_text_and_fits_only_over_five_sizes(tmp_path, capsys):
    from topomark.reference.cli.main import main
    five, three = tmp_path / "five", tmp_path / "three"
    for out, sizes in ((five, ["8", "9", "10", "11", "12"]), (three, ["14", "16", "18"])):
        assert main(["worst-case", "--search", "--vertices", *sizes, "--evaluations", "1", "--restart-family",
                     "strip", "--quiet", "-o", str(out)]) == 0  # one run: the family's own world
    capsys.readouterr()
    assert main(["worst-case", "--summarise", str(five)]) == 0
    text = capsys.readouterr().out
    row = next(line for line in text.splitlines() if line.startswith("| basic | strip | 9 |"))
    assert "`strip:n=9,cap=0`" in row and "`strip:n=8,cap=1`" in text
    assert "95 % CI" in text and "over 5 sizes" in text and "--restart-family strip" in text
    assert main(["worst-case", "--summarise", str(three)]) == 0
    assert "no fit (3 sizes; a growth fit needs at least 5)" in capsys.readouterr().out


def test_the_growth_fit_takes_one_world_per_size_however_often_a_size_was_searched(tmp_path, capsys):
    """A size searched by two runs is one point of the fit (the better world there), and the report counts sizes,
    not runs: fitting every run's world would weigh the sizes searched most and count them more than once."""
    from topomark.reference.cli.main import main
    once, again = tmp_path / "once", tmp_path / "again"
    for out, seed in ((once, "0"), (again, "1")):
        assert main(["worst-case", "--search", "--vertices", "8", "9", "10", "11", "12", "--evaluations", "1",
                     "--restart-family", "strip", "--seed", seed, "--quiet", "-o", str(out)]) == 0
    capsys.readouterr()
    assert main(["worst-case", "--summarise", str(once)]) == 0
    alone = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("- basic: cost ∝"))
    assert main(["worst-case", "--summarise", str(once), str(again)]) == 0
    both = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("- basic: cost ∝"))
    assert "over 5 sizes" in both and both == alone  # the same worlds at each size: the same fit


def _searched(algorithm, ratios):
    return [{"algorithm": algorithm, "max_degree": 4, "family": None, "per_n": [
        {"n": n, "search": {"best": {"cost": 10 * n, "ratio_to_bound": q}}} for n, q in zip((20, 50, 100), ratios)]}]


def test_the_verdict_says_the_bound_is_tight_only_where_the_ratio_does_not_fall():
    from topomark.reference.worstcase.verdicts import CIRCULANT_PROOF, STRIP_SAYS, verdicts
    rising = verdicts([], _searched("case-2", [0.1, 0.12, 0.12]), {("case-2", 50): "strip:n=50,cap=1"})[0]
    assert rising.startswith("- `case-2`: Shown") and "n = 50: 0.1200 (`strip:n=50,cap=1`)" in rising
    assert "does not fall with n on worlds of maximum degree 4" in rising
    falling = verdicts([], _searched("case-2", [0.1, 0.12, 0.11]))[0]
    assert "falls somewhere over the sizes searched" in falling and "does not fall" not in falling
    basic = verdicts([], _searched("basic", [0.1, 0.12, 0.11]))[0]  # basic rests on the strip's exact formula
    assert STRIP_SAYS[1:] in basic and "23/24·n³" in basic
    assert basic.startswith("- `basic`: " + CIRCULANT_PROOF[0].upper() + CIRCULANT_PROOF[1:])  # proved at every n
    assert CIRCULANT_PROOF not in rising  # only basic's bound is proved


def test_the_verdict_shows_each_sizes_largest_ratio_and_names_that_world():
    """Two runs at n = 50, the costlier world given the lower cost / bound. The verdict shows the larger
    ratio and the report names its world, so figure and world are one world, as on the families page."""
    from topomark.reference.worstcase.summary import _names
    from topomark.reference.worstcase.verdicts import best_per_size, verdicts
    from topomark.spec.worldfile import world_to_json
    from topomark.reference.worlds.argument import resolve_world
    lower, higher = (world_to_json(resolve_world(f"worst-case:case={name}"))
                     for name in ("case-2-n50-d4-search", "case-2-n50-d4-search-3"))
    runs = [{"algorithm": "case-2", "max_degree": 4, "family": None, "per_n": [
        {"n": 50, "search": {"best": {"cost": cost, "ratio_to_bound": q, "world": w}}}]}
        for cost, q, w in ((1000, 0.10, lower), (900, 0.12, higher))]
    assert best_per_size(runs)[("case-2", 50)]["cost"] == 900
    assert _names(runs) == {("case-2", 50): "worst-case:case=case-2-n50-d4-search-3"}
    line = verdicts([], runs, _names(runs))[0]
    assert "n = 50: 0.1200 (`worst-case:case=case-2-n50-d4-search-3`)" in line and "0.1000" not in line


def test_the_verdict_names_each_algorithms_own_bound_and_family_formula():
    from topomark.reference.worstcase.verdicts import SPLIT_SAYS, verdicts
    assert "the O(m²n) bound" in verdicts([], _searched("enh2", [0.1, 0.09, 0.08]))[0]
    falling = verdicts([], _searched("case-2", [0.1, 0.09, 0.08]))[0]
    assert "the O(mn) bound tight" in falling and "O(m²n)" not in falling
    for algorithm in ("case-1a", "case-4"):  # these rest on the split strip's exact formula
        line = verdicts([], _searched(algorithm, [0.1, 0.09, 0.08]))[0]
        assert SPLIT_SAYS[1:] in line and "(5n² − 31n + c)/4" in line and "falls somewhere" not in line


def test_a_world_kept_for_two_algorithms_is_named_for_the_one_asked_and_a_command_keeps_its_objective(tmp_path,
                                                                                                       capsys):
    from topomark.reference.cli.main import main
    from topomark.reference.worlds.worst_cases import worst_case_world
    from topomark.reference.worstcase.naming import generator_text
    world = worst_case_world("case-4-n50-d4-split-search")  # the search for Case 1a found the same world
    assert generator_text(world, "case-4") == "worst-case:case=case-4-n50-d4-split-search"
    assert generator_text(world, "case-1a") == "worst-case:case=case-1a-n50-d4-split-search"
    out = tmp_path / "run"
    assert main(["worst-case", "--search", "--algorithm", "case-4", "--vertices", "12", "--evaluations", "2",
                 "--objective", "ratio", "--seed", "3", "--restart-family", "strip", "--quiet", "-o", str(out)]) == 0
    capsys.readouterr()
    assert main(["worst-case", "--summarise", str(out)]) == 0
    assert ("topomark worst-case --search --algorithm case-4 --restart-family strip --objective ratio --seed 3 "
            "--vertices 12 --evaluations 2 --max-degree 4") in capsys.readouterr().out


def test_a_search_goes_on_from_one_world_and_its_command_says_so(tmp_path, capsys):
    """``--restart-world`` starts from one world (here a kept worst world): the search can only gain on it, the
    stored run names it, and the summary's command repeats it with ``--restart-world``."""
    from topomark.reference.cli.main import main
    from topomark.reference.worlds.worst_cases import worst_case_world
    text = "worst-case:case=basic-n20-d4-search"
    own = explore(worst_case_world("basic-n20-d4-search"), "basic", check=False, record=False).cost
    found = adversarial_search("basic", 20, 4, evaluations=12, seed=1, restart=text, baseline=False)
    assert found.best is not None and found.best.cost >= own and found.to_json()["restart"] == text
    out = tmp_path / "run"
    assert main(["worst-case", "--search", "--algorithm", "basic", "--restart-world", text, "--vertices", "20",
                 "--evaluations", "2", "--quiet", "-o", str(out)]) == 0
    capsys.readouterr()
    assert main(["worst-case", "--summarise", str(out)]) == 0
    assert (f"topomark worst-case --search --algorithm basic --restart-world {text} --vertices 20 --evaluations 2 "
            "--max-degree 4") in capsys.readouterr().out


@pytest.mark.parametrize("argv,message", [
    (["--vertices", "30"], "has 20 places, not 30: search it at --vertices 20"),
    (["--vertices", "20", "--restart-family", "strip"], "--restart-family and --restart-world both"),
    (["--vertices", "20", "--max-degree", "3"], "has places of degree 4: max_degree must be >= 4, got 3")])
def test_a_restart_world_of_another_size_or_degree_or_beside_a_family_is_bad_input(argv, message, capsys):
    from topomark.reference.cli.main import main
    assert main(["worst-case", "--search", "--algorithm", "basic", "--restart-world",
                 "worst-case:case=basic-n20-d4-search", "--evaluations", "2", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


@pytest.mark.parametrize("argv", [["--search", "--vertices", "8", "--evaluations", "2"], ["--max-vertices", "4"]])
def test_under_json_progress_still_goes_to_stderr_unless_quiet(argv, capsys):
    """A long ``--json`` run is not silent: stdout holds the one JSON object, progress goes to stderr, and only
    ``--quiet`` stops it."""
    import json
    from topomark.reference.cli.main import main
    for quiet in (False, True):
        assert main(["worst-case", "--algorithm", "basic", "--max-degree", "3", "--json", *argv,
                     *(["--quiet"] if quiet else [])]) == 0
        out, err = capsys.readouterr()
        assert json.loads(out)["algorithm"] == "basic"
        assert (err == "") == quiet, err


def test_a_restart_world_searches_at_its_own_size_unless_told(capsys):
    import json
    from topomark.reference.cli.main import main
    assert main(["worst-case", "--search", "--algorithm", "basic", "--restart-world",
                 "worst-case:case=basic-n30-d4-search", "--evaluations", "1", "--quiet", "--json"]) == 0
    assert [r["n"] for r in json.loads(capsys.readouterr().out)["per_n"]] == [30]
    assert main(["worst-case", "--search", "--algorithm", "basic", "--evaluations", "1", "--quiet", "--json"]) == 0
    assert [r["n"] for r in json.loads(capsys.readouterr().out)["per_n"]] == [20]


def test_a_restart_world_file_without_a_start_starts_at_its_first_place(tmp_path):
    import json
    from topomark.reference.worstcase.structural import restart_world
    from topomark.spec.world import Start
    from topomark.spec.worldfile import world_to_json
    w = strip(8)
    path = tmp_path / "w.json"
    path.write_text(json.dumps(world_to_json(w.with_start(None))))
    got = restart_world(str(path), 8)
    assert got.rotation == w.rotation and got.start == Start(w.vertices[0], w.rotation[w.vertices[0]][0])
    assert restart_world("strip", 8).rotation == family_world("strip", 8)[0].rotation

"""Tests of topomark.proofs.census (languages of placements, §3.2, §3.3, §3.7, §6.1) and ``topomark census``."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.proofs.bisim import indistinguishable, is_counterexample
from topomark.proofs.census import census, language_code, machine, minimise, placement
from topomark.proofs.enumerate import count_by_size, embedded_worlds
from topomark.proofs.figures import figure_3_4, figure_3_21a, figure_6_1a
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.reference.cli.main import main
from topomark.reference.worlds.strategies import worlds
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.world import Start, World

FAST = settings(max_examples=60, deadline=None)


def code_of(world: World) -> tuple:
    mach = machine(world.with_start(None))
    return language_code(mach, minimise(mach), mach.index[world.start_state()])


def brute_force_census(class_name: str, max_vertices: int, max_degree: int) -> tuple[int, int]:
    """(languages, ambiguous languages) by pairwise bisimulation and find_isomorphism."""
    classes: list[list[World]] = []
    for w in embedded_worlds(max_vertices, max_degree):
        for p in MARKER_CLASSES[class_name].placements(w):
            for members in classes:
                if indistinguishable(members[0], p):
                    members.append(p)
                    break
            else:
                classes.append([p])
    ambiguous = 0
    for members in classes:
        if any(not find_isomorphism(members[0], q, markers=True).isomorphic for q in members[1:]):
            ambiguous += 1
        # all members pairwise indistinguishable (transitivity sanity check)
        assert all(indistinguishable(members[-1], q) for q in members)
    return len(classes), ambiguous


# -- the machine ----------------------------------------------------------------------
@FAST
@given(worlds(2, 6, max_degree=4, markers="any"), st.data())
def test_minimisation_agrees_with_bisimulation(world, data):
    darts = list(world.darts())
    s1 = data.draw(st.sampled_from(darts))
    s2 = data.draw(st.sampled_from(darts))
    mach = machine(world)
    block = minimise(mach)

    def started(s):
        return world.with_start(Start(s[0], world.neighbour(*s)))

    same = indistinguishable(started(s1), started(s2))
    assert (block[mach.index[s1]] == block[mach.index[s2]]) == same
    assert (code_of(started(s1)) == code_of(started(s2))) == same


@FAST
@given(worlds(2, 5, max_degree=3, markers="undirected-vertex", with_start=True),
       worlds(2, 5, max_degree=3, markers="undirected-vertex", with_start=True))
def test_language_code_equal_iff_indistinguishable_across_worlds(a, b):
    assert (code_of(a) == code_of(b)) == indistinguishable(a, b)


def test_figure_pairs_share_a_language():
    a, b = figure_3_4()
    assert code_of(a) == code_of(b)


# -- the census -------------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("class_name", ["none", "undirected-vertex", "directional-vertex", "undirected-edge"])
def test_census_matches_brute_force(class_name):
    result = census(class_name, 4, 3)
    assert (result.languages, result.ambiguous) == brute_force_census(class_name, 4, 3)


def test_rows_count_worlds_and_placements():
    result = census("directional-edge", 5, 3)
    assert {r.n: r.worlds for r in result.rows} == count_by_size(5, 3)
    for r in result.rows:
        assert r.placements == sum(len(list(MARKER_CLASSES["directional-edge"].placements(w)))
                                   for w in embedded_worlds(r.n, 3, min_vertices=r.n))
        assert r.languages <= min(r.placements, r.languages_upto)


@pytest.mark.parametrize("class_name,n", [("none", 5), ("undirected-vertex", 5), ("two-undirected-vertex", 6),
                                          ("undirected-edge", 6)])
def test_every_ambiguous_class_is_rechecked(class_name, n):
    result = census(class_name, n, 3, verify_all=True)  # raises CheckFailure if a pair fails the re-check
    assert result.ambiguous > 0 and is_counterexample(*result.smallest_counterexample)


@pytest.mark.parametrize("class_name,figure", [("two-undirected-vertex", figure_3_21a), ("undirected-edge", figure_6_1a)])
def test_smallest_counterexample_has_six_vertices(class_name, figure):
    """Figures 3.21(a) and 6.1(a): none below 6 vertices; at 6 a pair with 7 edges, smaller than the prisms."""
    assert census(class_name, 5, 3).smallest_counterexample is None
    a, b = census(class_name, 6, 3).smallest_counterexample
    assert (a.n, a.m, b.n, b.m) == (6, 7, 6, 7)
    assert is_counterexample(a, b)
    assert code_of(figure()[0]) == code_of(figure()[1])  # the prism pair (m = 9) is ambiguous too


def test_degree_four_gives_a_five_vertex_edge_marker_counterexample():
    a, b = census("undirected-edge", 5, 4).smallest_counterexample
    assert (a.n, a.m, b.n, b.m) == (5, 7, 5, 7) and {a.genus(), b.genus()} == {0, 1}
    assert is_counterexample(a, b)
    da, db = (w.with_markers([m.__class__(m.between, 1, w.start.at) for m in w.markers], w.start) for w in (a, b))
    assert not is_counterexample(da, db)  # directing the marker (head at the start) breaks the tie


def test_directional_vertex_has_no_counterexample():
    result = census("directional-vertex", 5, 3)
    assert result.smallest_counterexample is None and result.ambiguous == 0


def test_none_counterexample_is_c3_vs_c4():
    result = census("none", 5, 3)
    a, b = result.smallest_counterexample
    assert sorted((a.n, b.n)) == [3, 4] and all(w.degree(v) == 2 for w in (a, b) for v in w.vertices)
    assert is_counterexample(a, b)
    assert [r.ambiguous_upto for r in result.rows] == [0, 0, 2, 4]


def test_undirected_vertex_smallest_counterexample_is_k4():
    """Smaller than Figure 3.4's wheel W4 (5 vertices): the wheel W3 = K4, planar vs twisted."""
    result = census("undirected-vertex", 5, 3)
    a, b = result.smallest_counterexample
    assert (a.n, a.m, b.n, b.m) == (4, 6, 4, 6)
    assert {a.genus(), b.genus()} == {0, 1}
    assert is_counterexample(a, b)
    assert [r.ambiguous_upto for r in result.rows] == [0, 0, 1, 2]
    assert census("undirected-vertex", 3, 3).smallest_counterexample is None


def test_result_does_not_depend_on_jobs():
    one = census("undirected-vertex", 5, 3, jobs=1)
    two = census("undirected-vertex", 5, 3, jobs=2, chunk_size=7)
    assert one == two


def test_placement_reconstruction():
    w = next(iter(embedded_worlds(3, 2, min_vertices=3)))
    assert placement(w, "none", 0) == next(MARKER_CLASSES["none"].placements(w))


# -- CLI -----------------------------------------------------------------------------
def test_cli_census_json(capsys):
    assert main(["census", "--marker", "undirected-vertex", "--max-vertices", "4", "--max-degree", "3",
                 "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert [row["n"] for row in data["rows"]] == [2, 3, 4]
    assert data["ambiguous"] == 1 and len(data["smallest_counterexample"]) == 2
    assert all(w["format"] == "topomark/world@1" for w in data["smallest_counterexample"])
    assert main(["census", "--marker", "directional-vertex", "--max-vertices", "4", "--max-degree", "3",
                 "--json", "--jobs", "2"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["smallest_counterexample"] is None


def test_cli_census_text(capsys):
    assert main(["census", "--marker", "none", "--max-vertices", "4", "--max-degree", "2"]) == 1
    captured = capsys.readouterr()
    assert "smallest counterexample" in captured.out and "census:" in captured.err


@pytest.mark.parametrize("argv", [
    ["--marker", "nope", "--max-vertices", "4", "--max-degree", "3"],
    ["--marker", "none", "--max-vertices", "1", "--max-degree", "3"],
    ["--marker", "none", "--max-vertices", "11", "--max-degree", "3"],
    ["--marker", "none", "--max-vertices", "4", "--max-degree", "0"],
    ["--marker", "none", "--max-vertices", "4", "--max-degree", "3", "--jobs", "0"],
    ["--marker", "none", "--max-vertices", "four", "--max-degree", "3"],
    ["--max-vertices", "4", "--max-degree", "3"],
])
def test_cli_census_rejects_bad_options(argv, capsys):
    assert main(["census", *argv]) == 2
    assert capsys.readouterr().err.startswith("topomark: error:")


@pytest.mark.parametrize("class_name", sorted(MARKER_CLASSES))
def test_layouts_enumerate_exactly_the_placements(class_name):
    from topomark.proofs.census import marker_layouts

    for w in embedded_worlds(4, 3):
        ours = [World(w.rotation, markers, Start(v, w.neighbour(v, i)))
                for _, markers, starts in marker_layouts(class_name, w) for v, i in starts]
        assert ours == list(MARKER_CLASSES[class_name].placements(w))
        assert [k for k, _, _ in marker_layouts(class_name, w)] == [
            sum(len(s) for _, _, s in list(marker_layouts(class_name, w))[:j])
            for j in range(len(list(marker_layouts(class_name, w))))]

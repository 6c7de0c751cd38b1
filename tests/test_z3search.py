"""Tests of topomark.proofs.z3search, drawing and the ``search`` command (thesis §3.2, §3.7, §6.1)."""

from __future__ import annotations

import itertools
import json
import xml.etree.ElementTree as ET

import pytest

from topomark.proofs import bisim, z3search
from topomark.proofs.bench_z3 import language_key
from topomark.proofs.drawing import clockwise_ok, layout, pair_svg, save_pair
from topomark.proofs.enumerate import embedded_worlds
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.reference.cli.main import main
from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.robot import perceive
from topomark.spec.world import Start, World


# -- brute force, independent of Z3 -------------------------------------------------------
def brute_force_counterexample(marker: str, max_vertices: int, max_degree: int, planar: bool = False):
    """Some counterexample pair among all placed worlds within the bounds, or None."""
    groups: dict[tuple, list[World]] = {}
    for world in embedded_worlds(max_vertices, max_degree):
        if planar and world.genus() != 0:
            continue
        for placed in MARKER_CLASSES[marker].placements(world):
            groups.setdefault(language_key(placed), []).append(placed)
    for members in groups.values():
        for a, b in itertools.combinations(members, 2):
            if bisim.is_counterexample(a, b):
                return a, b
    return None


# -- search ---------------------------------------------------------------------------------
def test_none_smallest_counterexample_is_two_cycles():
    res = z3search.search("none", 4, 2)
    assert res.outcome == "found" and res.found
    a, b = res.worlds
    assert sorted((a.n, b.n)) == [3, 4]
    assert all(w.degree(v) == 2 for w in (a, b) for v in w.vertices)
    assert bisim.check_relation(a, b, res.relation) is None
    assert bisim.distinguishing_sequence(a, b) is None
    assert not find_isomorphism(a, b).isomorphic
    assert [c.verdict for c in res.checks[:-1]] == ["unsat"] * (len(res.checks) - 1)


def test_undirected_vertex_counterexample_within_figure_3_4_bounds():
    res = z3search.search("undirected-vertex", 5, 4)
    assert res.found
    a, b = res.worlds
    assert max(a.n, b.n) <= 5 and bisim.is_counterexample(a, b)
    assert a.vertex_mark(a.start.at) is not None and b.vertex_mark(b.start.at) is not None
    # the witness walk: same perceptions in both worlds, every state of both worlds entered
    walk = list(res.perceptions)
    assert walk == perceive(a, a.start_state(), res.motions) == perceive(b, b.start_state(), res.motions)
    assert z3search.reachable_relation(a, b) == res.relation


def test_directional_vertex_proved_small_bound():
    rep = z3search.prove("directional-vertex", 4, 3)
    assert rep.outcome == "proved" and rep.proved
    assert rep.bounds["max_vertices"] == 4 and rep.bounds["max_degree"] == 3
    assert rep.solver.startswith("z3 ") and rep.seconds >= 0
    assert all(c.verdict == "unsat" for c in rep.search.checks)
    assert len(rep.search.checks) == len(z3search.size_pairs(4))


@pytest.mark.parametrize("marker", ["directional-edge", "vertex-and-edge", "three-undirected-vertex"])
def test_other_sufficient_classes_proved_tiny_bound(marker):
    assert z3search.prove(marker, 4, 3).proved


def test_unknown_on_tiny_timeout_is_not_none():
    res = z3search.search("directional-vertex", 6, 4, timeout=0.05)
    assert res.outcome == "unknown" and not res.found
    assert res.outcome != "none"
    rep = z3search.prove("directional-vertex", 6, 4, timeout=0.05)
    assert rep.outcome == "unknown" and not rep.proved


def test_invalid_arguments():
    with pytest.raises(InvalidInput, match="unknown marker class"):
        z3search.search("nope", 4, 3)
    with pytest.raises(InvalidInput, match="at least|>= 2"):
        z3search.search("none", 1, 3)
    with pytest.raises(InvalidInput, match="too large"):
        z3search.search("none", 9, 3)
    with pytest.raises(InvalidInput, match=">= 1"):
        z3search.search("none", 4, 0)


def test_recheck_rejects_bad_models():
    res = z3search.search("none", 4, 2)
    a, b = res.worlds
    with pytest.raises(CheckFailure, match="isomorphic"):
        z3search.recheck("none", a, a, z3search.reachable_relation(a, a))
    with pytest.raises(CheckFailure, match="bisimulation"):
        z3search.recheck("none", a, b, frozenset(list(res.relation)[1:]) - {(a.start_state(), b.start_state())})
    with pytest.raises(CheckFailure, match="markers"):
        z3search.recheck("undirected-vertex", a, b, res.relation)


def test_size_pairs_order():
    assert z3search.size_pairs(3) == [(2, 2), (2, 3), (3, 3)]
    assert z3search.size_pairs(4, 3) == [(3, 3), (3, 4), (4, 4)]


# -- Z3 agrees with brute force on tiny bounds -------------------------------------------------
def brute_force_smallest(marker: str, max_vertices: int, max_degree: int, planar: bool = False):
    """The smallest n (size of the larger world) with a counterexample, and a pair; (None, None) if none."""
    for n in range(2, max_vertices + 1):
        pair = brute_force_counterexample(marker, n, max_degree, planar)
        if pair is not None:
            return n, pair
    return None, None


@pytest.mark.slow
@pytest.mark.parametrize("marker,n,d", [
    ("none", 4, 2), ("none", 4, 3), ("undirected-vertex", 4, 3), ("undirected-vertex", 3, 3),
    ("directional-vertex", 4, 3), ("two-undirected-vertex", 4, 3), ("undirected-edge", 4, 3),
    ("three-undirected-vertex", 4, 3), ("directional-edge", 4, 3), ("vertex-and-edge", 4, 3),
])
def test_z3_agrees_with_brute_force(marker, n, d):
    smallest, pair = brute_force_smallest(marker, n, d)
    res = z3search.search(marker, n, d)
    assert res.outcome in ("found", "none")
    assert res.found == (pair is not None), (marker, n, d, pair)
    if pair is not None:  # Z3 tries sizes in order, so its pair is as small as the smallest one
        a, b = res.worlds
        assert max(a.n, b.n) == smallest
        assert bisim.is_counterexample(*pair)


def _count_encodings(n: int, d: int, marker: str, planar: bool = False) -> int:
    """Number of models of the single-world encoding (projected on the world's variables)."""
    import z3

    b = z3search.Builder()
    w = z3search.WorldVars(b, "A", n, d, marker, planar)
    solver = z3.SolverFor("QF_FD")
    solver.from_string(b.text())
    onehots = list(w.tv.values()) + list(w.te.values()) + ([w.e] if w.e else [])
    keys = [z3.Bool(lit) for oh in onehots for lit in oh.values() if not isinstance(lit, bool)]
    keys += [z3.Bool(w.head0)] if w.head0 else []
    count = 0
    while solver.check() == z3.sat:
        model = solver.model()
        count += 1
        solver.add(z3.Or([k != model.eval(k, model_completion=True) for k in keys]))
    return count


@pytest.mark.parametrize("marker,n,d", [("none", 4, 3), ("directional-vertex", 4, 3), ("directional-edge", 4, 3),
                                        ("two-undirected-vertex", 3, 2)])
def test_symmetry_breaking_is_exact(marker, n, d):
    """One encoding per placed world up to start-preserving isomorphism: sound and complete symmetry breaking."""
    from topomark.spec.isomorphism import anchored

    classes = []
    for world in embedded_worlds(n, d, min_vertices=n):
        reps: list[World] = []
        for p in MARKER_CLASSES[marker].placements(world):
            if not any(anchored(p, q, p.start_state(), q.start_state()).isomorphic for q in reps):
                reps.append(p)
        classes += reps
    assert _count_encodings(n, d, marker) == len(classes)


@pytest.mark.parametrize("n,d", [(4, 3), (5, 3)])
def test_planarity_constraint_is_exact(n, d):
    """With planar=True the encodings are exactly the genus-0 worlds with a start."""
    from topomark.spec.isomorphism import anchored

    count = 0
    for world in embedded_worlds(n, d, min_vertices=n):
        if world.genus() != 0:
            continue
        reps: list[World] = []
        for p in MARKER_CLASSES["none"].placements(world):
            if not any(anchored(p, q, p.start_state(), q.start_state()).isomorphic for q in reps):
                reps.append(p)
        count += len(reps)
    assert _count_encodings(n, d, "none", planar=True) == count


@pytest.mark.slow
@pytest.mark.parametrize("marker,n,d", [("none", 4, 3), ("undirected-vertex", 4, 3), ("directional-vertex", 3, 3)])
def test_planar_search_agrees_with_brute_force(marker, n, d):
    smallest, pair = brute_force_smallest(marker, n, d, planar=True)
    res = z3search.search(marker, n, d, planar=True)
    assert res.outcome in ("found", "none") and res.found == (pair is not None)
    if res.found:
        assert all(w.genus() == 0 for w in res.worlds) and max(w.n for w in res.worlds) == smallest


# -- the encoding on the thesis's figure pairs (sizes beyond the brute force) ---------------------
@pytest.mark.slow
@pytest.mark.parametrize("figure,marker,counterexample", [
    ("3.3", "none", True), ("3.4", "undirected-vertex", True), ("3.6", "directional-vertex", False),
    ("3.21a", "two-undirected-vertex", True), ("3.21b", "three-undirected-vertex", False),
    ("6.1a", "undirected-edge", True), ("6.1b", "directional-edge", False),
])
def test_encoding_accepts_exactly_the_thesis_counterexamples(figure, marker, counterexample):
    from topomark.proofs.figures import FIGURES

    a, b = FIGURES[figure]()[:2]
    assert bisim.is_counterexample(a, b) == counterexample
    assert z3search.pair_is_model(marker, a, b) == ("sat" if counterexample else "unsat")
    if counterexample:
        assert z3search.pair_is_model(marker, b, b) == "unsat"  # isomorphic: never a counterexample


@pytest.mark.slow
@pytest.mark.parametrize("marker", ["none", "undirected-vertex", "two-undirected-vertex", "undirected-edge",
                                    "directional-vertex"])
def test_pinned_pairs_match_the_specification(marker):
    """For sampled pairs, the formula holds exactly for the counterexamples (is_counterexample)."""
    import random

    rng = random.Random(2014)
    groups: dict[tuple, list[World]] = {}
    for world in embedded_worlds(4, 3):
        for placed in MARKER_CLASSES[marker].placements(world):
            groups.setdefault(language_key(placed), []).append(placed)
    bisimilar = [g for g in groups.values() if len(g) > 1]
    everyone = [w for g in groups.values() for w in g]
    counter = [(a, b) for g in bisimilar for a, b in itertools.combinations(g, 2) if bisim.is_counterexample(a, b)]
    pairs = counter[:2] + [tuple(rng.sample(rng.choice(bisimilar), 2)) for _ in range(4)]
    pairs += [tuple(rng.sample(everyone, 2)) for _ in range(3)]
    assert bool(counter) == (marker in ("none", "undirected-vertex"))  # at N <= 4, D <= 3
    for a, b in pairs:
        expected = "sat" if bisim.is_counterexample(a, b) else "unsat"
        assert z3search.pair_is_model(marker, a, b) == expected, (a.rotation, a.markers, b.rotation, b.markers)


def test_canonical_labelling_is_bfs():
    from topomark.proofs.figures import figure_3_4

    a, _ = figure_3_4()
    order, shift = z3search.canonical_labelling(a)
    assert order[a.start.at] == 0 and shift[a.start.at] == a.start_state()[1]
    assert sorted(order.values()) == list(range(a.n))


# -- drawing ------------------------------------------------------------------------------------------
def test_drawing_pair_svg_is_wellformed(tmp_path):
    res = z3search.search("undirected-vertex", 4, 3)
    a, b = res.worlds
    path = save_pair(a, b, tmp_path / "pair.svg", caption="M = (0,1)")
    root = ET.parse(path).getroot()
    circles = root.findall("{http://www.w3.org/2000/svg}circle")
    assert len(circles) >= a.n + b.n
    with pytest.raises(InvalidInput, match="svg"):
        save_pair(a, b, tmp_path / "pair.gif")


def test_every_small_planar_world_is_drawn_faithfully():
    planar = [w for w in embedded_worlds(5, 4) if w.genus() == 0]
    assert planar and all(layout(w)[1] for w in planar)


def test_drawing_planar_layout_is_clockwise():
    wheel = World({"c": ["a", "b", "d", "e"], "a": ["c", "e", "b"], "b": ["c", "a", "d"], "d": ["c", "b", "e"],
                   "e": ["c", "d", "a"]}, start=Start("c", "a"))
    assert wheel.genus() == 0
    pos, faithful = layout(wheel)
    assert faithful and clockwise_ok(wheel, pos)
    assert pair_svg(wheel, wheel).count("<circle") >= 10


# -- CLI ------------------------------------------------------------------------------------------------
def test_cli_found_writes_outputs(tmp_path, capsys):
    out = tmp_path / "o"
    rc = main(["search", "--marker", "none", "--max-vertices", "4", "--max-degree", "2", "--out", str(out), "--json"])
    assert rc == 0
    data = json.loads(capsys.readouterr().out)
    assert data["outcome"] == "found" and data["found"] is True
    assert {"worlds", "relation", "motions", "perceptions"} <= set(data)
    assert len(data["worlds"]) == 2 and data["worlds"][0]["format"] == "topomark/world@1"
    assert sorted(p.name for p in out.iterdir()) == ["a.json", "b.json", "pair.svg", "relation.json"]


def test_cli_text_found(capsys):
    assert main(["search", "--marker", "none", "--max-vertices", "4", "--max-degree", "2"]) == 0
    text = capsys.readouterr().out
    assert "counterexample found" in text and "P = ([2,A,A]" in text


def test_cli_none_exit_1(capsys):
    rc = main(["search", "--marker", "directional-vertex", "--max-vertices", "3", "--max-degree", "3", "--json"])
    assert rc == 1
    data = json.loads(capsys.readouterr().out)
    assert data["outcome"] == "none" and data["found"] is False


def test_cli_prove(capsys):
    rc = main(["search", "--marker", "directional-vertex", "--max-vertices", "3", "--max-degree", "3", "--prove",
               "--json"])
    assert rc == 0
    data = json.loads(capsys.readouterr().out)
    assert data["outcome"] == "none" and data["proof"] == "proved"
    assert {"bounds", "symmetry_breaking", "solver", "seconds"} <= set(data)
    rc = main(["search", "--marker", "none", "--max-vertices", "4", "--max-degree", "2", "--prove"])
    assert rc == 1 and "counterexample" in capsys.readouterr().out


def test_cli_unknown(capsys):
    rc = main(["search", "--marker", "directional-vertex", "--max-vertices", "6", "--max-degree", "4",
               "--timeout", "0.05", "--json"])
    assert rc == 1
    assert json.loads(capsys.readouterr().out)["outcome"] == "unknown"
    rc = main(["search", "--marker", "directional-vertex", "--max-vertices", "6", "--max-degree", "4",
               "--timeout", "0.05"])
    assert rc == 1 and "unknown (timeout)" in capsys.readouterr().out


@pytest.mark.parametrize("argv,message", [
    (["--marker", "bogus", "--max-vertices", "4", "--max-degree", "3"], "unknown marker class"),
    (["--marker", "none", "--max-vertices", "1", "--max-degree", "3"], "at least 2"),
    (["--marker", "none", "--max-vertices", "9", "--max-degree", "3"], "too large"),
    (["--marker", "none", "--max-vertices", "4", "--max-degree", "0"], "at least 1"),
    (["--marker", "none", "--max-vertices", "4", "--max-degree", "3", "--timeout", "-1"], "positive"),
    (["--marker", "none", "--max-vertices", "x", "--max-degree", "3"], "invalid int"),
    (["--max-vertices", "4", "--max-degree", "3"], "required"),
])
def test_cli_bad_options_exit_2(argv, message, capsys):
    assert main(["search"] + argv) == 2
    assert message in capsys.readouterr().err

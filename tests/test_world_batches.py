"""Tests of the fast enumeration: topomark.proofs.orbit_kernel and topomark.proofs.world_batches (§3.1.1, §3.1.3).

The batches must be :func:`embedded_worlds`'s worlds in its order (checked
against it for a slice of graphs here and every graph with n <= 7 in a slow
test, cut into shards that the workers share), with each world's exact stabiliser; the compiled kernel and the plain
one must give the same output; at n = 8, max degree 4 the count per graph is
Burnside's (slow test).
"""

from __future__ import annotations

import math
import os

import numpy as np
import pytest

from topomark.proofs import orbit_kernel
from topomark.proofs.burnside import worlds_on
from topomark.proofs.census_map import unit_arrays, unit_worlds
from topomark.proofs.enumerate import (_image, _orbit_representatives, embedded_worlds, graph_automorphisms,
                                       rotation_systems, world_of_rotation)
from topomark.proofs.graphs import automorphisms, classes
from topomark.proofs.orbit_kernel import compiled, representatives, scan
from topomark.proofs.world_arrays import back_links, from_arrays, to_arrays
from topomark.proofs.world_batches import (_tables, embedded_batches, graph_batches, graph_data, graphs_of)
from topomark.spec.errors import InvalidInput

PLAIN = (scan, False)


def _rows(n: int, d: int, gi: int, **kw) -> list[tuple[int, list[int], list[int], list[int]]]:
    return [(int(b.ranks[i]), b.nbr[i].tolist(), b.back[i].tolist(), b.stabiliser(i).tolist())
            for b in graph_batches(n, d, gi, **kw) for i in range(len(b))]


def _check_graph(n: int, d: int, gi: int) -> int:
    """Batches of graph gi == enumerate's representatives (arrays, order) with their exact stabilisers."""
    choices, _, actions = graph_data(n, d, gi)
    expected = list(_orbit_representatives(graphs_of(n, d)[gi]))
    got = [(b, i) for b in graph_batches(n, d, gi) for i in range(len(b))]
    assert len(got) == len(expected), (n, d, gi)
    for rot, (b, i) in zip(expected, got):
        want = to_arrays(world_of_rotation(rot))
        assert np.array_equal(b.offsets, want.offsets) and b.nbr[i].tolist() == want.nbr.tolist()
        assert b.back[i].tolist() == want.back.tolist()
        assert tuple(choices[v][x] for v, x in enumerate(b.digits[i].tolist())) == rot
        fixing = [a for a, (sigma, _) in enumerate(actions) if _image(rot, sigma) == rot]
        assert b.stabiliser(i).tolist() == fixing
    return len(got)


@pytest.mark.parametrize("n,d", [(2, 1), (3, 2), (4, 3), (5, 4), (6, 3)])
def test_batches_are_the_enumerations_worlds_with_their_stabilisers(n, d):
    assert sum(_check_graph(n, d, gi) for gi in range(len(graphs_of(n, d)))) == sum(
        1 for _ in embedded_worlds(n, d, min_vertices=n))


def test_a_slice_of_seven_vertex_graphs():
    """At n = 7, max degree 4, among graphs with at most 2,000 rotation systems: every 30th, and the three
    with the largest automorphism groups."""
    gs = graphs_of(7, 4)
    small = [gi for gi, g in enumerate(gs) if math.prod(math.factorial(x - 1) for _, x in g.degree()) <= 2000]
    symmetric = sorted(small, key=lambda gi: -len(automorphisms(gs[gi])))[:3]
    assert len(graph_data(7, 4, symmetric[0])[2]) >= 12
    for gi in sorted(set(small[::30]) | set(symmetric)):
        _check_graph(7, 4, gi)


SHARDS = 4
"""The slow exhaustive checks are cut into this many shards of graph indices, so that pytest-xdist's workers
share them rather than one worker running them all at the end of the suite; together the shards cover every
graph."""


def test_every_max_degree_three_graph_is_one_of_the_max_degree_four_graphs():
    """So checking every graph of max degree <= 4 (below) checks every graph of max degree <= 3 too: a graph's
    batches depend on the graph (its labelling included), not on the bound it was listed under."""
    for n in range(2, 8):
        four = [sorted(g.edges) for g in graphs_of(n, 4)]
        assert all(sorted(g.edges) in four for g in graphs_of(n, 3)), n


@pytest.mark.slow
@pytest.mark.parametrize("shard", range(SHARDS))
def test_every_graph_up_to_seven_vertices(shard):
    """Every graph with n <= 7, max degree <= 4 (so every one of max degree <= 3 too): those whose index is
    ``shard`` modulo :data:`SHARDS`."""
    for n in range(2, 8):
        for gi in range(shard, len(graphs_of(n, 4)), SHARDS):
            _check_graph(n, 4, gi)


def test_embedded_batches_follow_embedded_worlds_across_sizes():
    flat = [from_arrays(b.offsets, b.nbr[i]) for b in embedded_batches(5, 3) for i in range(len(b))]
    assert flat == list(embedded_worlds(5, 3))
    with pytest.raises(InvalidInput):
        next(embedded_batches(11, 3))
    with pytest.raises(InvalidInput):
        next(embedded_batches(5, 0))


# -- the kernel: compiled = plain, chunks and residues ---------------------------------------
def _kernel_output(n: int, d: int, gi: int, use, chunk: int, start: int = 0, step: int = 1) -> list[list[int]]:
    t = _tables(n, d, gi)
    out: list[list[int]] = [[], [], []]
    for ranks, offsets, stab in representatives(*t.kernel, start=start, step=step, stop=t.total, chunk=chunk, use=use):
        out[0] += ranks.tolist()
        out[1] += np.diff(offsets).tolist()
        out[2] += stab.tolist()
    return out


SLICE = [(4, 3, 5), (5, 4, 20), (6, 4, 77), (6, 3, 28)]  # the last graph of each list: K4, K5, the octahedron, K_{3,3}


@pytest.mark.parametrize("n,d,gi", SLICE)
def test_plain_kernel_is_chunk_and_residue_independent(n, d, gi):
    whole = _kernel_output(n, d, gi, PLAIN, chunk=1 << 15)
    assert _kernel_output(n, d, gi, PLAIN, chunk=3) == whole
    split = sorted(r for c in range(3) for r in _kernel_output(n, d, gi, PLAIN, 1 << 15, start=c, step=3)[0])
    assert split == whole[0]


@pytest.mark.parametrize("n,d,gi", SLICE)
def test_compiled_kernel_gives_the_plain_kernels_output(n, d, gi):
    fast = compiled()
    if fast is None:  # numba is a dependency where it has wheels; CI (CI=true) must run the compiled kernel
        if os.environ.get("CI"):
            pytest.fail("numba is not installed under CI: the compiled kernel cannot be compared")
        pytest.skip("numba is not installed: only the plain kernel runs here (tested above)")
    assert _kernel_output(n, d, gi, (fast, True), chunk=5) == _kernel_output(n, d, gi, PLAIN, chunk=1 << 15)


def test_unit_worlds_are_the_same_with_the_plain_kernel(monkeypatch):
    units = [(5, 20, 0, 1), (6, 77, 1, 2), (4, 5, 0, 1)]
    with_default = [list(unit_worlds(u, 4)) for u in units]
    monkeypatch.setattr(orbit_kernel, "compiled", lambda: None)
    assert [list(unit_worlds(u, 4)) for u in units] == with_default
    assert [r for r, _, _ in with_default[2]] == [0, 1, 5]  # K4: 16 rotation systems, 3 worlds


def test_unit_worlds_keep_their_meaning():
    """(rank, world, autos): rank = the world's position in rotation_systems' product order, autos = every
    automorphism of the graph fixing it, in graph_automorphisms' order with the identity moved first."""
    for n, d, gi in [(4, 3, 5), (5, 3, 9), (6, 3, 28), (6, 4, 60)]:
        g = graphs_of(n, d)[gi]
        rank_of = {rot: r for r, rot in enumerate(rotation_systems(g))}
        autos = sorted(graph_automorphisms(g), key=lambda s: any(k != v for k, v in s.items()))
        for c, step in [(0, 1), (1, 2)]:
            rows = list(unit_worlds((n, gi, c, step), d))
            reps = [rot for rot in _orbit_representatives(g) if rank_of[rot] % step == c]
            assert [rank for rank, _, _ in rows] == [rank_of[rot] for rot in reps]
            assert [w for _, w, _ in rows] == [world_of_rotation(rot) for rot in reps]
            assert [a for _, _, a in rows] == [tuple(s for s in autos if _image(rot, s) == rot) for rot in reps]


def test_unit_arrays_are_unit_worlds_as_arrays():
    for unit in [(6, 77, 0, 1), (6, 77, 2, 3), (7, 352, 0, 5)]:
        rows = [(int(b.ranks[i]), from_arrays(b.offsets, b.nbr[i])) for b in unit_arrays(unit, 4) for i in range(len(b))]
        assert rows == [(rank, w) for rank, w, _ in unit_worlds(unit, 4)]
        for b in unit_arrays(unit, 4):
            assert all(np.array_equal(back_links(b.offsets, b.nbr[i]), b.back[i]) for i in range(len(b)))


def test_a_wrong_action_table_is_seen_by_the_cross_check():
    """Seeded fault: the kernel fed a broken automorphism action lists other worlds than enumerate does."""
    t = _tables(4, 3, 5)
    radices, source, base, table = t.kernel
    broken = table.copy()
    broken[len(table) // 2:] = 0  # the second half of the automorphisms map every choice to choice 0
    good = next(representatives(radices, source, base, table, start=0, step=1, stop=t.total, use=PLAIN))[0]
    bad = next(representatives(radices, source, base, broken, start=0, step=1, stop=t.total, use=PLAIN))[0]
    assert good.tolist() == [0, 1, 5] and bad.tolist() != good.tolist()


@pytest.mark.slow
@pytest.mark.parametrize("shard", range(2))
def test_eight_vertices_degree_four_counts_are_burnsides(shard):
    """Every graph's world count is Burnside's, 7,149,942 in all (docs/census.md); a sample is checked as worlds.

    Two shards (graphs of even and of odd index): every graph's batches are counted by one of them, and both
    check that Burnside's counts add up to 7,149,942, so the batches' total is that number."""
    cs = classes(8, 4)
    assert len(graphs_of(8, 4)) == len(cs)
    assert sum(worlds_on(c) for c in cs) == 7_149_942
    for gi in range(shard, len(cs), 2):
        c = cs[gi]
        assert sorted(graphs_of(8, 4)[gi].edges) == sorted(c.graph().edges)
        batches = list(graph_batches(8, 4, gi))
        assert sum(len(b) for b in batches) == worlds_on(c), gi
        if gi % 97 == 0:
            b = batches[0]
            for i in range(0, len(b), max(1, len(b) // 5)):
                assert np.array_equal(to_arrays(from_arrays(b.offsets, b.nbr[i])).back, b.back[i])


def test_without_a_place_for_numbas_cache_the_kernel_still_compiles(monkeypatch):
    try:
        import numba
    except ImportError:  # numba is a dependency where it has wheels; CI (CI=true) must compile
        if os.environ.get("CI"):
            pytest.fail("numba is not installed under CI: the kernel's cache fallback cannot be tested")
        pytest.skip("numba is not installed: nothing to compile")
    monkeypatch.setattr(numba.core.config, "CACHE_LOCATOR_CLASSES", "NoSuchLocator", raising=False)
    fresh = orbit_kernel.compiled.__wrapped__()
    assert fresh is not None
    assert _kernel_output(4, 3, 5, (fresh, True), chunk=2) == _kernel_output(4, 3, 5, PLAIN, chunk=2)

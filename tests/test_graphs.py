"""Tests of topomark.proofs.graphs: connected graphs of max degree D up to isomorphism, for any n (§3.1.1)."""

from __future__ import annotations

import random
import warnings

import networkx as nx
import pytest
from networkx.algorithms.isomorphism import GraphMatcher

from topomark.proofs import graphs
from topomark.proofs.graphs import automorphisms, canonical, classes, count, generate
from topomark.spec.errors import InvalidInput


def _wl(g: nx.Graph) -> str:
    with warnings.catch_warnings():  # networkx 3.5 notes its hash values changed; we only bucket
        warnings.simplefilter("ignore", UserWarning)
        return nx.weisfeiler_lehman_graph_hash(g, iterations=3)


def _match(ours: list[nx.Graph], theirs: list[nx.Graph]) -> bool:
    """A bijection ours -> theirs by networkx's isomorphism test (independent of our canonical form)."""
    buckets: dict[str, list[nx.Graph]] = {}
    for h in theirs:
        buckets.setdefault(_wl(h), []).append(h)
    for g in ours:
        bucket = buckets.get(_wl(g), [])
        hits = [h for h in bucket if nx.is_isomorphic(g, h)]
        if len(hits) != 1:
            return False
        bucket.remove(hits[0])
    return not any(buckets.values())


def _atlas(n: int, d: int) -> list[nx.Graph]:
    return [g for g in nx.graph_atlas_g() if g.number_of_nodes() == n and nx.is_connected(g)
            and max(x for _, x in g.degree()) <= d]


@pytest.mark.parametrize("d", [3, 4])
def test_augmentation_gives_exactly_the_atlas_classes(d):
    for n in range(1, 8):
        assert _match(generate(n, d), _atlas(n, d)), (n, d)


@pytest.mark.slow
def test_counts_match_published_figures():
    # D = 3: Wolfram, A New Kind of Science (2002), notes to ch. 9 sec. 7 "Trivalent networks";
    # cubic ones: OEIS A002851.  D = 4: OEIS A121941; quartic ones: OEIS A006820.
    assert [count(n, 3) for n in range(1, 11)] == [1, 1, 2, 6, 10, 29, 64, 194, 531, 1733]
    regular = {n: sum(all(c.degree(v) == 3 for v in range(n)) for c in classes(n, 3)) for n in (8, 10)}
    assert regular == {8: 5, 10: 19}
    assert [count(n, 4) for n in range(5, 9)] == [21, 78, 353, 1929]
    assert sum(all(c.degree(v) == 4 for v in range(8)) for c in classes(8, 4)) == 6


def test_classes_past_the_atlas_are_distinct_connected_and_bounded():
    gs = generate(8, 3)
    assert all(nx.is_connected(g) and max(x for _, x in g.degree()) <= 3 for g in gs)
    buckets: dict[str, list[nx.Graph]] = {}
    for g in gs:
        bucket = buckets.setdefault(_wl(g), [])
        assert not any(nx.is_isomorphic(g, h) for h in bucket)
        bucket.append(g)


def test_canonical_form_ignores_labels_and_separates_classes():
    rng = random.Random(7)
    for c in classes(7, 4)[::7] + classes(8, 3)[::9]:
        perm = list(range(c.n))
        rng.shuffle(perm)
        moved = [0] * c.n
        for v in range(c.n):
            moved[perm[v]] = sum(1 << perm[w] for w in c.neighbours(v))
        assert canonical(tuple(moved)).adjacency == c.adjacency
    assert len({c.adjacency for c in classes(7, 4)}) == count(7, 4)


def test_automorphism_groups_are_whole_and_correct():
    for c in classes(6, 4) + classes(8, 3)[-20:]:
        g = c.graph()
        expected = {tuple(m[v] for v in range(c.n)) for m in GraphMatcher(g, g).isomorphisms_iter()}
        assert set(c.automorphisms) == expected
    petersen = automorphisms(nx.petersen_graph())
    assert len(petersen) == 120
    g = nx.petersen_graph()
    assert all(all(g.has_edge(m[u], m[v]) for u, v in g.edges) for m in petersen)
    assert len(automorphisms(nx.complete_bipartite_graph(4, 4))) == 2 * 24 * 24


@pytest.mark.parametrize("n,d", [(0, 3), (graphs.MAX_VERTICES + 1, 3), (4, -1)])
def test_bad_sizes_are_invalid_input(n, d):
    with pytest.raises(InvalidInput):
        classes(n, d)

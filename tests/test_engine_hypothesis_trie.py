"""The hypothesis trie answers stages 1 and 2 exactly as comparing one hypothesis at a time (thesis §4.1).

The engine's Enhancement 1-3 kernels compare the hypotheses' motion sequences M with the executed paths through
:mod:`topomark.reference.engine.hypothesis_trie`; these tests hold it to the plain per-hypothesis comparison
(Algorithm 4.1 lines 16-20 and 23-26) on random hypothesis sets, and show that a wrong tie-break or a missed
node is caught.
"""

from __future__ import annotations

import random

import numpy as np
import pytest

from topomark.reference.engine import hypothesis_trie as ht
from topomark.reference.engine.trie import add_child, new_trie, start_trie


def _hypotheses(rng: random.Random) -> tuple[list[list[int]], list[int]]:
    """Motion sequences over few motions (so they share prefixes) and a remaining subset in a policy order."""
    seqs = [[rng.randrange(3) for _ in range(rng.randint(1, 6))] for _ in range(rng.randint(1, 12))]
    remaining = rng.sample(range(len(seqs)), rng.randint(1, len(seqs)))
    return seqs, remaining


def _built(seqs: list[list[int]], remaining: list[int]) -> tuple:
    off = np.cumsum([0] + [len(s) for s in seqs]).astype(np.int64)
    mot = np.array([m for s in seqs for m in s] or [0], dtype=np.int64)
    Q = ht.new_hypothesis_trie(len(mot), len(seqs))
    ht.build(Q, mot, off, len(seqs), np.array(remaining, dtype=np.int64), len(remaining))
    return Q, off


def _plain_choice(seqs, remaining, path):
    """Lines 23-26 one hypothesis at a time: the longest common prefix with the path, the first in order."""
    best, best_len = -1, 0
    for k in remaining:
        common = 0
        while common < len(path) and common < len(seqs[k]) and seqs[k][common] == path[common]:
            common += 1
        if common > best_len:
            best, best_len = k, common
    return best, best_len


def _faulty_choice(Q, path, length):
    """A seeded fault: ties go to the last hypothesis in the policy's order."""
    k, depth = ht.longest_overlap(Q, path, length)
    node = 0
    for d in range(depth):
        node = ht.child(Q, node, int(path[d]))
    members = [int(m) for m in Q[ht.MEMBERS][Q[ht.START][node]:Q[ht.START][node + 1]]
               if Q[ht.STATE][m] == ht.REMAINING]
    return (max(members, key=lambda m: Q[ht.RANK][m]), depth) if members else (k, depth)


def _trial(rng: random.Random, choice) -> bool:
    seqs, remaining = _hypotheses(rng)
    Q, off = _built(seqs, remaining)
    gone = rng.sample(remaining, rng.randint(0, len(remaining) - 1))
    for k in gone:
        ht.remove(Q, off, k)
    left = [k for k in remaining if k not in gone]
    path = [rng.randrange(3) for _ in range(rng.randint(0, 6))]
    got = choice(Q, np.array(path + [0], dtype=np.int64), len(path))
    return got == _plain_choice(seqs, left, path)


@pytest.mark.parametrize("seed", range(4))
def test_stage_two_takes_the_longest_overlap_first_in_order(seed):
    rng = random.Random(seed)
    assert all(_trial(rng, ht.longest_overlap) for _ in range(300))


def test_a_tie_broken_the_other_way_is_caught():
    rng = random.Random(0)
    assert not all(_trial(rng, _faulty_choice) for _ in range(300))


def _path_trie(rng: random.Random, depth: int, first: int) -> tuple:
    """An execution trie whose nodes form one path of ``depth`` motions (nodes 1..depth) under a root, and the
    perceptions sensed along it."""
    T = new_trie(depth + 1)
    start_trie(T, 3, 0)
    node = 0
    for _ in range(depth):
        node = add_child(T, node, rng.randrange(3), rng.choice((2, 3)), rng.randrange(2))
    return T, np.arange(1, depth + 1, dtype=np.int64)


def _plain_stage_one(T, seqs, remaining, degree, code, off, first, depth):
    """Lines 16-20 one hypothesis at a time: M walked along the path, a new node sensing other than P^E."""
    out = set()
    for k in remaining:
        for s, m in enumerate(seqs[k][:depth]):
            node = s + 1
            if T[1][node] != m:
                break
            if node >= first and (T[2][node] != degree[off[k] + s] or T[3][node] != code[off[k] + s]):
                out.add(k)
                break
    return out


def _stage_one_trial(rng: random.Random, overlapping) -> bool:
    seqs, remaining = _hypotheses(rng)
    Q, off = _built(seqs, remaining)
    size = int(off[-1]) or 1
    degree = np.array([rng.choice((2, 3)) for _ in range(size)], dtype=np.int64)
    code = np.array([rng.randrange(2) for _ in range(size)], dtype=np.int64)
    depth = rng.randint(1, 6)
    T, nodes = _path_trie(rng, depth, 1)
    first = rng.randint(1, depth)
    overlapping(Q, T, nodes, depth, first, off, degree, code)
    marked = {k for k in range(len(seqs)) if Q[ht.STATE][k] == ht.MARKED}
    return marked == _plain_stage_one(T, seqs, remaining, degree, code, off, first, depth)


@pytest.mark.parametrize("seed", range(4))
def test_stage_one_marks_exactly_the_hypotheses_a_new_node_contradicts(seed):
    rng = random.Random(seed)
    assert all(_stage_one_trial(rng, ht.overlapping) for _ in range(300))


def test_old_nodes_compared_again_are_caught():
    """A seeded fault: every node of the path compared, not only those added since the last check."""
    def every_node(Q, T, nodes, count, first, off, degree, code):
        ht.overlapping(Q, T, nodes, count, 1, off, degree, code)
    rng = random.Random(0)
    assert not all(_stage_one_trial(rng, every_node) for _ in range(300))


def test_build_counts_every_remaining_hypothesis_through_each_node():
    Q, off = _built([[1, 2], [1, 3], [2, 2]], [2, 0, 1])
    assert int(Q[ht.META][0]) == 6
    assert [int(Q[ht.LIVE][Q[ht.AT][s]]) for s in range(6)] == [2, 1, 2, 1, 1, 1]
    ht.remove(Q, off, 0)
    assert [int(Q[ht.LIVE][Q[ht.AT][s]]) for s in range(6)] == [1, 0, 1, 1, 1, 1]
    assert ht.longest_overlap(Q, np.array([1, 2], dtype=np.int64), 2) == (1, 1)

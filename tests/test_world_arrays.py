"""World arrays round-trip: the compiled kernels' flat form of a rotation system says what the world says (§3.1.1)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings

from topomark.proofs.world_arrays import back_links, from_arrays, to_arrays
from topomark.reference.worlds.strategies import worlds


@settings(max_examples=60, deadline=None)
@given(worlds(max_vertices=9))
def test_round_trip_keeps_every_exit(world):
    a = to_arrays(world)
    assert a.n == world.n and a.m == world.m
    for k, v in enumerate(a.names):
        for i, w in enumerate(world.rotation[v]):
            d = a.offsets[k] + i
            assert a.names[a.nbr[d]] == w
            assert world.target((v, i)) == (w, int(a.back[d]))
    assert np.array_equal(back_links(a.offsets, a.nbr), a.back)
    rebuilt = from_arrays(a.offsets, a.nbr)
    assert rebuilt.rotation == {f"v{k}": tuple(f"v{a.nbr[d]}" for d in range(a.offsets[k], a.offsets[k + 1]))
                                for k in range(a.n)}


def test_a_multi_edge_is_refused():
    offsets, nbr = np.array([0, 2, 4], dtype=np.int32), np.array([1, 1, 0, 0], dtype=np.int32)
    with pytest.raises(AssertionError, match="no multi-edges"):
        back_links(offsets, nbr)

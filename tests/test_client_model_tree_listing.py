"""An independent client written from Algorithm 5.1's listing (``reference/oracle/examples/client_model_tree_listing.py``)
against the oracle (§5.2.2, mapping with no markers by a tree of world models; §5.3's cues).

``model-tree`` and ``model-tree-listing`` have no conformance suite: the registry does not call them deterministic
(§5.2.2: "the algorithm is still not deterministic … we cannot determine which world model is the correct one"),
so ``suite_algorithms`` refuses them.  The client is judged by ``run_external`` with an empty kit instead, beside
topomark's literal explorer on the same world with the same options:

* the client is standalone: the standard library only, nothing of topomark;
* on small worlds, from several starts and with every option it takes (cues n, m, diameter and planarity, local
  signatures, no entry check, the window), it makes the moves ``model-tree-listing`` makes, to the traversal, and
  ends the same way: a map, or no map at a cap or when its models cannot be told apart;
* its map is the world's, and on a tree world the oracle passes it; on a world with a cycle the oracle fails a
  right map as a ``guess`` — a two-fold cover senses the same degrees everywhere, and the vertex count the client
  was told is no part of the protocol;
* where ``model-tree`` (topomark's variant) changes the listing, on the smallest worlds ``test_listing_audit.py``
  found for each change, the client costs what the listing costs, not what the variant does;
* the seeded faults: a copy whose map is mirrored fails (a wrong map), and a copy that leaves out lines 18–23
  (no validation walk) makes other costs than the listing's.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.kit import Kit
from topomark.spec.world import Start, World
from topomark.reference.oracle.conformance import suite_algorithms
from topomark.reference.oracle.run_external import Limits, run_external
from topomark.reference.run.explore import explore
from topomark.spec.errors import InvalidInput

CLIENT = EXAMPLES / "client_model_tree_listing.py"
PAIR = ["model-tree", "model-tree-listing"]

TRIANGLE = {"v0": ["v1", "v2"], "v1": ["v0", "v2"], "v2": ["v0", "v1"]}
PAW = {"v0": ["v3"], "v1": ["v2", "v3"], "v2": ["v1", "v3"], "v3": ["v0", "v1", "v2"]}
K4 = {"v0": ["v1", "v2", "v3"], "v1": ["v0", "v2", "v3"], "v2": ["v0", "v1", "v3"], "v3": ["v0", "v1", "v2"]}
C4 = {"v0": ["v1", "v3"], "v1": ["v0", "v2"], "v2": ["v1", "v3"], "v3": ["v2", "v0"]}
SPIDER = {"c": ["a1", "b1", "d1"], "a1": ["c"], "b1": ["c", "b2"], "b2": ["b1"], "d1": ["c", "d2"],
          "d2": ["d1", "d3"], "d3": ["d2"]}  # legs of 1, 2 and 3 edges: its mirror image is another embedding


def _world(rotation: dict, at: str, facing: str) -> World:
    return World(rotation).with_start(Start(at, facing))


def _client(tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new)


def _both(world: World, cmd: list[str], options: dict, name: str = "model-tree-listing"):
    """topomark's run of ``name`` and the client's, with the same options (the client's as its arguments)."""
    ours = explore(world, name, check=False, options=options)
    args = [x for k, v in options.items() for x in (f"--{k}", str(v))]
    theirs = run_external(world, cmd + args, Limits(max_traversals=10**6, wall=60), version=2, kit=Kit())
    return ours, theirs


def test_the_client_is_standalone():
    assert imported_modules(CLIENT) == {"json", "sys", "collections"}  # the standard library only: nothing of topomark


def test_neither_entry_has_a_conformance_suite():
    for name in PAIR:
        with pytest.raises(InvalidInput, match="randomised: it has no conformance suite"):
            suite_algorithms([name])


CASES = [  # world, start, facing, options; topomark's listing: (claimed outcome, cost)
    (SPIDER, "b2", "b1", {}, ("correct", 9)),  # a tree: TM completes, no cue needed
    (TRIANGLE, "v0", "v1", {"cue-n": 3}, ("correct", 10)),
    (PAW, "v3", "v1", {"cue-n": 4}, ("correct", 40)),
    (PAW, "v0", "v3", {"cue-n": 4}, ("correct", 37)),
    (PAW, "v1", "v2", {"cue-n": 4}, ("correct", 26)),
    (PAW, "v1", "v2", {"cue-n": 4, "signatures": "local"}, ("correct", 12)),
    (PAW, "v1", "v2", {"cue-n": 4, "entry-check": "no"}, ("correct", 18)),
    (PAW, "v1", "v2", {"cue-diameter": 2}, ("correct", 39)),
    (C4, "v0", "v1", {"cue-m": 4}, ("correct", 23)),
    (C4, "v0", "v1", {"cue-n": 4, "cue-planar": "yes"}, ("correct", 18)),
    (C4, "v0", "v1", {"max-steps": 8, "window": 3}, ("limit", 136)),  # no cue: the window never closes
    (K4, "v0", "v1", {"cue-n": 4, "max-steps": 20}, ("limit", 529)),
    (C4, "v0", "v1", {"cue-diameter": 2}, ("failed", 47)),  # completed models left that it cannot tell apart
]


def test_the_client_makes_the_listing_s_moves_and_maps_what_it_maps(tmp_path):
    cmd = _client(tmp_path)
    for rotation, at, facing, options, listing in CASES:
        world = _world(rotation, at, facing)
        ours, theirs = _both(world, cmd, options)
        assert (ours.claimed, ours.cost) == listing, (rotation, at, options)
        assert theirs.cost == ours.cost, (rotation, at, options, theirs.message)
        if ours.claimed != "correct":  # no map: the client says why and sends none
            assert theirs.reason == "crash" and theirs.map is None, theirs.message
        elif rotation is SPIDER:  # a tree: what it sensed determines the map
            assert (theirs.verdict, theirs.reason) == ("pass", "ok"), theirs.message
        else:  # the right map, which only the cue it was told (no part of the protocol) determines
            assert (theirs.verdict, theirs.reason) == ("fail", "guess"), theirs.message
            assert theirs.determination.how == "two-fold cover"


VARIANT = [  # the smallest worlds where model-tree changes its listing (tests/test_listing_audit.py)
    (TRIANGLE, "v0", "v1", {"cue-n": 3}),  # line 17's multi-edge hypothesis, validated at no cost
    (PAW, "v3", "v1", {"cue-n": 4}),  # the same, with validation walks
    (PAW, "v0", "v3", {"cue-n": 4}),  # lines 18-23's paths out and back
    (K4, "v0", "v1", {"cue-n": 4, "max-steps": 20}),  # the stopping rules
]


def test_where_the_variant_changes_the_listing_the_client_costs_what_the_listing_costs(tmp_path):
    cmd = _client(tmp_path)
    differences = 0
    for rotation, at, facing, options in VARIANT:
        world = _world(rotation, at, facing)
        variant, theirs = _both(world, cmd, options, name="model-tree")
        listing = explore(world, "model-tree-listing", check=False, options=options)
        assert theirs.cost == listing.cost >= variant.cost
        differences += theirs.cost != variant.cost or listing.claimed != variant.claimed
        if variant.claimed == listing.claimed == "correct":  # the same right map
            assert theirs.reason == "guess"
    assert differences == 3  # the triangle's extra hypothesis costs no move


def test_seeded_fault_a_mirrored_map_fails(tmp_path):
    mirrored = _client(tmp_path, "[names[w] for w, _ in row]", "[names[w] for w, _ in row[::-1]]")
    world = _world(SPIDER, "b2", "b1")
    ours, theirs = _both(world, mirrored, {})
    assert theirs.cost == ours.cost and (theirs.verdict, theirs.reason) == ("fail", "not-isomorphic")


def test_seeded_fault_no_validation_walk_is_not_the_listing(tmp_path):
    blind = _client(tmp_path, 'if self.o["--signatures"] == "local" or self.validate(child, v, i):  # lines 18-26',
                    "if True:  # lines 18-23 left out")
    world, options = _world(PAW, "v1", "v2"), {"cue-n": 4}
    ours, theirs = _both(world, blind, options)
    assert ours.cost == 26 and theirs.cost != ours.cost and theirs.reason == "guess"  # the right map all the same

"""The independent client of the footprint searches with ``--case footprints``: §2.3.1's footprints model of Deng
and Mirzaian (m + n homogeneous markers, Figure 2.4) as the text writes it, against the conformance oracle.

* it passes ``footprints-listing``'s suite with the listing's reference costs, case for case, within the bound,
  and costs what topomark's literal explorer costs on random worlds;
* it passes ``footprints``'s suite (topomark's search, which checks every vertex it passes) with passes and
  differences only;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map); a copy that leaves out
  the text's "same degree as v_u" maps correctly at another cost than the listing's.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from listing_clients import EXAMPLES, patched

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.run_external import run_external
from topomark.reference.run.explore import explore
from topomark.reference.worstcase.moves import random_world

CLIENT = EXAMPLES / "client_footprint_listing.py"
PAIR = ["footprints", "footprints-listing"]


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("footprints-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(PAIR))
    return root


def _client(tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new) + ["--case", "footprints"]


def _run(world, command: list[str]):
    spec = algorithm_spec("footprints-listing")
    result = run_external(world, command, version=2, kit=spec.kit_for(world.n, world.m, {"markers": None}))
    return result, explore(world, spec.name, check=False).cost


def test_the_client_passes_the_listing_s_suite_with_its_costs_and_the_variant_s_with_differences(suite, tmp_path):
    rows = run_algorithms(suite, _client(tmp_path), PAIR)
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == set(PAIR)
    for row in rows:
        j = row.to_json()
        if row.algorithm == "footprints-listing":
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
            assert j["bound_binds"] and j["cost"] <= j["bound"]
            assert j["reason"] == ("failed" if row.case["expected"] == "failed" else "ok")
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and "footprints (topomark's variant)" in j["message"]


def test_the_client_costs_what_topomark_s_listing_costs_on_random_worlds(tmp_path):
    rng, command = random.Random(231), _client(tmp_path)
    for _ in range(6):
        world = random_world(rng.randint(5, 9), rng.choice([3, 4]), rng)
        result, listed = _run(world, command)
        assert result.verdict == "pass" and result.cost == listed, (result.message, world)


def test_seeded_fault_a_wrong_join_fails(suite, tmp_path):
    old = "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)"
    new = "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = [far[0], (far[1] + 1) % len(self.exits[far[0]])], list(e)"
    rows = run_algorithms(suite, _client(tmp_path, old, new), ["footprints-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)


DEGREE = ("chosen = {v for v in range(len(self.exits)) if v != vk and len(self.exits[v]) == degree}",
          "chosen = {v for v in range(len(self.exits)) if v != vk}")


def test_seeded_fault_leaving_out_the_degree_changes_the_cost(tmp_path):
    world = random_world(7, 4, random.Random(0))
    result, listed = _run(world, _client(tmp_path))
    assert result.verdict == "pass" and result.cost == listed
    result, listed = _run(world, _client(tmp_path, *DEGREE))
    assert result.verdict == "pass" and result.cost != listed

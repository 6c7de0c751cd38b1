"""The census's compiled engine gives the reference's records (topomark.proofs.census_kernel, census_compiled).

The reference (``census_map.world_records``) is the definition: for every
world of n ≤ 6, D ≤ 4 (slow) and a slice in the fast tests, the compiled
kernel must write the same rows — language digests, members, iso keys — and
a sharded census must write the same shard bytes and results with either
engine.  A kernel that mis-numbers one output is caught by that comparison;
without numba ``auto`` runs the reference, saying so in one line.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest

import topomark.proofs.census_map as census_map
import topomark.proofs.census_kernel as census_kernel
import topomark.proofs.census_moore as census_moore
from topomark.proofs.blake2b_compiled import blake2b16
from topomark.proofs.census_compiled import batch_records, resolve_engine, rotation_records
from topomark.proofs.census_map import (automorphism_images, plan, unit_arrays, unit_rotations, unit_worlds,
                                       world_records)
from topomark.proofs.census_run import sharded_census
from topomark.proofs.census_shards import records
from topomark.proofs.world_arrays import back_links
from topomark.reference.cli.main import main
from topomark.spec.errors import InvalidInput

VERTEX_CLASSES = sorted(census_kernel.CLASS_CODES)
BOTH = ("directional-vertex", "undirected-vertex")


def _rows_agree(class_name: str, units: list, max_degree: int) -> int:
    """Assert both engines write the same rows and placements on ``units``; return the rows compared."""
    compared = 0
    for unit in units:
        n, gi = unit[0], unit[1]
        ref: list = []
        placements = sum(world_records(class_name, (n, gi, ri), w, autos, ref)
                         for ri, w, autos in unit_worlds(unit, max_degree))
        fast, worlds, fast_placements = rotation_records(class_name, n, gi, max_degree,
                                                         unit_rotations(unit, max_degree))
        assert fast.tobytes() == records(ref).tobytes(), f"{class_name}: the engines disagree on unit {unit}"
        assert fast_placements == placements and worlds == len(list(unit_worlds(unit, max_degree)))
        batch = batch_records(class_name, max_degree, unit_arrays(unit, max_degree),
                              automorphism_images(n, max_degree, gi))
        assert batch[0].tobytes() == fast.tobytes(), f"{class_name}: the batch path disagrees on unit {unit}"
        assert batch[1:] == (worlds, placements)
        compared += len(ref)
    return compared


def _units(max_vertices: int, max_degree: int, min_vertices: int = 2) -> list:
    return [u for task in plan(max_vertices, max_degree, min_vertices, task_worlds=500) for u, _ in task]


@pytest.mark.parametrize("class_name", VERTEX_CLASSES)
def test_every_world_up_to_four_vertices(class_name):
    assert _rows_agree(class_name, _units(4, 4), 4) > 0


@pytest.mark.parametrize("class_name", BOTH)
def test_a_slice_of_six_vertex_worlds(class_name):
    """Every 15th unit of n = 6 (graphs with several automorphisms, layouts with several anchors among them)."""
    assert _rows_agree(class_name, _units(6, 4, 6)[::15], 4) > 1000


@pytest.mark.slow
@pytest.mark.parametrize("class_name", BOTH)
def test_every_world_up_to_six_vertices(class_name):
    assert _rows_agree(class_name, _units(6, 4), 4) > 100_000


def test_compiled_blake2b_is_hashlibs():
    data = np.frombuffer(bytes(range(256)) * 2, np.uint8)
    for length in [*range(0, 260), 383, 384, 385]:
        d0, d1 = blake2b16(data, 3, 3 + length)
        got = int(d0).to_bytes(8, "little") + int(d1).to_bytes(8, "little")
        assert got == hashlib.blake2b(bytes(data[3:3 + length]), digest_size=16).digest(), length


def test_back_links_and_signature_texts_are_the_specs():
    offsets = np.array([0, 3, 6, 9, 12], np.int32)  # K4
    nbr = np.array([1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1], np.int32)
    assert census_moore.back_of(offsets, nbr).tolist() == back_links(offsets, nbr).tolist()
    (text, ends), rank = census_moore.signature_table(4)
    named = {bytes(text[ends[i]:ends[i + 1]]).decode(): i for i in range(len(rank)) if rank[i] >= 0}
    assert named["[3,V-2,A]"] == census_moore.output_id(3, 1, 2, 4)
    assert named["[4,V2,A]"] == census_moore.output_id(4, 2, -1, 4)
    assert sorted(named, key=lambda t: rank[named[t]]) == sorted(named)


# -- whole censuses -----------------------------------------------------------------------
def _shards(root: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(root.glob("map-*.bin"))}


def engines_agree(class_name: str, max_vertices: int, max_degree: int, root: Path) -> bool:
    """Whether a sharded census writes the same map data and gives the same result on both engines."""
    results, data = [], []
    for engine in ("reference", "compiled"):
        results.append(sharded_census(class_name, max_vertices, max_degree, root / engine, task_worlds=50, shards=3,
                                      engine=engine))
        data.append(_shards(root / engine))
    return results[0] == results[1] and data[0] == data[1] and len(data[0]) > 1


@pytest.mark.parametrize("class_name", BOTH)
def test_sharded_census_same_on_both_engines(class_name, tmp_path):
    assert engines_agree(class_name, 5, 4, tmp_path)


def test_a_misnumbered_output_is_caught(tmp_path, monkeypatch):
    """Seeded fault: the kernel reads ``[3,V-1,A]`` as ``[3,V-2,A]`` (two outputs share one number)."""
    real = census_moore.signature_table(4)
    (text, ends), rank = real
    wrong = census_moore.output_id(3, 1, 1, 4)
    right = census_moore.output_id(3, 1, 2, 4)
    texts = [bytes(text[ends[i]:ends[i + 1]]) for i in range(len(rank))]
    texts[wrong] = texts[right]
    bad_ends = np.zeros(len(texts) + 1, np.int32)
    bad_ends[1:] = np.cumsum([len(t) for t in texts])
    bad_rank = rank.copy()
    bad_rank[wrong] = rank[right]
    bad = ((np.frombuffer(b"".join(texts), np.uint8).copy(), bad_ends), bad_rank)
    monkeypatch.setattr(census_moore, "signature_table", lambda d: bad if d == 4 else real)
    assert not engines_agree("directional-vertex", 5, 4, tmp_path)


def test_without_numba_auto_runs_the_reference_and_says_so(tmp_path, monkeypatch):
    notes: list[str] = []
    with_numba = sharded_census("directional-vertex", 4, 3, tmp_path / "a", engine="auto")
    monkeypatch.setattr(census_moore, "COMPILED", False)
    ran: list[str] = []
    real = census_map.batch_records
    monkeypatch.setattr(census_map, "batch_records", lambda *a: ran.append("compiled") or real(*a))
    without = sharded_census("directional-vertex", 4, 3, tmp_path / "b", engine="auto", note=notes.append)
    assert without == with_numba and ran == []
    assert len(notes) == 1 and "numba is not installed" in notes[0]
    with pytest.raises(InvalidInput, match="needs numba"):
        resolve_engine("compiled", "directional-vertex")


def test_engine_choice():
    assert resolve_engine("auto", "directional-vertex") == "compiled"
    assert resolve_engine("auto", "undirected-edge") == "reference"  # edge markers: no kernel
    with pytest.raises(InvalidInput, match="unknown census engine 'fast'"):
        resolve_engine("fast", "none")
    with pytest.raises(InvalidInput, match="vertex-marker classes"):
        resolve_engine("compiled", "undirected-edge")


def test_cli_engine_option(capsys):
    argv = ["census", "--marker", "undirected-vertex", "--max-vertices", "4", "--max-degree", "3", "--quiet"]
    assert main([*argv, "--engine", "fast"]) == 2
    assert "invalid choice: 'fast'" in capsys.readouterr().err  # the same refusal as worst-case's --engine
    assert main(["census", "--marker", "vertex-and-edge", "--max-vertices", "3", "--max-degree", "2",
                 "--engine", "compiled"]) == 2
    assert "vertex-marker classes" in capsys.readouterr().err
    outputs = []
    for engine in ("compiled", "reference"):
        assert main([*argv, "--engine", engine, "--json"]) == 1  # the class has counterexamples at n = 4
        outputs.append({k: v for k, v in json.loads(capsys.readouterr().out).items() if k != "seconds"})
    assert outputs[0] == outputs[1]


def test_kernel_modules_are_hashed_into_the_code_version():
    """Shards of an earlier kernel are another code's: a resume refuses them.  Every module the census's map
    imports from proofs/ decides what a map task writes (the batches of worlds it reads, the orbits that choose
    each world's representative), so each is hashed."""
    import ast
    from pathlib import Path

    import topomark.proofs.census_map as census_map
    from topomark.proofs.census_integrity import CODE_MODULES
    assert {"topomark.proofs.census_kernel", "topomark.proofs.census_moore",
            "topomark.proofs.census_compiled"} <= set(CODE_MODULES)
    tree = ast.parse(Path(census_map.__file__).read_text())
    imported = {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom) and node.module
                and node.module.startswith("topomark.proofs.")}
    assert imported <= set(CODE_MODULES), imported - set(CODE_MODULES)


def test_the_batch_path_takes_each_worlds_own_automorphisms():
    """Seeded fault: the automorphism table misordered, so a stabiliser's indices name other automorphisms;
    the iso keys change and the comparison with the reference catches it (K4: 24 automorphisms)."""
    unit = (4, 5, 0, 1)
    images = automorphism_images(4, 4, 5)
    good = batch_records("undirected-vertex", 4, unit_arrays(unit, 4), images)[0]
    ref: list = []
    for ri, w, autos in unit_worlds(unit, 4):
        world_records("undirected-vertex", (4, 5, ri), w, autos, ref)
    assert good.tobytes() == records(ref).tobytes()
    wrong = np.ascontiguousarray(images[::-1])
    bad = batch_records("undirected-vertex", 4, unit_arrays(unit, 4), wrong)[0]
    assert bad.tobytes() != records(ref).tobytes()

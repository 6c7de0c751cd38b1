"""Tests of the census as map and reduce over shards (topomark.proofs.census_run and its modules).

The sharded census must give exactly today's in-memory census (rows and
smallest counterexample), resume after an interruption, run on Dask, and
reject bad input with exit 2.
"""

from __future__ import annotations

import json
import time

import numpy as np
import pytest
from hypothesis import given, settings

import topomark.proofs.census_run as census_run
from topomark.proofs.census import census, language_code, machine, minimise
from topomark.proofs.census_exec import Progress
from topomark.proofs.census_language import start_digests
from topomark.proofs.census_map import (_graphs, _iso_key, marker_layouts, marker_key, marked, rotation_count,
                                        unit_worlds, world_at)
from topomark.proofs.census_run import sharded_census
from topomark.proofs.census_shards import RECORD, _pair_key, combine, done_path, reduce_path, summary
from topomark.proofs.enumerate import _image, _orbit_representatives, world_of_rotation, canonical_form
from topomark.reference.cli.main import main
from topomark.reference.worlds.strategies import worlds
from topomark.spec.errors import InvalidInput
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.spec.robot import sense
from topomark.spec.world import World


# -- the kernel ------------------------------------------------------------------------
def _digest(world: World) -> bytes:
    mach = machine(world.with_start(None))
    block = minimise(mach)
    s = mach.index[world.start_state()]
    return start_digests(mach, block, [s])[block[s]]


def _code(world: World) -> tuple:
    mach = machine(world.with_start(None))
    return language_code(mach, minimise(mach), mach.index[world.start_state()])


@settings(max_examples=40, deadline=None)
@given(worlds(2, 5, max_degree=3, markers="any", with_start=True),
       worlds(2, 5, max_degree=3, markers="any", with_start=True))
def test_anchored_digest_equal_iff_language_code_equal(a, b):
    assert (_digest(a) == _digest(b)) == (_code(a) == _code(b))
    assert _digest(a) == _digest(a.with_start(a.start))  # deterministic


@settings(max_examples=25, deadline=None)
@given(worlds(2, 6, max_degree=4, markers="any", with_start=True))
def test_anchored_digest_equal_iff_code_equal_within_a_world(w):
    """Starts of one world (where automorphisms make several anchors tie)."""
    for d in w.darts():
        other = w.with_start(type(w.start)(d[0], w.neighbour(*d)))
        assert (_digest(w) == _digest(other)) == (_code(w) == _code(other))


@pytest.mark.parametrize("n,max_degree", [(4, 3), (5, 4), (6, 3)])
def test_units_list_the_enumerations_worlds(n, max_degree):
    """Orbit representatives decided per rotation system, whole or split by rank modulo 3, are
    exactly ``enumerate``'s worlds in its order; world_at rebuilds each from its rank."""
    for gi, g in enumerate(_graphs(n, max_degree)):
        ranks = rotation_count(n, max_degree, gi)
        whole = list(unit_worlds((n, gi, 0, 1), max_degree))
        split = sorted((r for c in range(3) for r in unit_worlds((n, gi, c, 3), max_degree)), key=lambda r: r[0])
        assert [w for _, w, _ in whole] == [world_of_rotation(r) for r in _orbit_representatives(g)]
        assert [(rank, w) for rank, w, _ in split] == [(rank, w) for rank, w, _ in whole]
        assert all(rank < ranks for rank, _, _ in whole)
        assert all(world_at(n, max_degree, gi, rank) == w for rank, w, _ in whole)
        for _, w, autos in whole:  # the stabiliser: automorphisms fixing the rotation system
            assert all(_image(tuple(tuple(int(x[1:]) for x in w.rotation[f"v{v}"]) for v in range(n)), s)
                       == tuple(tuple(int(x[1:]) for x in w.rotation[f"v{v}"]) for v in range(n)) for s in autos)


@pytest.mark.parametrize("class_name", sorted(MARKER_CLASSES))
def test_marked_and_iso_keys_agree_with_spec(class_name):
    """marked() senses what World() senses; iso keys are equal iff canonical forms are (n <= 4, D <= 4)."""
    for n in range(2, 5):
        for gi in range(len(_graphs(n, 4))):
            for ri, w, autos in unit_worlds((n, gi, 0, 1), 4):
                keys: dict[bytes, tuple] = {}
                for _, markers, _ in marker_layouts(class_name, w):
                    fast, slow = marked(w, markers), World(w.rotation, markers)
                    assert all(sense(fast, d) == sense(slow, d) for d in w.darts())
                    iso = _iso_key((n, gi, ri), marker_key(markers), autos)
                    assert keys.setdefault(iso, canonical_form(slow)) == canonical_form(slow)
                assert len(set(keys.values())) == len(keys)


def test_shard_summary_picks_the_least_pair_and_combine_is_associative():
    rng = np.random.default_rng(7)
    recs = np.zeros(3000, RECORD)
    for f in ("d0", "d1", "i0", "i1"):
        recs[f] = rng.integers(0, 40, len(recs))  # few digests and iso keys: many ambiguous classes
    for f, hi in (("n", 8), ("m", 12), ("gi", 4), ("ri", 9), ("k", 50)):
        recs[f] = rng.integers(2 if f == "n" else 0, hi, len(recs))
    recs["mask"] = 1 << recs["n"].astype(np.uint32)
    whole = summary(recs, 2, 7, all_pairs=True)
    assert whole["pairs"] and whole["pair"] == min(whole["pairs"], key=_pair_key)
    halves = combine(np.concatenate([combine(recs[:1700]), combine(recs[1700:])]))
    assert summary(halves, 2, 7, all_pairs=True) == whole


# -- sharded = in memory ----------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("class_name", sorted(MARKER_CLASSES))
def test_sharded_census_equals_in_memory(class_name, tmp_path):
    assert sharded_census(class_name, 5, 3, tmp_path, task_worlds=6, shards=3) == census(class_name, 5, 3)


def test_sharded_degree_four(tmp_path):
    """n <= 5 at max degree 4 (K5's 7,776 rotation systems split over units): the 5-vertex edge-marker pair."""
    result = sharded_census("undirected-edge", 5, 4, tmp_path, task_worlds=40, shards=5)
    assert result == census("undirected-edge", 5, 4) and result.smallest_counterexample[0].n == 5


def test_sharded_verify_all(tmp_path):
    result = sharded_census("none", 5, 3, tmp_path, verify_all=True, shards=2)  # CheckFailure if a pair fails
    assert result.ambiguous == 4


# -- resume -----------------------------------------------------------------------------
def test_interrupted_census_resumes_from_finished_tasks(tmp_path, monkeypatch):
    real = census_run.run_map
    calls: list[int] = []

    def dying(root, task, *args):
        if len(calls) == 3:  # the fourth task is killed halfway: a data file written, no done file
            (tmp_path / f"map-{task}.bin").write_bytes(b"garbage, never read")
            raise KeyboardInterrupt
        calls.append(task)
        return real(root, task, *args)

    monkeypatch.setattr(census_run, "run_map", dying)
    with pytest.raises(KeyboardInterrupt):
        sharded_census("undirected-vertex", 5, 3, tmp_path, task_worlds=5, shards=4)
    manifest = json.loads((tmp_path / "manifest.json").read_text())
    tasks = len(manifest["tasks"])
    assert [t for t in range(tasks) if done_path(tmp_path, t).exists()] == calls == [0, 1, 2]

    resumed: list[int] = []
    monkeypatch.setattr(census_run, "run_map", lambda root, task, *a: resumed.append(task) or real(root, task, *a))
    assert sharded_census("undirected-vertex", 5, 3, tmp_path, task_worlds=5) == census("undirected-vertex", 5, 3)
    assert resumed == list(range(3, tasks))  # finished tasks are not run again

    reduce_path(tmp_path, 1).unlink()  # a lost shard summary is reduced again; nothing is mapped again
    resumed.clear()
    assert sharded_census("undirected-vertex", 5, 3, tmp_path, task_worlds=5) == census("undirected-vertex", 5, 3)
    assert resumed == [] and reduce_path(tmp_path, 1).exists()


def test_shards_of_another_census_are_refused(tmp_path):
    sharded_census("none", 3, 3, tmp_path)
    with pytest.raises(InvalidInput, match="another census"):
        sharded_census("none", 4, 3, tmp_path)


# -- Dask -------------------------------------------------------------------------------
def test_dask_cluster_of_two_workers_gives_the_same_census(tmp_path):
    import distributed  # in the test extra
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        result = sharded_census("undirected-edge", 5, 3, tmp_path, scheduler=cluster.scheduler_address,
                                task_worlds=8)
    assert result == census("undirected-edge", 5, 3)


# -- progress and CLI -------------------------------------------------------------------
def test_progress_line_shows_worlds_rate_and_time_left():
    lines: list[str] = []
    bar = Progress(100, lines.append, every=0.0)
    bar.done(25, 24)
    assert lines[-1].startswith("census: [#######.") and "24/~100 worlds" in lines[-1]
    assert "worlds/s" in lines[-1] and "min left" in lines[-1]


def test_cli_shards_dir_and_progress(tmp_path, capsys):
    argv = ["census", "--marker", "undirected-vertex", "--max-vertices", "5", "--max-degree", "3", "--json"]
    assert main([*argv, "--shards", str(tmp_path / "s"), "--jobs", "2"]) == 1
    first = json.loads(capsys.readouterr().out)
    assert (tmp_path / "s" / "manifest.json").exists()
    assert main([*argv, "--shards", str(tmp_path / "s")]) == 1  # everything resumed from disk
    again = json.loads(capsys.readouterr().out)
    assert {k: v for k, v in first.items() if k != "seconds"} == {k: v for k, v in again.items() if k != "seconds"}
    assert first["ambiguous"] == 2


def test_cli_unwritable_shard_directory(tmp_path, capsys):
    (tmp_path / "file").write_text("not a directory")
    assert main(["census", "--marker", "none", "--max-vertices", "3", "--max-degree", "2",
                 "--shards", str(tmp_path / "file" / "shards")]) == 2
    assert "is not writable" in capsys.readouterr().err


def test_cli_unreachable_scheduler_fails_fast(capsys, monkeypatch):
    monkeypatch.setattr("topomark.proofs.census_exec.CONNECT_TIMEOUT", 1)
    t0 = time.perf_counter()
    assert main(["census", "--marker", "none", "--max-vertices", "3", "--max-degree", "2",
                 "--scheduler", "tcp://127.0.0.1:9"]) == 2
    assert time.perf_counter() - t0 < 20
    err = capsys.readouterr().err
    assert err.startswith("topomark: error:") and "cannot reach the Dask scheduler" in err

"""Hostile input to ``topomark worst-case`` (``--summarise``, sizes, ``-o``, ``--shards``) and ``census --shards``:
each is exit 2 with one message naming what is wrong, before any hang, unbounded read or work."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from topomark.proofs.census_map import _autos, _graphs, estimate
from topomark.proofs.census_shards import seal
from topomark.reference.cli.main import main
from topomark.reference.worstcase import limits, resumable
from topomark.reference.worstcase.exhaustive import Setup

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("run") / "out"
    assert main(["worst-case", "--max-vertices", "4", "--max-degree", "3", "--quiet", "-o", str(out)]) == 0
    return out


def _copy(run_dir: Path, tmp_path: Path) -> Path:
    d = tmp_path / "run"
    shutil.copytree(run_dir, d, symlinks=True)
    return d


def _edit(d: Path, change) -> None:
    data = json.loads((d / "worst-case.json").read_text())
    change(data)
    (d / "worst-case.json").write_text(json.dumps(data))


def _refused(argv: list[str], capsys, *words: str) -> str:
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    for w in words:
        assert w in err, err
    return err


# -- 1. --summarise trusts nothing it reads ------------------------------------------------
def test_summarise_untouched_run_is_accepted(run_dir, capsys):
    assert main(["worst-case", "--summarise", str(run_dir)]) == 0
    assert "| basic | 3 | 4 |" in capsys.readouterr().out


def test_an_algorithm_name_never_becomes_a_path(run_dir, tmp_path, capsys):
    d = _copy(run_dir, tmp_path)
    (d / "worst-case-cost-per-m.png").write_bytes(b"png")
    _edit(d, lambda x: x.update(algorithm="../../escaped"))
    out = tmp_path / "deep" / "er" / "report"
    _refused(["worst-case", "--summarise", str(d), "-o", str(out)], capsys, "worst-case.json", "algorithm")
    assert not list(tmp_path.rglob("*escaped*"))


@pytest.mark.parametrize("kind", ["dev-zero", "fifo"])
def test_a_plot_that_is_not_a_regular_file_is_refused(run_dir, tmp_path, capsys, kind):
    d = _copy(run_dir, tmp_path)
    plot = d / "worst-case-cost-per-m.png"
    plot.unlink(missing_ok=True)
    if kind == "fifo":
        os.mkfifo(plot)
    else:
        plot.symlink_to("/dev/zero")
    _refused(["worst-case", "--summarise", str(d), "-o", str(tmp_path / "report")], capsys, str(plot),
             "not a regular file")


DAMAGED = {
    "not-json": b"this is not json", "empty": b"", "null": b"null", "truncated": b'{"algorithm": "basic", "per_',
    "deep": b"[" * 100_000 + b"]" * 100_000, "huge-int": b'{"max_vertices": ' + b"9" * 5000 + b"}",
    "latin-1": '{"algorithm": "bäsic"}'.encode("latin-1"), "nan": b'{"max_vertices": NaN}',
    "oversize": b" " * (16 * 2**20 + 1),
}


@pytest.mark.parametrize("name", sorted(DAMAGED))
def test_damaged_results_files_are_bad_input(run_dir, tmp_path, capsys, name):
    d = _copy(run_dir, tmp_path)
    (d / "worst-case.json").write_bytes(DAMAGED[name])
    _refused(["worst-case", "--summarise", str(d)], capsys, "worst-case.json")


FIELDS = {
    "missing-per_n": lambda x: x.pop("per_n"), "algorithm-int": lambda x: x.update(algorithm=3),
    "unknown-algorithm": lambda x: x.update(algorithm="nope"),
    "max_vertices-huge": lambda x: x.update(max_vertices=10**30), "row-string": lambda x: x["per_n"].append("x"),
    "runs-negative": lambda x: x["per_n"][0].update(runs=-1),
    "max_cost-float": lambda x: x["per_n"][-1].update(max_cost=1.5),
    "witness-out-of-range": lambda x: x["per_n"][-1]["argmax_at"].update(graph=10**6),
    "argmax-world-swapped": lambda x: x["per_n"][-1].update(argmax=x["per_n"][0]["argmax"]),
    "max_cost-edited": lambda x: x["per_n"][-1].update(max_cost=x["per_n"][-1]["max_cost"] + 1),
    "setup-policy": lambda x: x["setup"].update(policies=["a", "b", "c"]),
}


@pytest.mark.parametrize("name", sorted(FIELDS))
def test_mistyped_or_edited_fields_are_bad_input_naming_the_field(run_dir, tmp_path, capsys, name):
    d = _copy(run_dir, tmp_path)
    _edit(d, FIELDS[name])
    err = _refused(["worst-case", "--summarise", str(d)], capsys, "worst-case.json", "field")
    assert err.count("\n") == 1


def test_an_edited_ratio_is_refused_not_reported_as_a_broken_bound(run_dir, tmp_path, capsys):
    d = _copy(run_dir, tmp_path)
    _edit(d, lambda x: x["per_n"][-1].update(max_ratio_to_bound=1.5))
    _refused(["worst-case", "--summarise", str(d)], capsys, "max_ratio_to_bound")
    e = _copy(run_dir, tmp_path / "b")  # the exact fraction edited too, consistently: the re-run refutes it

    def lie(x):
        row = x["per_n"][-1]
        row["ratio_exact"] = [3 * row["ratio_exact"][1], row["ratio_exact"][1]]
        row["max_ratio_to_bound"] = 3.0
    _edit(e, lie)
    _refused(["worst-case", "--summarise", str(e)], capsys, "ratio_exact", "the run at argmax_ratio_at gives")


def test_a_directory_with_no_runs_is_bad_input(tmp_path, capsys):
    _refused(["worst-case", "--summarise", str(tmp_path)], capsys, str(tmp_path), "no worst-case.json")


# -- 2. every size is bounded before work ----------------------------------------------------
@pytest.mark.parametrize("argv, words", [
    (["worst-case", "--max-vertices", "7", "--max-degree", "6"], ("--max-degree 6", "100,000,000")),
    (["census", "--marker", "none", "--max-vertices", "8", "--max-degree", "7"], ("--max-degree 7",)),
    (["worst-case", "--search", "--evaluations", "1000000"], ("--evaluations 1000000",)),
    (["worst-case", "--search", "--vertices", "20000"], ("--vertices 20000",)),
    (["worst-case", "--search", "--vertices", "300000"], ("--vertices 300000",)),
    (["worst-case", "--search", "--vertices", "400", "--evaluations", "40000"], ("product",)),
])
def test_sizes_past_their_bounds_are_refused_before_work(argv, words, capsys):
    t0 = time.perf_counter()
    _refused(argv + ["--quiet"], capsys, *words)
    assert time.perf_counter() - t0 < 10


@pytest.mark.parametrize("n", [7, 8])
def test_the_degree_table_is_the_world_bound(n):
    """Each n's largest degree enumerates at most MAX_WORLDS worlds, one more degree more than that."""
    def worlds(d: int) -> int:
        return sum(estimate(g, len(_autos(n, d, gi))) for gi, g in enumerate(_graphs(n, d)))
    d = limits.LARGEST_DEGREE[n]
    assert worlds(d) <= limits.MAX_WORLDS < worlds(d + 1)
    assert all(worlds(k) <= limits.MAX_WORLDS for k in range(1, 6) if n == 6)


def test_below_seven_vertices_every_degree_fits():
    assert sum(estimate(g, len(_autos(6, 5, gi))) for gi, g in enumerate(_graphs(6, 5))) <= limits.MAX_WORLDS
    assert limits.exhaustive_refusal(6, 10**6) is None


def test_help_states_the_bounds(capsys):
    with pytest.raises(SystemExit):
        main(["worst-case", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "7: 4, 8: 4" in text and "100,000" in text and "500" in text


# -- 3. outputs: the scratch folder and -o ---------------------------------------------------
def _env(tmp: Path) -> dict[str, str]:
    return {**os.environ, "TMPDIR": str(tmp), "PYTHONPATH": str(ROOT)}


def test_sigterm_removes_the_scratch_folder(tmp_path):
    proc = subprocess.Popen([sys.executable, "-m", "topomark", "worst-case", "--max-vertices", "6", "--max-degree",
                             "5", "--quiet"], cwd=ROOT, env=_env(tmp_path), stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    deadline = time.time() + 60
    while not list(tmp_path.glob("topomark-worst-case-*")) and time.time() < deadline:
        time.sleep(0.2)
    assert list(tmp_path.glob(f"topomark-worst-case-{proc.pid}-*")), "the run made no scratch folder"
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(60) == 143
    assert "Traceback" not in proc.stderr.read().decode()
    assert not list(tmp_path.glob("topomark-worst-case-*"))


def test_a_scratch_folder_of_a_dead_process_is_removed_at_the_next_start(tmp_path):
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    stale = tmp_path / f"topomark-worst-case-{dead.pid}-abc"
    (stale / "inner").mkdir(parents=True)
    other = tmp_path / "topomark-worst-case-notapid"
    other.mkdir()
    done = subprocess.run([sys.executable, "-m", "topomark", "worst-case", "--max-vertices", "3", "--quiet"],
                          cwd=ROOT, env=_env(tmp_path), capture_output=True)
    assert done.returncode == 0, done.stderr
    assert not stale.exists() and other.exists()


@pytest.mark.parametrize("target", ["/dev/full", "fifo", "/proc/topomark-out"])
def test_unwritable_out_is_refused_before_work(tmp_path, capsys, target):
    if target == "fifo":
        target = str(tmp_path / "fifo")
        os.mkfifo(target)
    t0 = time.perf_counter()  # a search of minutes: refused before it, not after
    _refused(["worst-case", "--max-vertices", "6", "--max-degree", "5", "--quiet", "-o", target], capsys, "-o", target)
    assert time.perf_counter() - t0 < 10
    _refused(["worst-case", "--search", "--vertices", "5", "--evaluations", "2", "--quiet", "-o", target], capsys,
             "-o")


# -- 4. resume directories -------------------------------------------------------------------
@pytest.fixture
def shards(tmp_path) -> Path:
    d = tmp_path / "shards"
    assert main(["worst-case", "--max-vertices", "5", "--max-degree", "4", "--quiet", "--shards", str(d)]) == 0
    return d


def _reseal(path: Path, change) -> None:
    record = {k: v for k, v in json.loads(path.read_text()).items() if k != "checksum"}
    change(record)
    path.write_text(json.dumps(seal(record)))


def test_a_manifest_resealed_with_tasks_dropped_is_refused(shards, capsys):
    tasks = json.loads((shards / "manifest.json").read_text())["tasks"]
    assert len(tasks) >= 1 and len(tasks[0]) >= 2

    def drop(m):
        m["tasks"][0] = m["tasks"][0][1:]
    _reseal(shards / "manifest.json", drop)
    _refused(["worst-case", "--max-vertices", "5", "--max-degree", "4", "--quiet", "--shards", str(shards)], capsys,
             "manifest.json", "plan")


def test_resealed_tallies_are_bad_input_not_a_topomark_failure(shards, capsys):
    def inflate(r):
        t = r["tallies"][-1]
        t["max_cost"] += 5
        t["pairs"].append([t["max_cost"], t["max_cost"], 1])  # cost/m 1: the largest cost/m stays
        t["runs"] += 1
        t["outcomes"]["correct"] += 1
    _reseal(shards / "task-0.json", inflate)
    _refused(["worst-case", "--max-vertices", "5", "--max-degree", "4", "--quiet", "--shards", str(shards)], capsys,
             "task-0.json", "run again")
    _reseal(shards / "task-0.json", lambda r: r["tallies"][-1].update(runs=r["tallies"][-1]["runs"] + 7))
    _refused(["worst-case", "--max-vertices", "5", "--max-degree", "4", "--quiet", "--shards", str(shards)], capsys,
             "task-0.json", "outcomes")


def test_a_fifo_shard_file_is_refused(shards, capsys):
    (shards / "task-0.json").unlink()
    os.mkfifo(shards / "task-0.json")
    _refused(["worst-case", "--max-vertices", "5", "--max-degree", "4", "--quiet", "--shards", str(shards)], capsys,
             "task-0.json", "not a regular file")


def test_a_fifo_census_shard_file_is_refused(tmp_path, capsys):
    d = tmp_path / "c"
    d.mkdir()
    os.mkfifo(d / "manifest.json")
    _refused(["census", "--marker", "none", "--max-vertices", "4", "--max-degree", "3", "--quiet", "--shards",
              str(d)], capsys, "manifest.json", "not a regular file")


def test_a_relative_shards_directory_reaches_the_tasks_absolute(tmp_path, monkeypatch):
    seen = []
    real = resumable._task

    def spy(root, *args):
        seen.append(root)
        return real(root, *args)
    monkeypatch.setattr(resumable, "_task", spy)
    monkeypatch.chdir(tmp_path)
    resumable.worst_case(Setup("basic"), 3, 2, Path("rel"))
    assert seen and all(Path(r).is_absolute() and Path(r) == tmp_path / "rel" for r in seen)


@pytest.mark.parametrize("option", [["--shards", "d"], ["--jobs", "2"], ["--max-vertices", "5"],
                                    ["--min-vertices", "3"], ["--scheduler", "local"], ["--sample", "0.5"],
                                    ["--cross-check"]])
def test_search_refuses_the_exhaustive_options(option, capsys):
    _refused(["worst-case", "--search", "--vertices", "5", "--evaluations", "2", "--quiet", *option], capsys,
             option[0], "--search")

"""Hostile outputs (issue 15 items 7, 8, 13): unwritable files, a streamed trace, bounded memory, concurrent bench."""

from __future__ import annotations

import csv
import io
import json
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from topomark.reference.worlds import generators as g
from topomark.reference.bench import run_store as runstore
from topomark.reference.cli.cmd_explore import _Progress
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.worlds.argument import resolve_world
from topomark.reference.trace.sink import FileSink, ListSink, RingSink, TeeSink
from topomark.spec.errors import InvalidInput

SMALL = "lattice:rows=3,cols=3"
BENCH = ["bench", "random-20", "--graphs", "3", "--sizes", "15", "20", "--jobs", "1", "--no-plots", "--quiet"]


def cli(*argv, timeout=300):
    return subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", *map(str, argv)],
                          capture_output=True, text=True, timeout=timeout)


def _targets(tmp_path: Path) -> dict[str, tuple[str, str]]:
    """Unwritable file paths: (path, a word the message must give as the reason)."""
    (tmp_path / "adir").mkdir()
    return {"missing-dir": (str(tmp_path / "no" / "such" / "out.json"), "does not exist"),
            "directory": (str(tmp_path / "adir"), "directory"),
            "dev-full": ("/dev/full", "No space left")}


COMMANDS = {
    "explore --trace": lambda p: ["explore", SMALL, "--trace", p],
    "explore --map": lambda p: ["explore", SMALL, "--map", p],
    "world -o": lambda p: ["world", SMALL, "-o", p],
}


@pytest.mark.slow
@pytest.mark.parametrize("case", ["missing-dir", "directory", "dev-full"])
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_unwritable_output_is_bad_input_naming_the_path(tmp_path, command, case):
    path, reason = _targets(tmp_path)[case]
    proc = cli(*COMMANDS[command](path))
    assert proc.returncode == 2, proc.stderr
    assert path in proc.stderr and reason in proc.stderr
    assert "Traceback" not in proc.stderr and proc.stderr.count("\n") == 1


def test_unwritable_output_is_refused_before_the_run(tmp_path):
    """A typo in --map must not cost the exploration: nothing is explored, no trace is started."""
    proc = cli("explore", "lattice-hole:rows=40,cols=40", "--trace", tmp_path / "t.jsonl",
               "--map", tmp_path / "no" / "m.json", timeout=60)
    assert proc.returncode == 2 and "m.json" in proc.stderr
    assert not (tmp_path / "t.jsonl").exists()


@pytest.mark.slow
@pytest.mark.parametrize("case", ["file", "under-a-file", "report-only-missing"])
def test_bench_out_that_is_not_a_directory_is_bad_input(tmp_path, case):
    (tmp_path / "afile").write_text("x")
    path, extra = {"file": (tmp_path / "afile", []), "under-a-file": (tmp_path / "afile" / "sub", []),
                   "report-only-missing": (tmp_path / "nowhere", ["--report-only"])}[case]
    proc = cli(*BENCH, "--out", path, *extra)
    assert proc.returncode == 2, proc.stderr
    assert str(path) in proc.stderr and "Traceback" not in proc.stderr
    assert not (tmp_path / "nowhere").exists()


# -- the trace is streamed, byte for byte what dump_trace makes -----------------------------------------------------
@pytest.mark.parametrize("spec, seed", [("lattice-hole:rows=5,cols=6", 3), ("complete:n=6", None),
                                        ("random:n=12,fraction=0.3", 3)])
def test_streamed_trace_is_byte_identical_to_the_list(tmp_path, spec, seed):
    proc = cli("explore", spec, *(["--seed", seed] if seed is not None else []), "--trace", tmp_path / "t.jsonl")
    assert proc.returncode == 0, proc.stderr
    listed = explore(resolve_world(spec, seed)).trace
    assert (tmp_path / "t.jsonl").read_bytes() == dump_trace(listed).encode()


def test_sinks_agree_with_the_list():
    world = g.lattice_hole(4, 5, seed=2)
    whole, ring, buf = ListSink(), RingSink(9), io.StringIO()
    out = explore(world, sink=TeeSink(whole, ring))
    assert out.trace == [] and whole.records == explore(world).trace
    assert ring.records == whole.records[-9:] and ring.records[-1]["event"] == "end"
    assert explore(world, record=False).trace == []


@pytest.mark.parametrize("algorithm", ["basic", "enh3", "enh5-d1"])
def test_dropping_hypotheses_changes_no_count_cost_or_trace(algorithm):
    world = g.lattice_hole(5, 5, seed=1)
    kept, lean = explore(world, algorithm), explore(world, algorithm, keep_hypotheses=False)
    its = kept.explorer.iterations
    hyps = [h for it in its for h in it.hypotheses]
    assert (kept.iterations, kept.hypotheses) == (len(its), len(hyps)) and kept.hypotheses > 0
    assert kept.hypotheses_confirmed == sum(h.outcome == "case 3" for h in hyps)
    assert kept.hypotheses_rejected == sum(h.outcome in ("case 1", "case 2") for h in hyps)
    assert kept.loop_iterations == sum(it.kind == "loop" for it in its)
    assert lean.summary() == kept.summary() and dump_trace(lean.trace) == dump_trace(kept.trace)
    assert all(it.hypotheses == [] for it in lean.explorer.iterations)


def test_file_sink_reports_a_full_disk_as_bad_input():
    with pytest.raises(InvalidInput, match="/dev/full: cannot write: No space left"):
        with FileSink("/dev/full") as sink:
            for k in range(10_000):
                sink.emit({"event": "move", "step": k})


def test_violation_shows_the_last_records_without_keeping_the_trace(tmp_path):
    script = textwrap.dedent(f"""
        import sys
        sys.path.insert(0, {str(Path(__file__).parent)!r})
        from faults_min import KeepsLoopDartInU
        from dataclasses import replace
        from topomark.reference.algorithms.registry import REGISTRY
        from topomark.reference.cli.main import main
        REGISTRY["basic"] = replace(REGISTRY["basic"], explorer=KeepsLoopDartInU)
        sys.exit(main(["explore", "lattice:rows=3,cols=3", "--json", "--trace", {str(tmp_path / 't.jsonl')!r}]))
    """)
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1, proc.stderr
    tail = json.loads(proc.stdout)["trace_tail"]
    records = [json.loads(line) for line in (tmp_path / "t.jsonl").read_text().splitlines()]
    assert records[-1]["event"] == "end" and records[-1]["violation"]
    assert tail == records[-9:-1] and len(tail) == 8


def test_plain_progress_line_on_a_long_run_when_not_a_terminal():
    now = [0.0]
    stream = io.StringIO()
    bar = _Progress(True, stream=stream, clock=lambda: now[0], every=10.0)
    bar(1, 100, 5)
    assert stream.getvalue() == ""  # a short run prints nothing
    now[0] = 12.0
    bar(40, 100, 700)
    assert stream.getvalue() == "topomark: exploring: 40/100 edges explored, cost 700 so far, 12 s elapsed\n"
    now[0] = 15.0
    bar(41, 100, 720)
    assert stream.getvalue().count("\n") == 1
    quiet = _Progress(False, stream=stream, clock=lambda: now[0] + 100)
    quiet(50, 100, 800)
    assert stream.getvalue().count("\n") == 1


# -- memory: proportional to the world, not to the trace ------------------------------------------------------------
PEAK = textwrap.dedent("""
    import resource, subprocess, sys
    proc = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    print(proc.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
""")


@pytest.mark.slow
def test_checked_exploration_without_trace_keeps_memory_small():
    """Measured: 50 MB peak for lattice-hole 30x30, checked (368 MB when the trace and every iteration's
    hypotheses were kept; 4.9 GB at 60x60).  2x headroom."""
    proc = subprocess.run([sys.executable, "-c", PEAK, sys.executable, "-m", "topomark.reference.cli.main", "explore",
                           "lattice-hole:rows=30,cols=30", "--json"], capture_output=True, text=True, timeout=600)
    code, peak_kb = map(int, proc.stdout.split())
    assert code == 0, proc.stderr
    assert peak_kb < 2 * 50 * 1024


# -- bench: one sweep per directory, a damaged CSV read robustly -----------------------------------------------------
def _check_csv(path: Path) -> list[list[str]]:
    lines = list(csv.reader(path.open(newline="")))
    assert lines[0] == list(runstore.CSV_FIELDS)
    rows = lines[1:]
    assert list(runstore.CSV_FIELDS) not in rows
    keys = [tuple(r[:5]) for r in rows]
    assert len(keys) == len(set(keys))
    return rows


def test_concurrent_bench_on_one_directory_never_corrupts(tmp_path):
    argv = [sys.executable, "-m", "topomark.reference.cli.main", *BENCH, "--out", str(tmp_path)]
    procs = [subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    results = [(p.wait(timeout=300), p.stderr.read()) for p in procs]
    for code, err in results:
        assert code == 0 or (code == 2 and "is in use by another topomark bench (pid " in err), err
    assert any(code == 0 for code, _ in results)
    assert len(_check_csv(tmp_path / "runs.csv")) == 6


def test_a_held_directory_is_refused_with_the_holder_pid(tmp_path):
    import os
    with runstore.locked(tmp_path):
        proc = cli(*BENCH, "--out", tmp_path)
    assert proc.returncode == 2
    assert f"{tmp_path} is in use by another topomark bench (pid {os.getpid()})" in proc.stderr
    assert not (tmp_path / "runs.csv").exists()
    assert cli(*BENCH, "--out", tmp_path).returncode == 0  # released


@pytest.mark.slow
@pytest.mark.parametrize("damage", ["second-header", "truncated-line"])
def test_damaged_csv_is_repaired_with_a_note(tmp_path, damage):
    assert cli(*BENCH, "--out", tmp_path).returncode == 0
    path = tmp_path / "runs.csv"
    lines = path.read_text().splitlines(keepends=True)
    extra = {"second-header": lines[0], "truncated-line": lines[3][:20]}[damage]
    path.write_text("".join(lines) + extra)
    report = cli(*BENCH, "--out", tmp_path, "--report-only")
    assert report.returncode == 0, report.stderr
    assert "topomark: note: " in report.stderr and "Traceback" not in report.stderr
    assert "Runs in this experiment: 6;" in (tmp_path / "random-20.md").read_text()
    again = cli(*BENCH, "--out", tmp_path, "--json")  # a sweep repairs the file under its lock
    assert again.returncode == 0, again.stderr
    assert json.loads(again.stdout)["ran"] == 0
    assert len(_check_csv(path)) == 6


def _short(row: list[str]) -> list[str]:
    return row[:-2]


def _not_an_integer(row: list[str]) -> list[str]:
    return [row[0], "abc", *row[2:]]


@pytest.mark.slow
@pytest.mark.parametrize("damage, what", [(_short, "fields where the header has"),
                                          (_not_an_integer, "column 2 (size): 'abc' is not a non-negative integer")])
def test_unrepairable_csv_is_bad_input_naming_the_line(tmp_path, damage, what):
    assert cli(*BENCH, "--out", tmp_path).returncode == 0
    path = tmp_path / "runs.csv"
    lines = path.read_text().splitlines(keepends=True)
    lines[3] = ",".join(damage(lines[3].rstrip("\n").split(","))) + "\n"
    path.write_text("".join(lines))
    proc = cli(*BENCH, "--out", tmp_path, "--report-only")
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert f"{path} line 4" in proc.stderr and what in proc.stderr

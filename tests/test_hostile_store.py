"""Hostile run stores: ``bench``'s ``runs.csv`` is a regular file of bounded size, its values are ones topomark
writes, and its rows are verified (checksums, the manifest ``runs.json``) before a report or a resume trusts them.

Each case runs the CLI in this process (``main``) except those that could block (a FIFO), which run in a child
process with a timeout.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from topomark.reference.bench.run_store import CSV_FIELDS, MAX_FIELD_CHARS, MAX_RUNS_BYTES
from topomark.reference.cli.main import main

BENCH = ["bench", "random-20", "--graphs", "2", "--sizes", "15", "--jobs", "1", "--no-plots", "--quiet"]


def bench(capsys, out: Path, *extra: str) -> tuple[int, str]:
    code = main([*BENCH, "--out", str(out), *extra])
    return code, capsys.readouterr().err


def refused(capsys, out: Path, *words: str, extra: tuple[str, ...] = ("--report-only",)) -> str:
    code, err = bench(capsys, out, *extra)
    assert code == 2 and "Traceback" not in err and len(err.strip().splitlines()) == 1, err[-2000:]
    for w in words:
        assert w in err, (w, err)
    assert len(err) < 800
    return err


def rows(path: Path) -> list[dict]:
    return list(csv.DictReader(path.open(newline="")))


@pytest.fixture
def store(tmp_path, capsys) -> Path:
    """A finished sweep's directory: two rows in runs.csv and the manifest."""
    code, err = bench(capsys, tmp_path)
    assert code == 0, err
    assert len(rows(tmp_path / "runs.csv")) == 2 and (tmp_path / "runs.json").exists()
    return tmp_path


def _lines(path: Path) -> list[str]:
    return path.read_text().splitlines(keepends=True)


def _edit(store: Path, line: int, column: str, value: str) -> Path:
    path = store / "runs.csv"
    lines = _lines(path)
    header = lines[0].rstrip("\n").split(",")
    record = next(csv.reader([lines[line - 1]]))
    record[header.index(column)] = value
    lines[line - 1] = ",".join(record) + "\n"
    path.write_text("".join(lines))
    return path


def cli(*argv, timeout=120):
    return subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", *map(str, argv)],
                          capture_output=True, text=True, timeout=timeout)


# -- 1: runs.csv and .lock must be regular files -----------------------------------------------------------------
@pytest.mark.parametrize("mode", ["--report-only", "sweep"])
def test_a_runs_csv_linked_to_dev_zero_is_refused_naming_it(tmp_path, capsys, mode):
    os.symlink("/dev/zero", tmp_path / "runs.csv")
    extra = ("--report-only",) if mode == "--report-only" else ()
    refused(capsys, tmp_path, f"{tmp_path / 'runs.csv'}: not a regular file", extra=extra)


@pytest.mark.parametrize("name", ["runs.csv", ".lock"])
def test_a_fifo_run_store_or_lock_is_refused_without_blocking(tmp_path, name):
    os.mkfifo(tmp_path / name)
    proc = cli(*BENCH, "--out", tmp_path, timeout=60)
    assert proc.returncode == 2, proc.stderr
    assert f"{tmp_path / name}: not a regular file" in proc.stderr and "Traceback" not in proc.stderr


def test_a_runs_csv_over_the_size_cap_is_refused(tmp_path, capsys):
    with (tmp_path / "runs.csv").open("wb") as fh:
        fh.truncate(MAX_RUNS_BYTES + 1)  # sparse: costs no disk
    refused(capsys, tmp_path, "runs.csv", f"larger than the limit of {MAX_RUNS_BYTES:,} bytes")


# -- 2: damaged values are bad input naming file, line and column --------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("column, value, words", [
    ("cost", "nan", ("column 11 (cost)", "'nan' is not a finite non-negative number")),
    ("cost", "inf", ("column 11 (cost)", "'inf'")),
    ("cost", "1e309", ("column 11 (cost)", "'1e309'")),
    ("cost", "-4", ("column 11 (cost)", "'-4'")),
    ("size", "9" * 5000, ("column 2 (size)", "at most 18 digits")),
    ("seed", "-1", ("column 3 (seed)", "'-1' is not a non-negative integer")),
    ("error", "x" * (50 << 20), (f"column {CSV_FIELDS.index('error') + 1} (error)", f"a field of {50 << 20:,} characters (at most "
                                                      f"{MAX_FIELD_CHARS:,})")),
    ("verified", "maybe", ("column 13 (verified)", "'maybe' is not True or False")),
], ids=["nan", "inf", "1e309", "negative-cost", "5000-digit-size", "negative-seed", "50MB-field", "flag"])
@pytest.mark.parametrize("mode", ["--report-only", "sweep"])
def test_a_damaged_value_is_bad_input_naming_file_line_and_column(store, capsys, column, value, words, mode):
    path = _edit(store, 3, column, value)
    refused(capsys, store, f"{path} line 3, column", *words, extra=("--report-only",) if mode != "sweep" else ())


@pytest.mark.parametrize("mode", ["--report-only", "sweep"])
def test_the_same_run_twice_is_refused(store, capsys, mode):
    path = store / "runs.csv"
    lines = _lines(path)
    path.write_text("".join(lines + [lines[1]]))
    refused(capsys, store, f"{path} line 4: the run random-20 15 0 basic", "already on line 2",
            extra=("--report-only",) if mode != "sweep" else ())


# -- 3: verified before trusted ----------------------------------------------------------------------------------
def test_an_edited_cost_is_refused_by_a_report_and_recomputed_by_a_sweep(store, capsys):
    original = rows(store / "runs.csv")
    path = _edit(store, 2, "cost", str(int(original[0]["cost"]) + 1))
    refused(capsys, store, f"{path} line 2: the row does not match its checksum")
    code, err = bench(capsys, store, "--json")
    assert code == 0 and "line 2: the row does not match its checksum" in err and "will be done again" in err
    again = rows(path)
    assert len(again) == 2 and {r["seed"]: r["cost"] for r in again} == {r["seed"]: r["cost"] for r in original}
    assert bench(capsys, store, "--report-only")[0] == 0


def test_a_truncated_last_row_is_refused_by_a_report_and_recomputed_by_a_sweep(store, capsys):
    path = store / "runs.csv"
    text = path.read_text()
    path.write_text(text[:-30])  # the last row cut, as a killed writer or a careless edit leaves it
    refused(capsys, store, f"{path}: 1 sound rows where runs.json records 2")
    code, err = bench(capsys, store, "--json")
    assert code == 0 and "an unfinished last line" in err
    assert path.read_text().count("\n") == 3 and bench(capsys, store, "--report-only")[0] == 0


def test_a_deleted_row_is_recomputed(store, capsys):
    path = store / "runs.csv"
    lines = _lines(path)
    path.write_text(lines[0] + lines[2])
    refused(capsys, store, "1 sound rows where runs.json records 2", "rows were deleted")
    assert main([*BENCH, "--out", str(store), "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["ran"] == 1 and "the missing runs will be done again" in err
    assert sorted(r["seed"] for r in rows(path)) == ["0", "1"]


def test_a_row_from_another_sweep_is_detected(tmp_path, capsys):
    here, there = tmp_path / "here", tmp_path / "there"
    assert bench(capsys, here)[0] == 0
    assert main([*BENCH[:5], "20", *BENCH[6:], "--out", str(there)]) == 0  # another sweep: size 20
    capsys.readouterr()
    foreign = _lines(there / "runs.csv")[1]
    path = here / "runs.csv"
    path.write_text(path.read_text() + foreign)
    refused(capsys, here, f"{path} line 4: the row does not match its checksum")
    code, err = bench(capsys, here)
    assert code == 0 and "line 4: the row does not match its checksum" in err
    assert [r["size"] for r in rows(path)] == ["15", "15"]


def test_the_manifest_records_the_sweeps_and_a_damaged_one_is_bad_input(store, capsys):
    manifest = json.loads((store / "runs.json").read_text())
    assert manifest["format"] == "topomark/bench-runs@1" and manifest["rows"] == 2
    assert manifest["sweeps"][0]["experiment"] == "random-20" and manifest["sweeps"][0]["sizes"] == [15]
    (store / "runs.json").write_text(json.dumps({**manifest, "store": "not hex"}))
    refused(capsys, store, f"{store / 'runs.json'}: not a topomark bench run-store manifest: store is not")


def test_a_runs_csv_without_a_manifest_is_read_with_a_note_and_adopted_by_a_sweep(store, capsys):
    (store / "runs.json").unlink()
    path = store / "runs.csv"
    path.write_text("".join(line.rsplit(",", 1)[0] + "\n" for line in _lines(path)))  # no checksum column
    code, err = bench(capsys, store, "--report-only")
    assert code == 0 and "no runs.json beside it" in err
    assert main([*BENCH, "--out", str(store), "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["ran"] == 0 and "this sweep adds them" in err
    assert (store / "runs.json").exists() and all(len(r["checksum"]) == 16 for r in rows(path))
    assert bench(capsys, store, "--report-only") == (0, "")


def test_a_store_written_before_a_column_was_added_still_verifies(store, capsys):
    """Each row's checksum covers the columns its file has: a runs.csv written by an earlier topomark, without a
    column added since (here ``drop_trips``), verifies and reports; an edited value in it is still caught."""
    from topomark.reference.bench.run_manifest import read_manifest, row_checksum
    path = store / "runs.csv"
    old = [r for r in rows(path)]
    header = [c for c in CSV_FIELDS if c != "drop_trips"]
    identity = read_manifest(store).store
    with path.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, header, extrasaction="ignore")
        writer.writeheader()
        for r in old:
            r.pop("drop_trips")
            writer.writerow({**r, "checksum": row_checksum(identity, r, header)})
    code, err = bench(capsys, store, "--report-only")
    assert code == 0, err
    _edit(store, 2, "cost", "7")
    refused(capsys, store, "line 2: the row does not match its checksum")

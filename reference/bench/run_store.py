"""The bench's run store ``DIR/runs.csv``: one writer at a time, whole-row appends, and a reader that repairs.

``topomark bench`` appends one CSV row per finished run and skips, when
restarted, the runs already in the file (:mod:`~topomark.reference.bench.experiments`).
This module keeps that file sound when runs are killed or started twice:

* :func:`locked` — a sweep holds ``DIR/.lock`` (``fcntl.flock``, never
  waiting); a second sweep on the same directory stops at once with exit 2,
  "DIR is in use by another topomark bench (pid N)".
* :class:`Appender` — each row reaches the file in one ``write`` on an
  ``O_APPEND`` descriptor, so a row is never interleaved with another.
* :func:`read_runs` — reads what a killed or (before the lock) concurrent
  sweep may have left: an unfinished last line is dropped, a repeated header
  line skipped and a second row for the same run collapsed, each with a note
  on stderr; anything else malformed is bad input (exit 2) naming the file
  and the line.  :func:`rewrite` then writes the repaired rows back
  atomically (a sweep does this under the lock).
* A file written before a column of :data:`DEFAULTS` existed (``policy``,
  ``lighthouse``, ``options``) reads with that column's default value, and a
  sweep rewrites it with the current columns before appending to it; a column
  that is not part of a run's key (``outcome``, ``markers_used``,
  ``marker_bound``, ``d_max``, ``other``: added for §6.2's kit algorithms;
  ``walk_steps``, ``lighthouse_at``, ``completed_models``, ``peak_models``,
  ``true_world_completed``: added for Chapter 5; ``drop_trips``: the traversals
  made only to drop markers, part of ``cost``) reads as missing (empty when
  rewritten), and the reports say "not measured" where they need it.
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterator

from topomark.spec.errors import InvalidInput

from topomark.reference.files.outputs import guarded

try:  # POSIX; elsewhere a sweep runs unlocked (rows are still appended whole)
    import fcntl
except ImportError:  # pragma: no cover - not on the platforms topomark supports
    fcntl = None

__all__ = ["CSV_FIELDS", "DEFAULTS", "Runs", "read_runs", "rewrite", "row_key", "locked", "Appender", "write_atomic"]

CSV_FIELDS = ("experiment", "size", "seed", "algorithm", "policy", "lighthouse", "options", "n", "m", "d_max", "cost",
              "cost_per_m", "verified", "checked", "outcome", "markers_used", "marker_bound", "walk_steps",
              "lighthouse_at", "completed_models", "peak_models", "true_world_completed", "travel", "new",
              "validation", "retrace", "expansion", "other", "drop_trips", "hypotheses", "pruned",
              "rejected_without_motion", "overlap_saved", "recorded", "upper_bound", "expression_3_3", "seconds",
              "cpu_seconds", "error")
REQUIRED = ("experiment", "size", "seed", "algorithm", "cost", "checked", "verified", "error")
INTEGERS = ("size", "seed")
NUMBERS = ("n", "m", "cost", "cost_per_m", "travel", "new", "validation", "retrace", "expansion", "hypotheses",
           "upper_bound", "expression_3_3", "seconds", "cpu_seconds", "d_max", "markers_used", "marker_bound", "other",
           "drop_trips", "walk_steps", "completed_models", "peak_models")


DEFAULTS = {"policy": "nearest", "lighthouse": "directional-vertex", "options": ""}
"""Columns added after the first runs files were written, and the value a row without them ran with."""


def row_key(row: dict) -> tuple[str, str, str, str, str, str, str]:
    """(world family, size, seed, algorithm, edge policy, lighthouse, option set): what a restarted sweep matches
    finished runs by."""
    return (row["experiment"], str(row["size"]), str(row["seed"]), row["algorithm"],
            row.get("policy") or DEFAULTS["policy"], row.get("lighthouse") or DEFAULTS["lighthouse"],
            row.get("options") or DEFAULTS["options"])


def _note(message: str) -> None:
    print(f"topomark: note: {message}", file=sys.stderr)


@dataclass
class Runs:
    """The sound rows of a runs file, and what had to be repaired to get them."""

    rows: list[dict] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    header: list[str] = field(default_factory=lambda: list(CSV_FIELDS))

    @property
    def needs_rewrite(self) -> bool:
        return bool(self.notes) or tuple(self.header) != CSV_FIELDS


def _text(path: Path) -> str:
    data = guarded(path, path.read_bytes)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InvalidInput(f"{path}: not a runs file: not UTF-8 text (byte {exc.start})") from None


def _check_row(path: Path, line: int, row: dict) -> None:
    """Bad input naming the line unless the values the report computes with are numbers."""
    for name in INTEGERS:
        if not row[name].lstrip("-").isdigit():
            raise InvalidInput(f"{path} line {line}: {name} {row[name]!r} is not an integer (the file is damaged; "
                               "delete that line to run it again)")
    for name in NUMBERS:
        value = row.get(name) or ""
        try:
            if value:
                float(value)
        except ValueError:
            raise InvalidInput(f"{path} line {line}: {name} {value!r} is not a number (the file is damaged; "
                               "delete that line to run it again)") from None


def _header(path: Path, line: int, record: list[str]) -> list[str]:
    missing = [f for f in REQUIRED if f not in record]
    if missing or len(set(record)) != len(record):
        raise InvalidInput(f"{path} line {line}: not a topomark bench runs header "
                           f"({'missing ' + ', '.join(missing) if missing else 'a repeated column'})")
    return record


def read_runs(path: str | Path, note: Callable[[str], None] | None = _note) -> Runs:
    """The rows of ``path`` (none if it does not exist), repaired as the module docstring says."""
    path = Path(path)
    runs = Runs()
    if not path.exists():
        return runs
    text = _text(path)
    if text and not text.endswith("\n"):
        runs.notes.append(f"{path} line {text.count(chr(10)) + 1}: an unfinished last line (a killed run) is "
                          "ignored; that run will be done again")
        text = text[: text.rfind("\n") + 1]
    reader = csv.reader(io.StringIO(text, newline=""))
    header: list[str] | None = None
    seen: set[tuple] = set()
    for record in reader:
        line = reader.line_num
        if not record:
            continue
        if header is None:
            header = runs.header = _header(path, line, record)
        elif record == header:
            runs.notes.append(f"{path} line {line}: a repeated header line is skipped")
        elif len(record) != len(header):
            raise InvalidInput(f"{path} line {line}: {len(record)} fields where the header has {len(header)} "
                               "(the file is damaged; delete that line to run it again)")
        else:
            row = dict(zip(header, record))
            for name, value in DEFAULTS.items():  # an older file: the column is added with what its runs used
                row[name] = row.get(name) or value
            _check_row(path, line, row)
            ident = (row_key(row), row["checked"])
            if ident in seen:
                runs.notes.append(f"{path} line {line}: a second row for the run {' '.join(ident[0])} is ignored")
                continue
            seen.add(ident)
            runs.rows.append(row)
    for message in runs.notes if note else ():
        note(message)
    return runs


def format_rows(rows: list[dict], header: bool = False) -> str:
    """CSV text of ``rows`` in the :data:`CSV_FIELDS` columns (a missing value is empty)."""
    buf = io.StringIO(newline="")
    writer = csv.DictWriter(buf, fieldnames=CSV_FIELDS, extrasaction="ignore", restval="")
    if header:
        writer.writeheader()
    writer.writerows(rows)
    return buf.getvalue()


def write_atomic(path: str | Path, text: str) -> None:
    """Replace ``path`` by ``text`` all at once (a temporary file renamed over it)."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")

    def write() -> None:
        try:
            tmp.write_text(text, encoding="utf-8", newline="")
            os.replace(tmp, path)
        finally:
            tmp.unlink(missing_ok=True)

    guarded(path, write)


def rewrite(path: str | Path, runs: Runs) -> None:
    """Write the repaired ``runs`` back to ``path``: one header, the current columns, each run once."""
    write_atomic(path, format_rows(runs.rows, header=True))


@contextlib.contextmanager
def locked(directory: str | Path) -> Iterator[None]:
    """Hold ``directory/.lock`` for a sweep; InvalidInput naming the holder's pid if another sweep has it."""
    lock = Path(directory) / ".lock"
    fd = guarded(lock, lambda: os.open(lock, os.O_RDWR | os.O_CREAT, 0o644))
    try:
        if fcntl is not None:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                pid = os.pread(fd, 32, 0).decode("ascii", "replace").strip() or "unknown"
                raise InvalidInput(f"{directory} is in use by another topomark bench (pid {pid})") from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        yield
    finally:
        os.close(fd)


class Appender:
    """Rows appended to a runs file, each in one write on an ``O_APPEND`` descriptor; a header if it is new."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.fd = guarded(self.path, lambda: os.open(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644))
        if os.fstat(self.fd).st_size == 0:
            self._write(format_rows([], header=True))

    def _write(self, text: str) -> None:
        data = text.encode("utf-8")
        guarded(self.path, lambda: os.write(self.fd, data) == len(data) or self._short())

    def _short(self) -> None:
        raise OSError(0, "a short write (is the disk full?)")

    def append(self, row: dict) -> None:
        self._write(format_rows([row]))

    def close(self) -> None:
        os.close(self.fd)

    def __enter__(self) -> "Appender":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

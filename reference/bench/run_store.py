"""The bench's run store ``DIR/runs.csv``: one writer at a time, whole-row appends, verified before trusted.

``topomark bench`` appends one CSV row per finished run and skips, when
restarted, the runs already in the file (:mod:`~topomark.reference.bench.experiments`).
This module keeps that file sound when runs are killed or started twice, and
refuses what topomark did not write:

* :func:`locked` — a sweep holds ``DIR/.lock`` (``fcntl.flock``, never
  waiting); a second sweep on the same directory stops at once with exit 2,
  "DIR is in use by another topomark bench (pid N)".  A ``.lock`` that is not
  a regular file (a FIFO, a device) is bad input, and nothing blocks on it.
* :class:`Appender` — each row reaches the file in one ``write`` on an
  ``O_APPEND`` descriptor, so a row is never interleaved with another.
* :func:`read_runs` — ``runs.csv`` must be a regular file (a FIFO, a device
  or a symlink to one is refused before it is read: the same predicate as
  world files, :func:`topomark.spec.jsontext.open_regular_file`) of at most
  :data:`MAX_RUNS_BYTES` bytes, with no field longer than
  :data:`MAX_FIELD_CHARS` characters.  What a killed sweep may leave is
  repaired with a note on stderr: an unfinished last line is dropped, a
  repeated header line skipped.  Anything else malformed is bad input
  (exit 2) naming the file, the line and the column: a value that is not a
  finite non-negative number where one belongs (``nan``, ``inf``, ``1e309``,
  ``-1``), an integer of more than 18 digits, the same run twice (same key,
  checked or not).
* Verification (:mod:`~topomark.reference.bench.run_manifest`): a row whose
  checksum does not match the store's manifest ``runs.json`` (edited, or
  copied from another directory's store), or a file with fewer rows than the
  manifest records, is recomputed by a sweep — dropped with a note saying so
  — and refused by ``--report-only`` (exit 2 naming the file and the line):
  a report is never made from rows topomark did not write.  *Decision:* a
  ``runs.csv`` without a manifest (written before topomark kept one) is read
  with a note that its rows are unverified, and the next sweep adopts it (its
  rows are rewritten with checksums and a manifest is written).
  :func:`rewrite` writes the repaired rows back atomically (a sweep does this
  under the lock).
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
import math
import os
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterator, cast

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.jsontext import MAX_INT_DIGITS, open_regular_fd, read_text_file

from topomark.reference.bench.run_manifest import MANIFEST_NAME, Manifest, read_manifest, row_checksum
from topomark.reference.files.outputs import guarded

try:  # POSIX; elsewhere a sweep runs unlocked (rows are still appended whole)
    import fcntl
except ImportError:  # pragma: no cover - not on the platforms topomark supports
    fcntl = None  # type: ignore[assignment]  # no module: a sweep runs unlocked

__all__ = ["CSV_FIELDS", "DEFAULTS", "MAX_RUNS_BYTES", "MAX_FIELD_CHARS", "Runs", "read_runs", "rewrite", "row_key",
           "locked", "Appender", "write_atomic", "write_manifest"]

CSV_FIELDS = ("experiment", "size", "seed", "algorithm", "policy", "lighthouse", "options", "n", "m", "d_max", "cost",
              "cost_per_m", "verified", "checked", "outcome", "markers_used", "marker_bound", "walk_steps",
              "lighthouse_at", "completed_models", "peak_models", "true_world_completed", "travel", "new",
              "validation", "retrace", "expansion", "other", "drop_trips", "phase_two", "hypotheses", "pruned",
              "rejected_without_motion", "overlap_saved", "recorded", "upper_bound", "expression_3_3", "seconds",
              "cpu_seconds", "error", "checksum")
REQUIRED = ("experiment", "size", "seed", "algorithm", "cost", "checked", "verified", "error")
INTEGERS = ("size", "seed")
NUMBERS = ("n", "m", "cost", "cost_per_m", "travel", "new", "validation", "retrace", "expansion", "hypotheses",
           "upper_bound", "expression_3_3", "seconds", "cpu_seconds", "d_max", "markers_used", "marker_bound", "other",
           "drop_trips", "walk_steps", "completed_models", "peak_models", "phase_two")
SIGNED = ("expression_3_3",)
"""The numbers that may be negative: (3.3)'s leading terms, below zero on the smallest worlds."""
FLAGS = ("checked", "verified")
MAX_RUNS_BYTES = 64 << 20
"""The largest ``runs.csv`` read (64 MiB: some 150,000 rows; the thesis's sweeps write a few thousand)."""
MAX_FIELD_CHARS = 10_000
"""The longest field read (a run's error message is clipped to 2,000 characters when written)."""
_INTEGER = re.compile(rf"[0-9]{{1,{MAX_INT_DIGITS}}}")


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
    """The sound rows of a runs file, what had to be repaired to get them, and the store's manifest."""

    rows: list[dict] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    header: list[str] = field(default_factory=lambda: list(CSV_FIELDS))
    manifest: Manifest | None = None
    dropped: int = 0  # rows a resume dropped for their checksum (to be run again)

    @property
    def needs_rewrite(self) -> bool:
        return bool(self.notes) or tuple(self.header) != CSV_FIELDS


def _damaged(path: Path, line: int, header: list[str], name: str, what: str) -> InvalidInput:
    return InvalidInput(f"{path} line {line}, column {header.index(name) + 1} ({name}): {what} (the file is damaged; "
                        "delete that line to run it again)")


def _check_row(path: Path, line: int, header: list[str], row: dict) -> None:
    """Bad input naming the line and column unless every value is one topomark writes."""
    for name, value in zip(header, row.values()):
        if len(value) > MAX_FIELD_CHARS:
            raise _damaged(path, line, header, name, f"a field of {len(value):,} characters (at most "
                                                     f"{MAX_FIELD_CHARS:,})")
    for name in INTEGERS:
        if not _INTEGER.fullmatch(row[name]):
            raise _damaged(path, line, header, name, f"{clip(row[name], 40, quote=True)} is not a non-negative "
                                                     f"integer of at most {MAX_INT_DIGITS} digits")
    for name in NUMBERS:
        value = row.get(name) or ""
        try:
            ok = not value or (math.isfinite(float(value)) and (float(value) >= 0 or name in SIGNED))
        except ValueError:
            ok = False
        if not ok:
            raise _damaged(path, line, header, name, f"{clip(value, 40, quote=True)} is not a finite "
                                                     + ("number" if name in SIGNED else "non-negative number"))
    for name in FLAGS:
        if row[name] not in ("True", "False"):
            raise _damaged(path, line, header, name, f"{clip(row[name], 40, quote=True)} is not True or False")


def _header(path: Path, line: int, record: list[str]) -> list[str]:
    missing = [f for f in REQUIRED if f not in record]
    if missing or len(set(record)) != len(record):
        raise InvalidInput(f"{path} line {line}: not a topomark bench runs header "
                           f"({'missing ' + ', '.join(missing) if missing else 'a repeated column'})")
    return record


@contextlib.contextmanager
def _field_limit(limit: int) -> Iterator[None]:
    """The csv module's field limit raised while a file is read, so an over-long field is reported by column."""
    old = csv.field_size_limit(limit)
    try:
        yield
    finally:
        csv.field_size_limit(old)


def read_runs(path: str | Path, note: Callable[[str], None] | None = _note, resume: bool = False) -> Runs:
    """The rows of ``path`` (none if it does not exist), repaired and verified as the module docstring says;
    ``resume`` (a sweep about to run again) drops the rows that fail verification instead of refusing them."""
    path = Path(path)
    runs = Runs(manifest=read_manifest(path.parent))
    if os.path.lexists(path):
        _parse(path, read_text_file(path, max_bytes=MAX_RUNS_BYTES), runs, resume)
    for message in runs.notes if note else ():
        cast(Callable[[str], None], note)(message)
    return runs


def _parse(path: Path, text: str, runs: Runs, resume: bool) -> None:
    manifest = runs.manifest
    if manifest is None and text:
        runs.notes.append(f"{path}: no {MANIFEST_NAME} beside it (written by an older topomark): its rows are read "
                          "without verifying their checksums" + ("; this sweep adds them" if resume else ""))
    if text and not text.endswith("\n"):
        runs.notes.append(f"{path} line {text.count(chr(10)) + 1}: an unfinished last line (a killed run) is "
                          "ignored; that run will be done again")
        text = text[: text.rfind("\n") + 1]
    reader = csv.reader(io.StringIO(text, newline=""))
    header: list[str] | None = None
    seen: dict[tuple, int] = {}
    with _field_limit(MAX_RUNS_BYTES):
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
                row = _row(path, line, header, record, manifest, resume, runs.notes)
                if row is None:
                    runs.dropped += 1
                    continue
                ident = (row_key(row), row["checked"])
                if ident in seen:
                    raise InvalidInput(f"{path} line {line}: the run {' '.join(filter(None, ident[0]))} "
                                       f"(checked={ident[1]}) is "
                                       f"already on line {seen[ident]} (the file is damaged; delete one of them)")
                seen[ident] = line
                runs.rows.append(row)
    _count(path, runs, resume)


def _row(path: Path, line: int, header: list[str], record: list[str], manifest: Manifest | None, resume: bool,
         notes: list[str]) -> dict | None:
    """The checked row of ``record``; None (noted) if a resume drops it for its checksum."""
    row = dict(zip(header, record))
    _check_row(path, line, header, row)
    # the checksum covers the file's own columns, as written: a store written before a column was added verifies
    intact = manifest is None or row.get("checksum") == row_checksum(manifest.store, row, header)
    for name, value in DEFAULTS.items():  # an older file: the column is added with what its runs used
        row[name] = row.get(name) or value
    if intact:
        return row
    what = (f"{path} line {line}: the row does not match its checksum (edited, cut short, or copied from another "
            f"run store)")
    if not resume:
        raise InvalidInput(f"{what}; run the sweep again to recompute it, or delete that line")
    notes.append(f"{what}: it is dropped and the run {' '.join(filter(None, row_key(row)))} will be done again")
    return None


def _count(path: Path, runs: Runs, resume: bool) -> None:
    """Fewer rows than the manifest recorded after the last sweep: rows were deleted."""
    if runs.manifest is None or len(runs.rows) + runs.dropped >= runs.manifest.rows:
        return
    what = (f"{path}: {len(runs.rows)} sound rows where {MANIFEST_NAME} records {runs.manifest.rows} after the last "
            "sweep (rows were deleted or damaged)")
    if not resume:
        raise InvalidInput(f"{what}; run the sweep again to recompute them")
    runs.notes.append(f"{what}: the missing runs will be done again")


def _text_row(row: dict, store: str | None) -> dict:
    """``row`` as the text ``runs.csv`` holds (defaults filled in), with its checksum when ``store`` is given."""
    text = {k: "" if row.get(k) is None else str(row[k]) for k in CSV_FIELDS if k != "checksum"}
    for name, value in DEFAULTS.items():
        text[name] = text[name] or value
    if store is not None:
        text["checksum"] = row_checksum(store, text, CSV_FIELDS)
    return text


def format_rows(rows: list[dict], header: bool = False, store: str | None = None) -> str:
    """CSV text of ``rows`` in the :data:`CSV_FIELDS` columns (a missing value is empty), each with its checksum
    for the store ``store`` (:func:`~topomark.reference.bench.run_manifest.row_checksum`) when given."""
    buf = io.StringIO(newline="")
    writer = csv.DictWriter(buf, fieldnames=CSV_FIELDS, extrasaction="ignore", restval="")
    if header:
        writer.writeheader()
    writer.writerows(_text_row(r, store) for r in rows)
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


def rewrite(path: str | Path, runs: Runs, manifest: Manifest) -> None:
    """Write the repaired ``runs`` back to ``path``: one header, the current columns, each run once, each row with
    its checksum for ``manifest``'s store."""
    write_atomic(path, format_rows(runs.rows, header=True, store=manifest.store))


def write_manifest(directory: str | Path, manifest: Manifest) -> None:
    """Write ``directory/runs.json`` (atomically)."""
    write_atomic(Path(directory) / MANIFEST_NAME, manifest.to_text())


def _stamp(fd: int) -> None:
    """Our pid in the lock file, for the message of a bench that finds it taken."""
    os.ftruncate(fd, 0)
    os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)


@contextlib.contextmanager
def locked(directory: str | Path) -> Iterator[None]:
    """Hold ``directory/.lock`` for a sweep; InvalidInput naming the holder's pid if another sweep has it, or
    naming ``.lock`` if it is not a regular file (a FIFO or device: checked without blocking)."""
    lock = Path(directory) / ".lock"
    fd = open_regular_fd(lock, os.O_RDWR | os.O_CREAT, max_bytes=None)
    try:
        if fcntl is not None:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                pid = clip(os.pread(fd, 32, 0).decode("ascii", "replace").strip() or "unknown", 20)
                raise InvalidInput(f"{directory} is in use by another topomark bench (pid {pid})") from None
        guarded(lock, lambda: _stamp(fd))
        yield
    finally:
        os.close(fd)


class Appender:
    """Rows appended to a runs file, each in one write on an ``O_APPEND`` descriptor; a header if it is new.

    ``store`` is the manifest's store identifier each row's checksum is made with.  The file must be a regular
    file (:func:`~topomark.spec.jsontext.open_regular_fd`: a FIFO never blocks the sweep)."""

    def __init__(self, path: str | Path, store: str):
        self.path, self.store = Path(path), store
        self.fd = open_regular_fd(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, max_bytes=None)
        self.appended = 0
        if os.fstat(self.fd).st_size == 0:
            self._write(format_rows([], header=True))

    def _write(self, text: str) -> None:
        data = text.encode("utf-8")
        guarded(self.path, lambda: os.write(self.fd, data) == len(data) or self._short())

    def _short(self) -> bool:  # never returns: it raises (typed for _write's `or`)
        raise OSError(0, "a short write (is the disk full?)")

    def append(self, row: dict) -> None:
        self._write(format_rows([row], store=self.store))
        self.appended += 1

    def close(self) -> None:
        os.close(self.fd)

    def __enter__(self) -> "Appender":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

"""The fault report: when topomark itself fails (exit 3), everything needed to reproduce the fault, in one file.

A fault is topomark's bug, not the user's, so the user should not have to gather what its maintainers need.
:func:`write_report` writes one JSON file, ``"format": "topomark/fault-report@1"`` (``docs/formats.md``):

* ``topomark`` (version, where it was imported from), ``python`` (version, implementation, executable),
  ``platform``, ``written`` (UTC), ``cwd``;
* ``argv``: the command line, as given;
* ``inputs``: each world or map file the command line names (``"format": "topomark/world@..."``), inlined
  (parsed; a file that is not JSON as text, the first :data:`MAX_TEXT` characters), so the report alone
  reproduces the run; a file larger than :data:`MAX_INPUT_BYTES` is named, not inlined;
* ``run``: the run in progress when it failed, if any (:mod:`topomark.reference.trace.flight`): its algorithm,
  its world (a generated one too) and the last trace records it made;
* ``failure``: the exception's ``type``, ``message`` and ``traceback``; ``check``, the check that failed — a
  :class:`~topomark.spec.errors.TopomarkFault`'s named check of topomark's own, or a
  :class:`~topomark.spec.errors.CheckFailure` behind the fault (its violation) — or null.

Where: ``topomark-fault-YYYYmmdd-HHMMSS.json`` (local time; ``-2``, ``-3``... when that name is taken) in the
directory ``TOPOMARK_FAULT_DIR`` names, else the current directory; when that directory cannot take it, the
system's temporary directory.  Writing the report never makes the failure worse: each part that cannot be
gathered says why in its place, and a report that cannot be written at all is a reason, not an exception.
"""

from __future__ import annotations

import datetime
import json
import os
import platform
import sys
import tempfile
import traceback
from pathlib import Path
from typing import Any, Callable, Sequence

from topomark.spec.errors import CheckFailure, TopomarkFault

from topomark.reference.trace.flight import run_of

__all__ = ["FORMAT", "ENV_DIR", "MAX_INPUT_BYTES", "MAX_TEXT", "build_report", "write_report", "report_dirs"]

FORMAT = "topomark/fault-report@1"
ENV_DIR = "TOPOMARK_FAULT_DIR"
"""The environment variable naming the directory fault reports go to (default: the current directory)."""

MAX_INPUT_BYTES = 16 * 1024 * 1024
"""A world file larger than this is named in the report, not inlined."""

MAX_TEXT = 100_000
"""The most characters of a named file that is not JSON kept in the report (it may be why topomark failed)."""


def build_report(argv: Sequence[str], exc: BaseException) -> dict[str, Any]:
    """The report of ``exc``, raised by ``topomark ARGV``: every part gathered on its own, a failed one saying why."""
    report: dict[str, Any] = {"format": FORMAT}
    parts: dict[str, Callable[[], Any]] = {
        "written": lambda: datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "topomark": _topomark, "python": _python, "platform": platform.platform, "cwd": os.getcwd,
        "argv": lambda: ["topomark", *map(str, argv)], "failure": lambda: _failure(exc),
        "inputs": lambda: _inputs(argv), "run": lambda: run_of(exc)}
    for name, gather in parts.items():
        try:
            report[name] = gather()
        except Exception as error:  # noqa: BLE001 - a part that cannot be gathered says why; the others stay
            report[name] = {"unavailable": f"{error.__class__.__name__}: {error}"}
    return report


def _topomark() -> dict[str, Any]:
    from importlib.metadata import PackageNotFoundError, version

    import topomark.spec

    try:
        installed = version("topomark")
    except PackageNotFoundError:
        installed = "unknown (the package is not installed)"
    return {"version": installed, "location": str(Path(topomark.spec.__file__).resolve().parents[1])}


def _python() -> dict[str, Any]:
    return {"version": sys.version, "implementation": platform.python_implementation(),
            "executable": sys.executable}


def _failure(exc: BaseException) -> dict[str, Any]:
    return {"type": f"{exc.__class__.__module__}.{exc.__class__.__qualname__}", "message": str(exc),
            "check": _check(exc),
            "traceback": "".join(traceback.format_exception(type(exc), exc, exc.__traceback__))}


def _check(exc: BaseException) -> dict[str, Any] | None:
    """The check that failed: a fault's named check of topomark's own, else a CheckFailure behind it, else None."""
    if isinstance(exc, TopomarkFault) and exc.check:
        return {"name": exc.check, "message": str(exc)}
    seen: set[int] = set()
    cause: BaseException | None = exc
    while cause is not None and id(cause) not in seen:
        seen.add(id(cause))
        if isinstance(cause, CheckFailure):
            found = cause.violation.to_json()
            return {"name": found.pop("check"), "message": str(cause), **found}
        cause = cause.__cause__ or cause.__context__
    return None


def _inputs(argv: Sequence[str]) -> list[dict[str, Any]]:
    """The world and map files ``argv`` names (an argument, or an ``--option=`` value), inlined."""
    out, seen = [], set()
    for arg in argv:
        for text in {str(arg), str(arg).partition("=")[2]} - {""}:
            path = _regular_file(text)
            if path is None or path in seen:
                continue
            seen.add(path)
            entry = _input(text, path)
            if entry is not None:
                out.append(entry)
    return out


def _regular_file(text: str) -> Path | None:
    try:
        path = Path(text)
        return path.resolve() if path.is_file() else None
    except (OSError, ValueError):  # a name too long for a path, an embedded NUL: no file
        return None


def _input(text: str, path: Path) -> dict[str, Any] | None:
    """A world file inlined (parsed), a ``.json`` file that is not JSON as text; None for any other file."""
    size = path.stat().st_size
    if size > MAX_INPUT_BYTES:
        return ({"path": text, "left_out": f"{size:,} bytes, more than the {MAX_INPUT_BYTES:,} a report inlines"}
                if path.suffix == ".json" else None)
    raw = path.read_text(encoding="utf-8", errors="replace")
    try:
        data = json.loads(raw)
    except (ValueError, RecursionError):
        if path.suffix != ".json":
            return None
        kept = raw[:MAX_TEXT]
        return {"path": text, "text": kept, "note": "not JSON" + (f"; the first {MAX_TEXT:,} of {len(raw):,} "
                                                                  "characters" if len(kept) < len(raw) else "")}
    if isinstance(data, dict) and str(data.get("format", "")).startswith("topomark/world"):
        return {"path": text, "json": data}
    return None


def report_dirs() -> list[Path]:
    """Where a report may go, in order: ``$TOPOMARK_FAULT_DIR`` or the current directory, then the temp dir."""
    first = os.environ.get(ENV_DIR) or "."
    dirs = [Path(first)]
    try:
        temp = Path(tempfile.gettempdir())
    except Exception:  # noqa: BLE001 - no temporary directory at all: the first place only
        return dirs
    return dirs if _same(dirs[0], temp) else [*dirs, temp]


def _same(a: Path, b: Path) -> bool:
    try:
        return a.resolve() == b.resolve()
    except (OSError, ValueError, RuntimeError):
        return False


def write_report(argv: Sequence[str], exc: BaseException, now: datetime.datetime | None = None
                 ) -> tuple[Path | None, str]:
    """Write the report of ``exc``; ``(path, "")``, or ``(None, why)``: each place tried and what it answered."""
    try:
        text = json.dumps(build_report(argv, exc), indent=1, default=repr, ensure_ascii=False) + "\n"
    except Exception as error:  # noqa: BLE001 - even a report that cannot be made leaves the exit code alone
        return None, f"the report could not be made: {error.__class__.__name__}: {error}"
    stamp = (now or datetime.datetime.now()).strftime("%Y%m%d-%H%M%S")
    failures = []
    for directory in report_dirs():
        try:
            return _write_new(directory, f"topomark-fault-{stamp}", text), ""
        except Exception as error:  # noqa: BLE001 - the next place, and in the end the reason
            failures.append(f"{directory}: {getattr(error, 'strerror', None) or error}")
    return None, "; ".join(failures)


def _write_new(directory: Path, stem: str, text: str) -> Path:
    """``directory/stem.json`` (or ``stem-2.json``...), created, never overwriting a file already there."""
    for attempt in range(1, 100):
        path = directory / (f"{stem}.json" if attempt == 1 else f"{stem}-{attempt}.json")
        try:
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        except FileExistsError:
            continue
        try:
            with os.fdopen(fd, "w", encoding="utf-8") as out:
                out.write(text)
        except BaseException:
            path.unlink(missing_ok=True)  # a half-written report is no report
            raise
        return path
    raise FileExistsError(f"{stem}.json and 98 more names are taken")

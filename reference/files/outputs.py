"""Output files the user names (``--trace``, ``--map``, ``-o``, ``--out``): checked early, failures are bad input.

Every command that writes a file the user named goes through this module, so
an unwritable path is always reported the same way: exit 2 and one message
naming the path and the reason, never a traceback.

* :func:`check_output` — before a long run starts: the parent directory
  exists and is a writable directory, and the path itself is not a
  directory.  (A device such as ``/dev/full`` passes: it only fails when
  written to, and that failure is caught too.)
* :func:`open_output` — a text file opened for writing whose ``write``,
  ``flush`` and ``close`` turn :class:`OSError` (``ENOSPC``, ``EIO``, ...)
  into :class:`~topomark.spec.errors.InvalidInput` naming the path.
* :func:`write_output` — write a whole text at once, the same way.
* :func:`check_output_dir` — an output *directory*, created if missing.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Callable, TypeVar

from topomark.spec.errors import InvalidInput

__all__ = ["check_output", "check_output_dir", "open_output", "write_output", "guarded", "OutputFile"]

T = TypeVar("T")


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _cannot(path: str | Path, why: str) -> InvalidInput:
    return InvalidInput(f"{path}: cannot write: {why}")


def check_output(path: str | Path) -> None:
    """Raise InvalidInput unless ``path`` can plausibly be created or overwritten as a file."""
    p = Path(path)
    if p.is_dir():
        raise _cannot(path, "it is a directory")
    parent = p.parent
    if not parent.exists():
        raise _cannot(path, f"the directory {str(parent)!r} does not exist")
    if not parent.is_dir():
        raise _cannot(path, f"{str(parent)!r} is not a directory")
    if p.exists():
        if not os.access(p, os.W_OK):
            raise _cannot(path, "permission denied")
    elif not os.access(parent, os.W_OK | os.X_OK):
        raise _cannot(path, f"permission denied in the directory {str(parent)!r}")


def check_output_dir(path: str | Path, create: bool = True) -> Path:
    """``path`` as an existing directory (made, with its parents, when ``create``); InvalidInput if impossible."""
    if not str(path).strip():
        raise InvalidInput("the output directory's path is empty")
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InvalidInput(f"{path}: cannot use as the output directory: it is not a directory")
    if create:
        try:
            p.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise InvalidInput(f"{path}: cannot create the output directory: {_reason(exc)}") from None
    elif not p.exists():
        raise InvalidInput(f"{path}: no such directory")
    if not os.access(p, os.W_OK | os.X_OK):
        raise InvalidInput(f"{path}: cannot write in the output directory: permission denied")
    return p


def guarded(path: str | Path, action: Callable[[], T]) -> T:
    """Run ``action`` (which writes ``path``); an OSError becomes InvalidInput naming ``path``."""
    try:
        return action()
    except OSError as exc:
        raise _cannot(path, _reason(exc)) from None


class OutputFile:
    """A text file open for writing; every OS error on it is InvalidInput naming the path."""

    def __init__(self, path: str | Path):
        check_output(path)
        self.path = path
        self._fh = guarded(path, lambda: open(path, "w", encoding="utf-8", newline=""))

    def write(self, text: str) -> None:
        guarded(self.path, lambda: self._fh.write(text))

    def flush(self) -> None:
        guarded(self.path, self._fh.flush)

    def close(self) -> None:
        """Flush and close; the file is closed even when the flush fails (the failure is still raised)."""
        if self._fh.closed:
            return
        try:
            guarded(self.path, self._fh.flush)
        finally:
            try:
                self._fh.close()
            except OSError:
                pass  # a flush that failed above already reported the path; closing cannot add news

    def __enter__(self) -> "OutputFile":
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        if exc_type is None:
            self.close()
            return
        try:  # already failing: close quietly, so the first error is the one reported
            self._fh.close()
        except OSError:
            pass


def open_output(path: str | Path) -> OutputFile:
    """Open ``path`` for writing text (checked first); use as a context manager."""
    return OutputFile(path)


def write_output(path: str | Path, text: str) -> None:
    """Write ``text`` to ``path`` (checked first); any OS error is InvalidInput naming the path."""
    with open_output(path) as fh:
        fh.write(text)

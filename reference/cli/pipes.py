"""A verdict's exit code never depends on how stdout and stderr are attached.

``topomark conformance run … | head -1`` closes the pipe after one line; a later ``print`` would raise
:class:`BrokenPipeError` and unwind the command before it returns its verdict, and a failing program would
look like a passing one to a shell with ``pipefail``.  The same holds for a stream closed before the command
started (``topomark explore … >&-``: Python then has no ``sys.stdout`` at all), a full disk, and a terminal or
pipe whose encoding cannot show a character topomark prints (``§``, ``→`` under ``PYTHONIOENCODING=ascii``).

:class:`ClosedPipeSafe` wraps stdout and stderr for the whole command (:func:`closed_pipe_safe`):

* a character the stream's encoding lacks is written as a backslash escape (``\\xa7`` for ``§``);
* once a write or flush fails (closed pipe, closed or full file), that stream's file descriptor is sent to the
  null device and the rest of its output is dropped, so the command runs to its verdict and exits with its own
  code (0, 1, 2 or 3), and Python's own flush at exit cannot fail either (it would exit 120).  A failure other
  than a closed pipe (the reader has gone: nothing is lost that anyone could read) is said once on stderr;
* a stream closed before the command started drops everything written to it, and its descriptor is taken by
  the null device, so no file the command opens can land on descriptor 1 or 2 and receive output.

>>> import io
>>> class Closed(io.StringIO):
...     def write(self, s):
...         raise BrokenPipeError(32, "Broken pipe")
>>> out = ClosedPipeSafe(Closed())
>>> out.write("FAIL [map]\\n"), out.broken
(11, True)
>>> out.write("more"), out.broken  # dropped, silently
(4, True)
>>> ascii_out = io.TextIOWrapper(io.BytesIO(), encoding="ascii")
>>> _ = ClosedPipeSafe(ascii_out).write("§3.3 → done")
>>> ascii_out.flush(); ascii_out.buffer.getvalue()
b'\\\\xa73.3 \\\\u2192 done'
"""

from __future__ import annotations

import contextlib
import errno
import os
import sys
from typing import Callable, Iterator, TextIO

__all__ = ["ClosedPipeSafe", "closed_pipe_safe"]

REPLACEMENT = "backslashreplace"
"""How a character the stream cannot encode is written: ``\\xa7``, ``\\u2192`` (no information lost)."""


class ClosedPipeSafe:
    """``stream``, except that writing to it never raises: an unencodable character is escaped, and a failed
    write or flush drops the output from then on (:attr:`broken` says so; ``on_error`` hears why, once, unless
    the reason is a closed pipe).  ``broken=True`` drops everything from the start."""

    def __init__(self, stream: TextIO, on_error: Callable[[str], None] | None = None, broken: bool = False):
        self._stream = stream
        self._on_error = on_error
        self.broken = broken

    def write(self, text: str) -> int:
        if not self.broken:
            try:
                return self._stream.write(text)
            except UnicodeEncodeError:
                return self._write_escaped(text)
            except (OSError, ValueError) as error:  # ValueError: the stream was closed
                self._close(error)
        return len(text)

    def flush(self) -> None:
        if not self.broken:
            try:
                self._stream.flush()
            except (OSError, ValueError) as error:
                self._close(error)

    def _write_escaped(self, text: str) -> int:
        encoding = getattr(self._stream, "encoding", None) or "ascii"
        try:
            self._stream.write(text.encode(encoding, REPLACEMENT).decode(encoding))
        except (OSError, ValueError) as error:
            self._close(error)
        return len(text)

    def _close(self, error: BaseException) -> None:
        """From now on the stream's descriptor is the null device: what the stream still buffers, and the
        interpreter's own flush at exit, go nowhere instead of failing (Python exits 120 when that flush fails)."""
        self.broken = True
        with contextlib.suppress(OSError, ValueError, AttributeError):  # no descriptor: an in-memory stream
            _to_null(self._stream.fileno())
        if self._on_error is not None and getattr(error, "errno", None) not in (errno.EPIPE, errno.ECONNRESET):
            self._on_error(f"{error.__class__.__name__}: {error}")

    def __getattr__(self, name: str):
        return getattr(self._stream, name)


def _to_null(fd: int) -> None:
    """Point descriptor ``fd`` at the null device (open or not)."""
    null = os.open(os.devnull, os.O_WRONLY)
    if null != fd:
        os.dup2(null, fd)
        os.close(null)


def _closed_at_start(fd: int) -> None:
    """Python found descriptor ``fd`` closed: the null device takes it, so that no file opened later gets it
    (and receives what a child process writes to its stdout or stderr)."""
    with contextlib.suppress(OSError):
        os.fstat(fd)
        return  # open after all (an interpreter embedded without streams): leave it alone
    with contextlib.suppress(OSError):
        _to_null(fd)


def _safe(stream: TextIO | None, fd: int, on_error: Callable[[str], None] | None = None) -> ClosedPipeSafe:
    """``stream`` wrapped; a stream closed before the start (``None``) becomes one on the null device that drops
    everything written to it, yet answers ``isatty()``, ``fileno()``... as a stream does."""
    if stream is not None:
        return ClosedPipeSafe(stream, on_error)
    _closed_at_start(fd)
    return ClosedPipeSafe(open(os.devnull, "w", encoding="utf-8"), broken=True)  # noqa: SIM115 - closed at the end


@contextlib.contextmanager
def closed_pipe_safe() -> Iterator[None]:
    """Within the block, stdout and stderr never raise (see the module); at its end both are flushed, then
    they are what they were."""
    saved = sys.stdout, sys.stderr
    err = _safe(sys.stderr, 2)
    out = _safe(sys.stdout, 1, on_error=lambda why: print(f"topomark: output lost, stdout failed: {why}", file=err))
    sys.stdout, sys.stderr = out, err
    try:
        yield
    finally:
        out.flush()
        err.flush()
        sys.stdout, sys.stderr = saved
        for stream, was in ((out, saved[0]), (err, saved[1])):
            if was is None:
                stream.close()

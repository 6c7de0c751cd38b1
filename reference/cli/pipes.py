"""A verdict's exit code never depends on whether the reader is still listening.

``topomark conformance run … | head -1`` closes the pipe after one line; a later ``print`` would raise
:class:`BrokenPipeError` and unwind the command before it returns its verdict, and a failing program would
look like a passing one to a shell with ``pipefail``.  :class:`ClosedPipeSafe` wraps stdout (and stderr): once
a write or flush finds the pipe closed it sends that stream's file descriptor to the null device and drops the
rest of the output, so the command runs to its verdict and exits with its own code (0, 1, 2 or 3).  Nothing is
lost that anyone could read.

>>> import io
>>> class Closed(io.StringIO):
...     def write(self, s):
...         raise BrokenPipeError(32, "Broken pipe")
>>> out = ClosedPipeSafe(Closed())
>>> out.write("FAIL [map]\\n"), out.broken
(11, True)
>>> out.write("more"), out.broken  # dropped, silently
(4, True)
"""

from __future__ import annotations

import contextlib
import os
import sys
from typing import Iterator, TextIO

__all__ = ["ClosedPipeSafe", "closed_pipe_safe"]


class ClosedPipeSafe:
    """``stream``, except that a closed pipe drops the output instead of raising (:attr:`broken` says so)."""

    def __init__(self, stream: TextIO):
        self._stream = stream
        self.broken = False

    def write(self, text: str) -> int:
        if not self.broken:
            try:
                return self._stream.write(text)
            except BrokenPipeError:
                self._close()
        return len(text)

    def flush(self) -> None:
        if not self.broken:
            try:
                self._stream.flush()
            except BrokenPipeError:
                self._close()

    def _close(self) -> None:
        """From now on the stream's descriptor is the null device: what the stream still buffers, and the
        interpreter's own flush at exit, go nowhere instead of failing (Python exits 120 when that flush fails)."""
        self.broken = True
        with contextlib.suppress(OSError, ValueError, AttributeError):  # no descriptor: an in-memory stream
            fd = self._stream.fileno()
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, fd)
            os.close(null)

    def __getattr__(self, name: str):
        return getattr(self._stream, name)


@contextlib.contextmanager
def closed_pipe_safe() -> Iterator[None]:
    """Within the block, stdout and stderr survive a closed pipe; afterwards they are what they were."""
    saved = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = ClosedPipeSafe(sys.stdout), ClosedPipeSafe(sys.stderr)
    try:
        yield
    finally:
        sys.stdout, sys.stderr = saved

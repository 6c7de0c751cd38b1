"""Where an exploration's trace records go: a list, a file (streamed), a ring of the last few, or several.

:func:`~topomark.reference.run.explore.explore` hands every ``topomark/trace@1``
record (``spec/trace.md``) to a *sink* as soon as it is made, so a run keeps
only what its caller asked for: a long exploration written with
``--trace FILE`` streams its trace to the file instead of holding millions of
records in memory, and without ``--trace`` nothing but the last few records
(for a violation's diagnostic) is kept.

A sink is anything with ``emit(record)``; one that wants only some kinds of
record says so with an ``events`` attribute (a set of ``event`` names: the
header and end records always come), and explore then does not make the
others — a counting sink on a long run skips formatting every move.
:func:`trace_line` is the one
serialisation (keys sorted, no whitespace), so a streamed file is byte-for-byte
what :func:`~topomark.reference.trace.records.dump_trace` makes of the same records.

A trace whose header is known only when the run ends (``drive``: the header
gives the map's n and m) goes to a :class:`SpoolSink`: the records are
written to an unnamed temporary file as they come and copied, after the
header, into the named file at the end — memory stays constant either way.
"""

from __future__ import annotations

import json
import tempfile
from collections import deque
from pathlib import Path
from typing import IO, Protocol

from topomark.reference.files.outputs import check_output, guarded, open_output

__all__ = ["TraceSink", "ListSink", "RingSink", "FileSink", "SpoolSink", "TeeSink", "trace_line"]


def trace_line(record: dict) -> str:
    """One JSON Lines record: keys sorted, no whitespace, a newline — byte-for-byte reproducible."""
    return json.dumps(record, sort_keys=True, separators=(",", ":")) + "\n"


class TraceSink(Protocol):
    def emit(self, record: dict) -> None: ...


class ListSink:
    """Every record, in order, in ``records`` (what ``Outcome.trace`` holds)."""

    def __init__(self) -> None:
        self.records: list[dict] = []

    def emit(self, record: dict) -> None:
        self.records.append(record)


class RingSink:
    """The last ``size`` records only (``records``, oldest first)."""

    def __init__(self, size: int) -> None:
        self._ring: deque[dict] = deque(maxlen=size)

    def emit(self, record: dict) -> None:
        self._ring.append(record)

    @property
    def records(self) -> list[dict]:
        return list(self._ring)


class FileSink:
    """Each record written to ``path`` as it comes; an unwritable path is InvalidInput naming it (exit 2).

    The file is opened (and so checked) when the sink is made, before any exploring; use as a context
    manager or call :meth:`close`, which flushes and reports a failed final write (``/dev/full``).
    """

    def __init__(self, path: str | Path) -> None:
        self.path = path
        self._out = open_output(path)

    def emit(self, record: dict) -> None:
        self._out.write(trace_line(record))

    def close(self) -> None:
        self._out.close()

    def __enter__(self) -> "FileSink":
        return self

    def __exit__(self, *exc) -> None:
        self._out.__exit__(*exc)


class SpoolSink:
    """Records spooled as they come, written to ``path`` after a header made at the end (:meth:`finish`).

    The path is checked when the sink is made (an unwritable one is InvalidInput before any exploring).  The
    spool is an unnamed temporary file beside ``path`` (in the system's temporary directory if that directory
    cannot hold one), removed when the sink is closed, whatever happens.
    """

    def __init__(self, path: str | Path) -> None:
        check_output(path)
        self.path = path
        self._spool = self._open_spool(Path(path).parent)

    def _open_spool(self, directory: Path) -> IO[str]:
        try:
            return tempfile.TemporaryFile("w+", encoding="utf-8", newline="", dir=directory)
        except OSError:
            return guarded(self.path, lambda: tempfile.TemporaryFile("w+", encoding="utf-8", newline=""))

    def emit(self, record: dict) -> None:
        guarded(self.path, lambda: self._spool.write(trace_line(record)))

    def finish(self, header: dict, end: dict) -> None:
        """Write ``path``: ``header``, every record emitted, ``end``; then close the spool."""
        try:
            guarded(self.path, lambda: self._spool.seek(0))
            with open_output(self.path) as out:
                out.write(trace_line(header))
                while chunk := guarded(self.path, lambda: self._spool.read(1 << 20)):
                    out.write(chunk)
                out.write(trace_line(end))
        finally:
            self.close()

    def close(self) -> None:
        self._spool.close()

    def __enter__(self) -> "SpoolSink":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


class TeeSink:
    """Every record to each of ``sinks``."""

    def __init__(self, *sinks: TraceSink) -> None:
        self.sinks = sinks

    def emit(self, record: dict) -> None:
        for sink in self.sinks:
            sink.emit(record)

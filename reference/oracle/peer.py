"""A program spoken to over ``topomark/protocol@1`` on its stdin/stdout: never a hang, never a leak.

:class:`Peer` is a context manager; within ``with Peer(cmd, ...) as peer``
the program runs, and on leaving the block (success, failure, exception or
signal) the program and everything it started are killed
(:func:`topomark.reference.oracle.process_tree.kill_tree`: the process group, setsid
escapers and orphans, found through ``/proc`` with topomark as a child
subreaper).  Whatever the program does, the costs are bounded:

* **time** — every receive waits at most ``message_timeout`` and never past
  the ``wall`` deadline; every send waits at most as long for room in the
  pipe; killing never waits on a pipe (the readers poll a stop flag and the
  pipes are closed only after they stopped), so a descendant that keeps a
  pipe open cannot block topomark;
* **memory** — stdout is read in chunks of :data:`CHUNK` bytes; a line
  longer than :data:`~topomark.reference.oracle.protocol.MAX_LINE` is never
  accumulated (the reader stops and the receiver reports ``garbage``), and
  at most :data:`QUEUE_BYTES` of complete lines wait unread (then the reader
  stops reading, and the program blocks on its own write); stderr keeps only
  the last :data:`TAIL_LINES` lines, each clipped to :data:`TAIL_CHARS`;
* **signals** — while a peer runs, SIGTERM and SIGHUP kill it (and its
  descendants) and exit topomark with 128 + the signal number and one line
  on stderr; the previous handlers are restored when the block ends.
  (SIGINT raises KeyboardInterrupt, which leaves the block like any error.)
"""

from __future__ import annotations

import os
import queue
import select
import signal
import subprocess
import threading
import time
import uuid
from collections import deque
from typing import Any, Sequence

from topomark.spec.errors import InvalidInput

from topomark.reference.oracle.process_tree import MARKER, kill_tree, subreaper
from topomark.reference.oracle.protocol import MAX_LINE, ProtocolError, decode, encode

__all__ = ["Peer", "CHUNK", "QUEUE_BYTES", "TAIL_LINES", "TAIL_CHARS"]

CHUNK = 1 << 16
QUEUE_BYTES = MAX_LINE  # complete lines waiting to be received, at most (plus the one that crossed it)
TAIL_LINES, TAIL_CHARS = 20, 500
_POLL = 0.1  # seconds between checks of the stop flag by the readers
_TOO_LONG, _EOF = object(), object()  # markers the stdout reader queues after the lines
_SIGNALS = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))


class _Lines:
    """Complete stdout lines (and the ``_TOO_LONG`` / ``_EOF`` markers), bounded in bytes; the reader waits for room."""

    def __init__(self) -> None:
        self._items: deque = deque()
        self._bytes = 0
        self._cond = threading.Condition()

    def put(self, item: Any, stop: threading.Event) -> bool:
        with self._cond:
            while self._bytes >= QUEUE_BYTES:
                if stop.is_set():
                    return False
                self._cond.wait(_POLL)
            self._items.append(item)
            self._bytes += _size(item)
            self._cond.notify_all()
        return True

    def get(self, timeout: float) -> Any:
        with self._cond:
            if not self._cond.wait_for(lambda: self._items, timeout):
                raise queue.Empty
            item = self._items.popleft()
            self._bytes -= _size(item)
            self._cond.notify_all()
            return item


def _ready(fd: int, event: int, timeout: float) -> bool:
    """True when ``fd`` is ready for ``event`` (or at its end: a hang-up or an error) within ``timeout`` seconds."""
    poller = select.poll()
    poller.register(fd, event)
    return bool(poller.poll(timeout * 1000))


def _size(item: Any) -> int:
    return (len(item) if isinstance(item, bytes) else 0) + 64


class _Tail:
    """The last lines of stderr, each clipped; a line without end is never held whole."""

    def __init__(self) -> None:
        self.lines: deque[str] = deque(maxlen=TAIL_LINES)
        self._head = bytearray()  # the first TAIL_CHARS bytes of the current line
        self._length = 0  # bytes in the current line so far

    def feed(self, chunk: bytes) -> None:
        *ended, rest = chunk.split(b"\n")
        for part in ended[:1] + ended[1:][-TAIL_LINES:]:  # older lines would drop out anyway
            self._add(part)
            self._end_line()
        self._add(rest)

    def _add(self, piece: bytes) -> None:
        self._head += piece[:max(0, TAIL_CHARS + 4 - len(self._head))]
        self._length += len(piece)

    def _end_line(self) -> None:
        self.lines.append(self._text())
        self._head.clear()
        self._length = 0

    def _text(self) -> str:
        text = self._head.decode("utf-8", "replace").rstrip("\r")
        if self._length <= TAIL_CHARS:
            return text
        return text[:TAIL_CHARS] + f"... ({self._length:,} bytes)"

    def snapshot(self) -> list[str]:
        return list(self.lines) + ([self._text()] if self._length else [])


class Peer:
    """A program spoken to over stdin/stdout; stderr is kept (its tail goes into verdicts).

    ``wall`` bounds the whole session from the start of the program: every
    receive after it fails with kind ``timeout``; ``message_timeout`` bounds
    each wait.  Use as a context manager (see the module docstring).
    """

    def __init__(self, command: Sequence[str], message_timeout: float = 10.0, wall: float = 60.0,
                 cwd: str | None = None):
        if not command:
            raise InvalidInput("no command given after --")
        self.command, self.cwd = list(command), cwd
        self.message_timeout, self.wall = message_timeout, wall
        self.deadline = time.monotonic() + wall
        self.received = 0
        self.proc: subprocess.Popen | None = None
        self._token = uuid.uuid4().hex
        self._lines, self._tail = _Lines(), _Tail()
        self._stop = threading.Event()
        self._threads: list[threading.Thread] = []
        self._saved: dict[int, Any] = {}
        self._reaping = False  # holding the subreaper (between start and kill)

    # -- lifetime -----------------------------------------------------------------
    def __enter__(self) -> "Peer":
        self._install_handlers()  # before the start: a signal can never leave an unkilled program behind
        try:
            self._start()
        except BaseException:
            self._restore_handlers()
            raise
        return self

    def __exit__(self, *exc: Any) -> None:
        try:
            self.kill()
        finally:
            self._restore_handlers()

    def _start(self) -> None:
        subreaper.acquire()
        self._reaping = True
        env = {**os.environ, MARKER: self._token}
        try:
            self.proc = subprocess.Popen(self.command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, start_new_session=True, cwd=self.cwd, env=env)
        except (OSError, ValueError) as exc:
            self._release()
            raise InvalidInput(f"cannot start {self.command[0]!r}: "
                               f"{getattr(exc, 'strerror', None) or exc}") from None
        self.deadline = time.monotonic() + self.wall
        for target, stream in ((self._read_stdout, self.proc.stdout), (self._read_stderr, self.proc.stderr)):
            thread = threading.Thread(target=target, args=(stream.fileno(),), daemon=True)
            thread.start()
            self._threads.append(thread)

    def _install_handlers(self) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        for signum in _SIGNALS:
            self._saved[signum] = signal.signal(signum, self._on_signal)

    def _restore_handlers(self) -> None:
        for signum, handler in self._saved.items():
            signal.signal(signum, handler if handler is not None else signal.SIG_DFL)
        self._saved.clear()

    def _on_signal(self, signum: int, frame: Any) -> None:
        self.kill()
        name = signal.Signals(signum).name
        os.write(2, f"topomark: {name} received: the program and everything it started were killed\n".encode())
        raise SystemExit(128 + signum)

    # -- readers ------------------------------------------------------------------
    def _chunks(self, fd: int):
        """The data on ``fd`` in chunks, until EOF or the stop flag; never blocks longer than ``_POLL``."""
        while not self._stop.is_set():
            try:
                if not _ready(fd, select.POLLIN, _POLL):
                    continue
                chunk = os.read(fd, CHUNK)
            except (OSError, ValueError):
                return
            if not chunk:
                return
            yield chunk

    def _read_stdout(self, fd: int) -> None:
        partial = bytearray()
        for chunk in self._chunks(fd):
            start = 0
            while (end := chunk.find(b"\n", start)) >= 0 and len(partial) + end - start < MAX_LINE:
                partial += chunk[start:end + 1]
                if not self._lines.put(bytes(partial), self._stop):
                    return
                partial.clear()
                start = end + 1
            partial += chunk[start:]
            if len(partial) > MAX_LINE:  # never held whole: the rest cannot matter, stop reading
                self._lines.put(_TOO_LONG, self._stop)
                return
        self._lines.put(_EOF, self._stop)

    def _read_stderr(self, fd: int) -> None:
        for chunk in self._chunks(fd):
            self._tail.feed(chunk)

    # -- messages -----------------------------------------------------------------
    def send(self, msg: dict[str, Any], timeout: float | None = None) -> None:
        """Write one message without ever blocking for long.

        A closed pipe means the program died (kind ``crash``); a pipe that stays
        full for ``timeout`` (default ``message_timeout``) means it stopped reading
        (kind ``timeout``).
        Writes go in chunks of at most PIPE_BUF bytes once ``poll`` reports
        the pipe writable, so a single write cannot block.
        """
        data = encode(msg).encode()
        try:
            fd = self.proc.stdin.fileno()
            while data:
                limit = self.message_timeout if timeout is None else timeout
                wait = max(0.0, min(limit, self.deadline - time.monotonic()))
                if not _ready(fd, select.POLLOUT, wait):
                    raise ProtocolError("timeout", f"the program stopped reading its input (no room in the pipe "
                                                   f"for {wait:g} s)")
                data = data[os.write(fd, data[:select.PIPE_BUF]):]
        except (BrokenPipeError, OSError, ValueError):
            raise ProtocolError("crash", self._died("stopped reading its input")) from None

    def receive(self, expect: Sequence[str] | None = None) -> dict[str, Any]:
        """The next message, validated; raises :class:`ProtocolError` on timeout, EOF or garbage."""
        remaining = self.deadline - time.monotonic()
        if remaining <= 0:
            raise ProtocolError("timeout", f"wall-time limit of {self.wall:g} s exceeded")
        wait = min(self.message_timeout, remaining)
        try:
            item = self._lines.get(wait)
        except queue.Empty:
            if wait < self.message_timeout:
                raise ProtocolError("timeout", f"wall-time limit of {self.wall:g} s exceeded") from None
            raise ProtocolError("timeout", f"no message within {self.message_timeout:g} s "
                                           f"(after {self.received} messages)") from None
        if item is _EOF:
            raise ProtocolError("crash", self._died("closed its output"))
        self.received += 1
        if item is _TOO_LONG:
            raise ProtocolError("garbage", f"message {self.received} is longer than {MAX_LINE} bytes")
        try:
            line = item.decode("utf-8")
        except UnicodeDecodeError:
            raise ProtocolError("garbage", f"message {self.received} is not UTF-8") from None
        return decode(line, expect)

    def _died(self, what: str) -> str:
        try:
            code = self.proc.wait(timeout=1.0)
        except subprocess.TimeoutExpired:
            code = None
        time.sleep(0.05)  # let the stderr reader catch up
        tail = " | ".join(self.stderr_tail()[-3:])
        status = "still running" if code is None else f"exit status {code}"
        return f"the program {what} ({status})" + (f"; stderr: {tail}" if tail else "")

    def finish(self, grace: float = 2.0) -> int | None:
        """Close stdin and give the program ``grace`` seconds to exit (the ``with`` block then kills the rest)."""
        try:
            self.proc.stdin.close()
        except OSError:
            pass
        try:
            return self.proc.wait(timeout=grace)
        except subprocess.TimeoutExpired:
            return None

    def kill(self) -> None:
        """Kill the program and everything it started; never blocks on a pipe (safe to call again)."""
        if self.proc is None:
            return
        kill_tree(self.proc.pid, self._token, exclude=self.proc.pid)
        try:
            self.proc.wait(timeout=5.0)
        except subprocess.TimeoutExpired:
            pass
        self._release()
        if self._threads:
            self._threads[1].join(0.5)  # every writer is dead: let stderr drain to EOF, briefly
        self._stop.set()
        for thread in self._threads:
            thread.join(2 * _POLL + 1.0)
        for stream in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            try:
                stream.close()
            except OSError:
                pass

    def _release(self) -> None:
        if self._reaping:
            self._reaping = False
            subreaper.release()

    def stderr_tail(self) -> list[str]:
        return self._tail.snapshot()

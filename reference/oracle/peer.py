"""A program spoken to over ``topomark/protocol@1`` on its stdin/stdout: never a hang, never a leak.

:class:`Peer` is a context manager; within ``with Peer(cmd, ...) as peer``
the program runs, and on leaving the block (success, failure, exception or
signal) the program and everything it started are killed
(:func:`topomark.reference.oracle.process_tree.kill_tree`: the process group, setsid
escapers and orphans, found through ``/proc`` with topomark as a child
subreaper).  Whatever the program does, the costs are bounded:

* **time** — the program's time is the time topomark waits for it: for its
  next message in :meth:`Peer.receive`, for room in its input pipe in
  :meth:`Peer.send` (:attr:`Peer.waited`).  Every receive waits at most
  ``message_timeout``, and all waits together at most ``wall``; what topomark
  does between them (checking a snapshot, judging the map) is topomark's
  time and counts against neither.  A program that keeps topomark busy
  without ever making it wait (messages sent ahead of their answers) is
  stopped by a ceiling on the whole session, :data:`CEILING` × ``wall``
  (kind ``limit``).  Stdout is read by the receiving thread itself, only
  when it needs the next line (a hand-over from a reader thread would cost
  every message a wake-up, which is waiting charged to the program).
  Killing never waits on a pipe (the stderr reader polls a stop flag and the
  pipes are closed only after it stopped), so a descendant that keeps a pipe
  open cannot block topomark;
* **memory** — stdout is read in chunks of :data:`CHUNK` bytes, and only
  while no complete line is buffered; a line longer than
  :data:`~topomark.reference.oracle.protocol.MAX_LINE` is never accumulated
  (it is ``garbage`` once that much of it is in), so at most
  :data:`QUEUE_BYTES` wait unread (the program then blocks on its own
  write); stderr keeps only the last :data:`TAIL_LINES` lines, each clipped
  to :data:`TAIL_CHARS`;
* **signals** — while a peer runs, SIGTERM and SIGHUP kill it (and its
  descendants) and exit topomark with 128 + the signal number and one line
  on stderr; the previous handlers are restored when the block ends.
  (SIGINT raises KeyboardInterrupt, which leaves the block like any error.)
"""

from __future__ import annotations

import os
import select
import signal
import subprocess
import threading
import time
import uuid
from collections import deque
from typing import IO, Any, Sequence, cast

from topomark.spec.errors import InvalidInput

from topomark.reference.oracle.process_tree import MARKER, kill_tree, subreaper
from topomark.reference.oracle.protocol import MAX_LINE, ProtocolError, decode, encode

__all__ = ["Peer", "CHUNK", "QUEUE_BYTES", "TAIL_LINES", "TAIL_CHARS", "CEILING"]

CHUNK = 1 << 16
QUEUE_BYTES = MAX_LINE + CHUNK  # bytes of stdout read but not yet received, at most
TAIL_LINES, TAIL_CHARS = 20, 500
CEILING = 10  # the whole session (the program's time and topomark's) ends at CEILING x wall, at most
_POLL = 0.1  # seconds between checks of the stop flag by the stderr reader
_SIGNALS = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))


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

    ``wall`` bounds the program's time, :attr:`waited` (the time spent
    waiting for it); a receive or send that would wait past it fails with kind
    ``timeout``; ``message_timeout`` bounds each wait.  The whole session
    ends at :data:`CEILING` × ``wall`` (kind ``limit``).  Use as a context
    manager (see the module docstring).
    """

    def __init__(self, command: Sequence[str], message_timeout: float = 10.0, wall: float = 60.0,
                 cwd: str | None = None):
        if not command:
            raise InvalidInput("no command given after --")
        self.command, self.cwd = list(command), cwd
        self.message_timeout, self.wall = message_timeout, wall
        self.started = time.monotonic()
        self.waited = 0.0  # seconds spent waiting for the program: its time, bounded by ``wall``
        self.received = 0
        self.proc: subprocess.Popen | None = None
        self._token = uuid.uuid4().hex
        self._buffer, self._eof, self._tail = bytearray(), False, _Tail()
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
        self.started = time.monotonic()
        thread = threading.Thread(target=self._read_stderr, args=(self._pipes()[2].fileno(),), daemon=True)
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

    def _read_stderr(self, fd: int) -> None:
        for chunk in self._chunks(fd):
            self._tail.feed(chunk)

    # -- messages -----------------------------------------------------------------
    def send(self, msg: dict[str, Any], timeout: float | None = None) -> None:
        """Write one message without ever blocking for long.

        A closed pipe means the program died (kind ``crash``); a pipe that stays
        full for ``timeout`` (default ``message_timeout``) means it stopped reading
        (kind ``timeout``).  The wait for room is the program's time (:attr:`waited`).
        Writes go in chunks of at most PIPE_BUF bytes once ``poll`` reports
        the pipe writable, so a single write cannot block.
        """
        data = encode(msg).encode()
        try:
            fd = self._pipes()[0].fileno()
            while data:
                wait = self._allowed(self.message_timeout if timeout is None else timeout)
                began = time.monotonic()
                try:
                    ready = _ready(fd, select.POLLOUT, wait)
                finally:
                    self.waited += time.monotonic() - began
                if not ready:
                    raise ProtocolError("timeout", f"the program stopped reading its input (no room in the pipe "
                                                   f"for {wait:g} s)")
                data = data[os.write(fd, data[:select.PIPE_BUF]):]
        except (BrokenPipeError, OSError, ValueError):
            raise ProtocolError("crash", self._died("stopped reading its input")) from None

    def receive(self, expect: Sequence[str] | None = None) -> dict[str, Any]:
        """The next message, validated; raises :class:`ProtocolError` on timeout, EOF or garbage."""
        wait = self._allowed(self.message_timeout)
        began = time.monotonic()
        try:
            item = self._next_line(began + wait)
        finally:
            self.waited += time.monotonic() - began
        if item is None:
            if wait < self.message_timeout:
                self._allowed(0.0)  # the wall or the ceiling ran out: raises saying which
                raise ProtocolError("timeout", self._over_wall())
            raise ProtocolError("timeout", f"no message within {self.message_timeout:g} s "
                                           f"(after {self.received} messages)")
        try:
            line = item.decode("utf-8")
        except UnicodeDecodeError:
            raise ProtocolError("garbage", f"message {self.received} is not UTF-8") from None
        return decode(line, expect)

    def _next_line(self, until: float) -> bytes | None:
        """The next complete stdout line, read in this thread (no hand-over between threads, which would cost
        each message a wake-up); None if none came by ``until``.  A line longer than MAX_LINE is never held
        whole: it is ``garbage`` as soon as its first MAX_LINE bytes are in."""
        while True:
            end = self._buffer.find(b"\n", 0, MAX_LINE + 1)
            if end >= 0:
                line = bytes(self._buffer[:end + 1])
                del self._buffer[:end + 1]
                self.received += 1
                return line
            if len(self._buffer) > MAX_LINE:
                self.received += 1
                raise ProtocolError("garbage", f"message {self.received} is longer than {MAX_LINE} bytes")
            if self._eof:
                raise ProtocolError("crash", self._died("closed its output"))
            fd = self._pipes()[1].fileno()
            if not _ready(fd, select.POLLIN, max(0.0, until - time.monotonic())):
                return None
            try:
                chunk = os.read(fd, CHUNK)
            except OSError:
                chunk = b""
            self._eof = not chunk
            self._buffer += chunk

    def _allowed(self, limit: float) -> float:
        """How long the next wait may last: ``limit``, within what is left of the program's ``wall``; raises
        :class:`ProtocolError` when nothing is left (``timeout``) or the session passed its ceiling (``limit``)."""
        if self.waited >= self.wall:
            raise ProtocolError("timeout", self._over_wall())
        elapsed = time.monotonic() - self.started
        if elapsed >= CEILING * self.wall:
            raise ProtocolError("limit", f"the session ran {elapsed:.1f} s, the ceiling of {CEILING} x the time "
                                         f"limit of {self.wall:g} s (the program {self.waited:.1f} s, topomark's "
                                         f"checking {elapsed - self.waited:.1f} s: a program that sends messages "
                                         f"ahead of their answers keeps topomark busy without making it wait); a "
                                         f"larger --timeout raises the ceiling")
        return max(0.0, min(limit, self.wall - self.waited, CEILING * self.wall - elapsed))

    def _over_wall(self) -> str:
        return (f"wall-time limit of {self.wall:g} s exceeded: topomark waited {self.waited:.1f} s for the program "
                f"(topomark's own {self.topomark_seconds():.1f} s of checking not counted)")

    def topomark_seconds(self) -> float:
        """Seconds since the program started that topomark did not spend waiting for it."""
        return max(0.0, time.monotonic() - self.started - self.waited)

    def _started(self) -> subprocess.Popen[bytes]:
        """The program, once started (every caller runs after :meth:`start`)."""
        return cast("subprocess.Popen[bytes]", self.proc)

    def _pipes(self) -> tuple[IO[bytes], IO[bytes], IO[bytes]]:
        """The program's stdin, stdout and stderr: pipes, opened with it."""
        proc = self._started()
        return cast(IO[bytes], proc.stdin), cast(IO[bytes], proc.stdout), cast(IO[bytes], proc.stderr)

    def _died(self, what: str) -> str:
        try:
            code = self._started().wait(timeout=1.0)
        except subprocess.TimeoutExpired:
            code = None
        time.sleep(0.05)  # let the stderr reader catch up
        tail = " | ".join(self.stderr_tail()[-3:])
        status = "still running" if code is None else f"exit status {code}"
        return f"the program {what} ({status})" + (f"; stderr: {tail}" if tail else "")

    def finish(self, grace: float = 2.0) -> int | None:
        """Close stdin and give the program ``grace`` seconds to exit (the ``with`` block then kills the rest)."""
        try:
            self._pipes()[0].close()
        except OSError:
            pass
        try:
            return self._started().wait(timeout=grace)
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
            self._threads[0].join(0.5)  # every writer is dead: let stderr drain to EOF, briefly
        self._stop.set()
        for thread in self._threads:
            thread.join(2 * _POLL + 1.0)
        for stream in self._pipes():
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

"""The explorer protocol ``topomark/protocol@1``: JSON Lines between a world and an explorer.

The thesis separates the robot from the world it explores (§3.1.1): the
robot only issues motions and marker operations and receives signatures.
This module turns that interface into a wire protocol (documented in
``spec/protocol.md``) so that topomark can play a world to another program
(``run-external``, :mod:`topomark.reference.external`) or drive another
program's world with the reference explorer (``drive``,
:mod:`topomark.reference.drive`).

Contents:

* :func:`encode` / :func:`decode` — one message per line, validated field by
  field against :data:`MESSAGES`;
* :class:`Peer` — a subprocess spoken to over pipes, with a reader thread,
  a per-message timeout, a wall-time deadline and a kill of the whole
  process group (no hangs, whatever the program does);
* :func:`snapshot_to_map` / :func:`map_to_snapshot` — (S, U) of §3.1.3 on
  the wire.
"""

from __future__ import annotations

import json
import os
import queue
import select
import signal
import subprocess
import threading
import time
from collections import deque
from dataclasses import dataclass
from typing import Any, Sequence

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.mapstate import PartialMap

__all__ = ["PROTOCOL", "MESSAGES", "ProtocolError", "encode", "decode", "Peer", "snapshot_to_map",
           "map_to_snapshot", "MAX_LINE"]

PROTOCOL = "topomark/protocol@1"
MAX_LINE = 4_000_000  # bytes; a longer line is garbage

_INT, _STR, _OBJ, _LIST = "integer", "string", "object", "list"
_OPT_INT = "integer or null"

# type -> {field: kind}; every listed field is required, no other field is allowed.
MESSAGES: dict[str, dict[str, str]] = {
    "hello": {"protocol": _STR, "role": _STR, "markers": _OBJ, "signature": _STR},
    "move": {"motion": _INT},
    "drop": {"direction": _OPT_INT},
    "signature": {"value": _STR},
    "snapshot": {"S": _OBJ, "U": _LIST},
    "map": {"world": _OBJ},
    "error": {"message": _STR},
    "bye": {},
}
_OPTIONAL: dict[str, dict[str, str]] = {
    "hello": {"limits": _OBJ},
    "snapshot": {"iteration": _INT},
    "signature": {"step": _INT},
    "bye": {"verdict": _STR, "cost": _INT, "message": _STR},
}


class ProtocolError(Exception):
    """The other side broke the protocol: ``kind`` is garbage, timeout, crash, limit or protocol."""

    def __init__(self, kind: str, message: str):
        super().__init__(message)
        self.kind = kind


def encode(msg: dict[str, Any]) -> str:
    return json.dumps(msg, sort_keys=True, separators=(",", ":")) + "\n"


def _is_kind(value: Any, kind: str) -> bool:
    if kind == _INT:
        return isinstance(value, int) and not isinstance(value, bool)
    if kind == _OPT_INT:
        return value is None or _is_kind(value, _INT)
    return isinstance(value, {_STR: str, _OBJ: dict, _LIST: list}[kind])


def decode(line: str, expect: Sequence[str] | None = None) -> dict[str, Any]:
    """Parse and validate one line; raises :class:`ProtocolError` (kind ``garbage``) on anything wrong."""
    text = line.strip()
    try:
        msg = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ProtocolError("garbage", f"not a JSON object: {_clip(text)!r} ({exc.msg})") from None
    if not isinstance(msg, dict) or not isinstance(msg.get("type"), str):
        raise ProtocolError("garbage", f"not a message (a JSON object with a string \"type\"): {_clip(text)!r}")
    kind = msg["type"]
    if kind not in MESSAGES:
        raise ProtocolError("garbage", f"unknown message type {kind!r} (known: {', '.join(MESSAGES)})")
    if expect is not None and kind not in expect:
        raise ProtocolError("protocol", f"unexpected message {kind!r} here (expected {' or '.join(expect)})")
    fields = {**MESSAGES[kind], **_OPTIONAL.get(kind, {})}
    for name, want in fields.items():
        if name in msg and not _is_kind(msg[name], want):
            raise ProtocolError("garbage", f"{kind}.{name} must be {want}, got {json.dumps(msg[name])}")
    missing = [f for f in MESSAGES[kind] if f not in msg]
    unknown = sorted(set(msg) - set(fields) - {"type"})
    if missing or unknown:
        what = f"missing field {missing[0]!r}" if missing else f"unknown field {unknown[0]!r}"
        raise ProtocolError("garbage", f"{kind} message: {what}")
    return msg


def _clip(text: str, limit: int = 120) -> str:
    return text if len(text) <= limit else text[:limit] + "..."


@dataclass
class _Eof:
    pass


class Peer:
    """A program spoken to over stdin/stdout; stderr is kept (its tail goes into verdicts).

    ``deadline`` is an absolute :func:`time.monotonic` time after which every
    receive fails with kind ``timeout``; ``message_timeout`` bounds each wait.
    """

    def __init__(self, command: Sequence[str], message_timeout: float = 10.0, wall: float = 60.0,
                 cwd: str | None = None):
        if not command:
            raise InvalidInput("no command given after --")
        try:
            self.proc = subprocess.Popen(list(command), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, start_new_session=True, cwd=cwd)
        except OSError as exc:
            raise InvalidInput(f"cannot start {command[0]!r}: {exc.strerror or exc}") from None
        self.message_timeout = message_timeout
        self.deadline = time.monotonic() + wall
        self.wall = wall
        self.lines: queue.Queue = queue.Queue()
        self.stderr: deque[str] = deque(maxlen=20)
        self.received = 0
        threading.Thread(target=self._read_stdout, daemon=True).start()
        threading.Thread(target=self._read_stderr, daemon=True).start()

    def _read_stdout(self) -> None:
        try:
            while True:
                raw = self.proc.stdout.readline(MAX_LINE + 1)
                if not raw:
                    break
                self.lines.put(raw)
        except (OSError, ValueError):
            pass
        self.lines.put(_Eof())

    def _read_stderr(self) -> None:
        try:
            for raw in self.proc.stderr:
                self.stderr.append(raw.decode("utf-8", "replace").rstrip("\n"))
        except (OSError, ValueError):
            pass

    def send(self, msg: dict[str, Any], timeout: float | None = None) -> None:
        """Write one message without ever blocking for long.

        A closed pipe means the program died (kind ``crash``); a pipe that stays
        full for ``timeout`` (default ``message_timeout``) means it stopped reading
        (kind ``timeout``).
        Writes go in chunks of at most PIPE_BUF bytes once ``select`` reports
        the pipe writable, so a single write cannot block.
        """
        data = encode(msg).encode()
        try:
            fd = self.proc.stdin.fileno()
            while data:
                limit = self.message_timeout if timeout is None else timeout
                wait = max(0.0, min(limit, self.deadline - time.monotonic()))
                if not select.select([], [fd], [], wait)[1]:
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
            item = self.lines.get(timeout=wait)
        except queue.Empty:
            if wait < self.message_timeout:
                raise ProtocolError("timeout", f"wall-time limit of {self.wall:g} s exceeded") from None
            raise ProtocolError("timeout", f"no message within {self.message_timeout:g} s "
                                           f"(after {self.received} messages)") from None
        if isinstance(item, _Eof):
            raise ProtocolError("crash", self._died("closed its output"))
        self.received += 1
        if len(item) > MAX_LINE:
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
        tail = " | ".join(list(self.stderr)[-3:])
        status = "still running" if code is None else f"exit status {code}"
        return f"the program {what} ({status})" + (f"; stderr: {tail}" if tail else "")

    def finish(self, grace: float = 2.0) -> int | None:
        """Close stdin, give the program ``grace`` seconds to exit, then kill its process group."""
        try:
            self.proc.stdin.close()
        except OSError:
            pass
        try:
            return self.proc.wait(timeout=grace)
        except subprocess.TimeoutExpired:
            self.kill()
            return None

    def kill(self) -> None:
        """Kill the program and everything it started (its own process group)."""
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
        try:
            self.proc.wait(timeout=5.0)
        except subprocess.TimeoutExpired:
            pass
        for stream in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            try:
                stream.close()
            except OSError:
                pass

    def stderr_tail(self) -> list[str]:
        return list(self.stderr)


# -- (S, U) on the wire -----------------------------------------------------------
def _dart(x: Any, what: str) -> tuple[int, int]:
    if not (isinstance(x, list) and len(x) == 2 and all(_is_kind(k, _INT) for k in x)):
        raise CheckFailure(f"{what} must be a map dart [vertex, exit], got {json.dumps(x)}")
    return (x[0], x[1])


def snapshot_to_map(S_obj: dict[str, Any], U: list[Any]) -> PartialMap:
    """Rebuild S and U from a snapshot; a malformed one raises :class:`CheckFailure` naming the defect.

    ``S`` is ``{"exits": [[dart-or-null, ...] per vertex], "marks": [{"vertex": v, "head": h}]}``.
    """
    exits = S_obj.get("exits")
    marks = S_obj.get("marks", [])
    if set(S_obj) - {"exits", "marks"} or not isinstance(exits, list) or not isinstance(marks, list):
        raise CheckFailure("snapshot S must be {\"exits\": [...], \"marks\": [...]}")
    S = PartialMap()
    for v, row in enumerate(exits):
        if not isinstance(row, list) or not row:
            raise CheckFailure(f"snapshot S.exits[{v}] must be a non-empty list (one entry per exit)")
        S.add_vertex(len(row))
    for v, row in enumerate(exits):
        for i, x in enumerate(row):
            if x is None:
                continue
            w, j = _dart(x, f"S.exits[{v}][{i}]")
            if not (0 <= w < len(exits) and 0 <= j < len(exits[w])) or exits[w][j] != [v, i]:
                raise CheckFailure(f"snapshot S: exit {i} of vertex {v} leads to {[w, j]}, "
                                   f"which does not lead back to {[v, i]}")
            if (v, i) < (w, j):
                S.add_edge((v, i), (w, j))
    for k, mark in enumerate(marks):
        if not (isinstance(mark, dict) and set(mark) == {"vertex", "head"} and _is_kind(mark["vertex"], _INT)
                and _is_kind(mark["head"], _OPT_INT) and 0 <= mark["vertex"] < S.n):
            raise CheckFailure(f"snapshot S.marks[{k}] must be {{\"vertex\": v, \"head\": exit or null}}")
        head = mark["head"]
        if head is not None and not 0 <= head < S.degree(mark["vertex"]):
            raise CheckFailure(f"snapshot S.marks[{k}]: head {head} is not an exit of vertex {mark['vertex']}")
        S.mark_vertex(mark["vertex"], head=head)
    S.unexplored = [_dart(x, f"U[{k}]") for k, x in enumerate(U)]
    return S


def map_to_snapshot(S: PartialMap) -> dict[str, Any]:
    """The ``snapshot`` message for (S, U)."""
    exits = [[None if S.arc((v, i)) is None else list(S.arc((v, i))) for i in range(S.degree(v))]
             for v in S.vertices]
    marks = [{"vertex": v, "head": S.vertex_mark(v).head} for v in S.vertices if S.vertex_mark(v)]
    return {"type": "snapshot", "S": {"exits": exits, "marks": marks}, "U": [list(d) for d in S.unexplored]}

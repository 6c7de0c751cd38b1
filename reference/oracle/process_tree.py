"""Finding and killing everything an external program started, whatever it forked.

A program run over the protocol (:class:`topomark.reference.oracle.peer.Peer`) is
started as the leader of a new session and process group, with the marker
variable :data:`MARKER` ``=<token>`` (a fresh random token) added to its
environment.  Killing only the group misses three kinds of descendants:

* the group outlives its leader: ``sh -c 'sleep 1000 & exit 0'`` leaves
  ``sleep`` in the group after ``sh`` exited (``killpg`` still reaches it —
  a group id stays valid while any member lives — so it is always sent);
* a child that calls ``setsid()`` leaves the group and the session;
* a double fork re-parents the grandchild away from the tree.

So on Linux, while a peer runs, topomark is a *child subreaper*
(``prctl(PR_SET_CHILD_SUBREAPER)``): orphans of the program re-parent to
topomark instead of to init, and stay findable.  :func:`kill_tree` then
walks ``/proc`` and kills, round after round until a scan finds nothing
alive, every process that is

1. in the program's process group or session, or
2. carries ``MARKER=<token>`` in its initial environment
   (``/proc/PID/environ``, readable for our own processes), or
3. a descendant (by parent pid) of one of those (the leader, a session
   leader, can leave neither its group nor its session),

and reaps those that are topomark's own (adopted) children.  A process
escapes only if it leaves the session, clears its environment *and* is
orphaned before the scan; on systems without ``/proc`` only the process
group is killed.
"""

from __future__ import annotations

import ctypes
import os
import signal
import sys
import threading
import time
from typing import Iterable

__all__ = ["MARKER", "subreaper", "kill_tree", "members"]

MARKER = "TOPOMARK_PEER"
_PR_SET_CHILD_SUBREAPER, _PR_GET_CHILD_SUBREAPER = 36, 37
_PROC = "/proc"


def _prctl():
    if not sys.platform.startswith("linux"):
        return None
    try:
        return ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return None


def _set_subreaper(on: bool) -> bool:
    """Set or clear this process's child-subreaper flag; returns the previous setting (False if unsupported)."""
    prctl = _prctl()
    if prctl is None:
        return False
    was = ctypes.c_int(0)
    prctl(_PR_GET_CHILD_SUBREAPER, ctypes.byref(was), 0, 0, 0)
    prctl(_PR_SET_CHILD_SUBREAPER, int(on), 0, 0, 0)
    return bool(was.value)


class _Subreaper:
    """Counted: topomark is a subreaper while at least one peer runs, and is restored as it was after the last."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._holders = 0
        self._was = False

    def acquire(self) -> None:
        with self._lock:
            if self._holders == 0:
                self._was = _set_subreaper(True)
            self._holders += 1

    def release(self) -> None:
        with self._lock:
            self._holders -= 1
            if self._holders == 0 and not self._was:
                _set_subreaper(False)


subreaper = _Subreaper()


def _table() -> dict[int, tuple[int, int, int, bool]]:
    """pid -> (parent pid, process group, session, is a zombie) for every process visible in /proc."""
    table: dict[int, tuple[int, int, int, bool]] = {}
    try:
        entries = os.listdir(_PROC)
    except OSError:
        return table
    for entry in entries:
        if not entry.isdigit():
            continue
        try:
            with open(f"{_PROC}/{entry}/stat", "rb") as fh:
                stat = fh.read()
            fields = stat[stat.rindex(b")") + 2:].split()
            table[int(entry)] = (int(fields[1]), int(fields[2]), int(fields[3]), fields[0] in (b"Z", b"X"))
        except (OSError, ValueError, IndexError):
            continue
    return table


def _tagged(pid: int, tag: bytes) -> bool:
    try:
        with open(f"{_PROC}/{pid}/environ", "rb") as fh:
            return tag in fh.read(1 << 20).split(b"\0")
    except OSError:
        return False


def members(leader: int, token: str, table: dict | None = None) -> set[int]:
    """The pids of the program started as ``leader`` with ``MARKER=token``, and of everything it started."""
    table = _table() if table is None else table
    me, tag = os.getpid(), f"{MARKER}={token}".encode()
    found = {pid for pid, (_, pgrp, sid, _) in table.items() if leader in (pgrp, sid)}
    found |= {pid for pid, (_, _, _, zombie) in table.items() if not zombie and pid not in found
              and pid != me and _tagged(pid, tag)}
    children: dict[int, list[int]] = {}
    for pid, (ppid, _, _, _) in table.items():
        children.setdefault(ppid, []).append(pid)
    stack = list(found)
    while stack:
        for child in children.get(stack.pop(), ()):
            if child not in found:
                found.add(child)
                stack.append(child)
    found.discard(me)
    return found


def _signal_all(pids: Iterable[int]) -> None:
    for pid in pids:
        try:
            os.kill(pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


def _reap(pids: Iterable[int], table: dict) -> None:
    """Collect the exit status of those ``pids`` that are our own (adopted) children, without blocking."""
    me = os.getpid()
    for pid in pids:
        if table.get(pid, (None,))[0] == me:
            try:
                os.waitpid(pid, os.WNOHANG)
            except ChildProcessError:
                pass


def kill_tree(leader: int, token: str, exclude: int | None = None, budget: float = 5.0) -> int:
    """SIGKILL the program's group and every member (see the module docstring); returns how many were found.

    ``exclude`` is a pid not to reap here (the leader, which its
    :class:`subprocess.Popen` reaps).  Scans repeat until none is alive or
    ``budget`` seconds have passed, so a process forked between a scan and
    the kill is caught by the next scan.
    """
    seen: set[int] = set()
    deadline = time.monotonic() + budget
    while True:
        try:
            os.killpg(leader, signal.SIGKILL)
        except (ProcessLookupError, PermissionError, OSError):
            pass
        table = _table()
        found = members(leader, token, table) if table else set()
        alive = {pid for pid in found if not table[pid][3]}
        _signal_all(alive)
        seen |= found
        _reap(found - {exclude}, table)
        if not alive or time.monotonic() > deadline:
            break
        time.sleep(0.01)
    time.sleep(0.02)  # the last ones killed become zombies of ours: collect them
    _reap(seen - {exclude}, _table())
    return len(seen)

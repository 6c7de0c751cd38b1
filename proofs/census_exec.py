"""Where the census's map and reduce tasks run, and its progress bar (thesis §3.2; the census of §3.3–§6.1).

An :class:`Executor` runs a list of calls ``(function, args)`` and yields
``(index, result)`` as they finish:

* ``jobs == 1`` and no scheduler — inline, in this process;
* ``jobs > 1`` — a pool of ``jobs`` local processes, which die with the
  process that started them: on Linux the kernel kills each when its parent
  dies (``prctl(PR_SET_PDEATHSIG)``), elsewhere each polls its parent every
  :data:`ORPHAN_POLL` seconds; so SIGKILL, SIGTERM or SIGHUP to the census
  leaves no worker behind.  Workers ignore SIGINT: the leader takes Ctrl-C
  (exit 130, as every command) and terminates them;
* ``scheduler="local"`` — a local Dask cluster of ``jobs`` worker processes;
* ``scheduler=ADDRESS`` — an existing Dask cluster (``dask scheduler`` /
  ``dask worker ADDRESS``).  Its workers must see the shard directory at the
  same path (a shared file system) and have topomark installed.  An address
  where no Dask scheduler completes the handshake within
  :data:`CONNECT_TIMEOUT` seconds (nothing listening, or a server that is not
  Dask and never answers) is bad input, and so is a scheduler that has no
  worker within :data:`WORKER_WAIT` seconds: nothing would ever run, and
  the census reached no verdict, so it is exit 2 (the address names a cluster
  that cannot run it), not 1 (a verdict).

Dask is optional (``pip install 'dask[distributed]'``, from a checkout ``pip install '.[cluster]'``); it is imported only
when a scheduler is asked for.

Examples
--------
>>> with executor(1, None) as ex:
...     sorted(ex.run([(pow, (2, 3)), (pow, (3, 2))]))
[(0, 8), (1, 9)]
"""

from __future__ import annotations

import asyncio
import contextlib
import ctypes
import logging
import multiprocessing
import os
import signal
import sys
import threading
import time
from typing import Any, Callable, Iterator

from topomark.spec.errors import InvalidInput
from topomark.spec.spelling import option

__all__ = ["Executor", "executor", "worker_count", "Progress", "CONNECT_TIMEOUT", "WORKER_WAIT", "ORPHAN_POLL",
           "die_with_leader"]

CONNECT_TIMEOUT = 5  # seconds to connect to a Dask scheduler and complete its handshake, all told
WORKER_WAIT = 60  # seconds a Dask scheduler may take to have its first worker
ORPHAN_POLL = 1.0  # seconds between a worker's checks that its leader lives, where PR_SET_PDEATHSIG is missing
_PR_SET_PDEATHSIG = 1
Call = tuple[Callable[..., Any], tuple]


class Executor:
    """Runs calls inline; subclasses run them elsewhere."""

    def run(self, calls: list[Call]) -> Iterator[tuple[int, Any]]:
        for i, (f, args) in enumerate(calls):
            yield i, f(*args)


def _watch(leader: int) -> None:
    while os.getppid() == leader:
        time.sleep(ORPHAN_POLL)
    os._exit(1)


def die_with_leader(leader: int) -> None:
    """A pool worker's initializer: die when process ``leader`` (its parent) dies; leave SIGINT to the leader."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    armed = False
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(None, use_errno=True)
            armed = libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0) == 0
    if os.getppid() != leader:  # the leader died before the signal was armed
        os._exit(1)
    if not armed:
        threading.Thread(target=_watch, args=(leader,), daemon=True).start()


def _call(item: tuple[int, Call]) -> tuple[int, Any]:
    i, (f, args) = item
    return i, f(*args)


class _Pool(Executor):
    def __init__(self, pool):
        self.pool = pool

    def run(self, calls: list[Call]) -> Iterator[tuple[int, Any]]:
        yield from self.pool.imap_unordered(_call, list(enumerate(calls)), chunksize=1)


class _Dask(Executor):
    def __init__(self, client):
        self.client = client

    def run(self, calls: list[Call]) -> Iterator[tuple[int, Any]]:
        from distributed import as_completed as dask_completed

        futures = {self.client.submit(f, *args, pure=False): i for i, (f, args) in enumerate(calls)}
        for fut in dask_completed(list(futures)):
            yield futures[fut], fut.result()


def _distributed():
    try:
        import distributed
    except ImportError:
        raise InvalidInput(f"{option('scheduler')} needs Dask: pip install 'dask[distributed]' (from a checkout: pip install '.[cluster]')") from None
    return distributed


@contextlib.contextmanager
def _dask(jobs: int, scheduler: str) -> Iterator[Executor]:
    distributed = _distributed()
    if scheduler == "local":
        with distributed.LocalCluster(n_workers=jobs, threads_per_worker=1, dashboard_address=None,
                                      silence_logs=logging.CRITICAL) as cluster, \
                distributed.Client(cluster) as client:  # silenced: workers log a closed scheduler on shutdown
            yield _Dask(client)
        return
    _handshake(scheduler)
    try:
        client = distributed.Client(scheduler, timeout=CONNECT_TIMEOUT)
    except Exception as e:  # OSError/TimeoutError when unreachable, ValueError/TypeError for a malformed address
        raise InvalidInput(f"cannot reach the Dask scheduler at {scheduler!r} within {CONNECT_TIMEOUT} s "
                           f"({type(e).__name__}: {str(e)[:200]})") from None
    with client:
        try:
            client.wait_for_workers(1, timeout=WORKER_WAIT)
        except TimeoutError:
            raise InvalidInput(f"the Dask scheduler at {scheduler!r} has had no worker for {WORKER_WAIT} s, so "
                               f"nothing would run; start one with: dask worker {scheduler}") from None
        yield _Dask(client)


def _handshake(address: str) -> None:
    """Connect to ``address`` and ask who it is, all within CONNECT_TIMEOUT; InvalidInput unless a Dask scheduler
    answers.  (``distributed.Client``'s own timeout does not cover a server that accepts and never answers.)"""
    from distributed.comm import connect

    async def identity():
        comm = await connect(address, timeout=CONNECT_TIMEOUT)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    def ask(box: dict) -> None:
        try:
            box["reply"] = asyncio.run(asyncio.wait_for(identity(), CONNECT_TIMEOUT))
        except BaseException as e:  # noqa: BLE001 - reported below as unreachable
            box["error"] = e

    box: dict[str, Any] = {}
    thread = threading.Thread(target=ask, args=(box,), daemon=True)  # its own event loop, whatever the caller runs
    thread.start()
    thread.join(CONNECT_TIMEOUT + 5)
    reply, error = box.get("reply"), box.get("error")
    if error is not None or thread.is_alive():
        why = "no answer" if error is None or isinstance(error, TimeoutError) else \
            f"{type(error).__name__}: {str(error)[:200]}"
        raise InvalidInput(f"cannot reach the Dask scheduler at {address!r} within {CONNECT_TIMEOUT} s ({why})")
    if not isinstance(reply, dict) or reply.get("type") != "Scheduler":
        raise InvalidInput(f"{address!r} answered, but not as a Dask scheduler ({str(reply)[:100]})")


def worker_count(jobs: int, tasks: int) -> int:
    """How many worker processes to start for ``tasks`` tasks when ``jobs`` are allowed: never more than there
    are tasks (an idle worker still costs a process), and at least 1.

    >>> worker_count(48, 12), worker_count(2, 12), worker_count(4, 0)
    (12, 2, 1)
    """
    return max(1, min(jobs, tasks))


@contextlib.contextmanager
def executor(jobs: int, scheduler: str | None, tasks: int | None = None) -> Iterator[Executor]:
    """The executor for ``jobs`` local processes, or for a Dask ``scheduler`` (an address or ``"local"``).

    With ``tasks`` (the most calls any one :meth:`Executor.run` will get), at most that many local workers start.
    """
    if jobs < 1:
        raise InvalidInput(f"{option('jobs')} must be at least 1, not {jobs}")
    if tasks is not None:
        jobs = worker_count(jobs, tasks)
    if scheduler is not None:
        with _dask(jobs, scheduler) as ex:
            yield ex
    elif jobs == 1:
        yield Executor()
    else:  # fork, as bench's pool: the workers start at once and need nothing pickled but the calls
        ctx = multiprocessing.get_context("fork" if "fork" in multiprocessing.get_all_start_methods() else None)
        with ctx.Pool(jobs, initializer=die_with_leader, initargs=(os.getpid(),)) as pool:
            yield _Pool(pool)  # leaving the block (a result, an error, Ctrl-C) terminates the workers


class Progress:
    """Worlds done, rate and time left, reported through ``sink`` at most every ``every`` seconds.

    Progress is counted in *estimated* worlds per map task (known before a
    task runs) for the bar and the time left, and in worlds for the count shown.
    """

    def __init__(self, estimated: int, sink: Callable[[str], None] | None, every: float = 2.0,
                 label: str = "census"):
        self.estimated, self.sink, self.every, self.label = max(estimated, 1), sink, every, label
        self.est_done = self.est_session = self.worlds = 0
        self.t0 = self.last = time.perf_counter()

    def skip(self, est: int, worlds: int) -> None:
        """A task finished by an earlier run (resumed)."""
        self.est_done += est
        self.worlds += worlds

    def done(self, est: int, worlds: int) -> None:
        self.est_done += est
        self.est_session += est
        self.worlds += worlds
        if time.perf_counter() - self.last >= self.every:
            self.report()

    def line(self) -> str:
        elapsed = max(time.perf_counter() - self.t0, 1e-9)
        frac = min(self.est_done / self.estimated, 1.0)
        bar = "#" * int(30 * frac) + "." * (30 - int(30 * frac))
        rate = self.est_session / elapsed
        left = (self.estimated - self.est_done) / rate if rate > 0 else float("inf")
        eta = "?" if left == float("inf") else f"{max(left, 0) / 60:.1f} min"
        return f"{self.label}: [{bar}] {self.count()}, {rate:,.1f} worlds/s, ~{eta} left"

    def count(self) -> str:
        """Worlds so far out of the estimate; once the count passes the estimate, the count alone.

        >>> p = Progress(2367, None); p.worlds = 2539; p.count()
        '2,539 worlds (more than the ~2,367 estimated)'
        """
        if self.worlds > self.estimated:
            return f"{self.worlds:,} worlds (more than the ~{self.estimated:,} estimated)"
        return f"{self.worlds:,}/~{self.estimated:,} worlds"

    def report(self) -> None:
        self.last = time.perf_counter()
        if self.sink is not None:
            self.sink(self.line())

    def finish(self) -> None:
        if self.sink is not None:
            elapsed = time.perf_counter() - self.t0
            self.sink(f"census: {self.worlds:,} worlds mapped ({elapsed:.1f} s this run); reducing the shards")

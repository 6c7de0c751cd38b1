"""Where the census's map and reduce tasks run, and its progress bar (thesis §3.2; the census of §3.3–§6.1).

An :class:`Executor` runs a list of calls ``(function, args)`` and yields
``(index, result)`` as they finish:

* ``jobs == 1`` and no scheduler — inline, in this process;
* ``jobs > 1`` — a pool of ``jobs`` local processes;
* ``scheduler="local"`` — a local Dask cluster of ``jobs`` worker processes;
* ``scheduler=ADDRESS`` — an existing Dask cluster (``dask scheduler`` /
  ``dask worker ADDRESS``).  Its workers must see the shard directory at the
  same path (a shared file system) and have topomark installed.  An address
  that does not answer within :data:`CONNECT_TIMEOUT` seconds is bad input.

Dask is optional (``pip install topomark[cluster]``); it is imported only
when a scheduler is asked for.

Examples
--------
>>> with executor(1, None) as ex:
...     sorted(ex.run([(pow, (2, 3)), (pow, (3, 2))]))
[(0, 8), (1, 9)]
"""

from __future__ import annotations

import contextlib
import logging
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any, Callable, Iterator

from topomark.spec.errors import InvalidInput

__all__ = ["Executor", "executor", "worker_count", "Progress", "CONNECT_TIMEOUT"]

CONNECT_TIMEOUT = 5  # seconds to reach a Dask scheduler
Call = tuple[Callable[..., Any], tuple]


class Executor:
    """Runs calls inline; subclasses run them elsewhere."""

    def run(self, calls: list[Call]) -> Iterator[tuple[int, Any]]:
        for i, (f, args) in enumerate(calls):
            yield i, f(*args)


class _Pool(Executor):
    def __init__(self, pool: ProcessPoolExecutor):
        self.pool = pool

    def run(self, calls: list[Call]) -> Iterator[tuple[int, Any]]:
        futures = {self.pool.submit(f, *args): i for i, (f, args) in enumerate(calls)}
        for fut in as_completed(futures):
            yield futures[fut], fut.result()


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
        raise InvalidInput("--scheduler needs Dask: pip install 'topomark[cluster]'") from None
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
    try:
        client = distributed.Client(scheduler, timeout=CONNECT_TIMEOUT)
    except Exception as e:  # OSError/TimeoutError when unreachable, ValueError/TypeError for a malformed address
        raise InvalidInput(f"cannot reach the Dask scheduler at {scheduler!r} within {CONNECT_TIMEOUT} s "
                           f"({type(e).__name__}: {str(e)[:200]})") from None
    with client:
        yield _Dask(client)


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
        raise InvalidInput(f"--jobs must be at least 1, not {jobs}")
    if tasks is not None:
        jobs = worker_count(jobs, tasks)
    if scheduler is not None:
        with _dask(jobs, scheduler) as ex:
            yield ex
    elif jobs == 1:
        yield Executor()
    else:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            yield _Pool(pool)


class Progress:
    """Worlds done, rate and time left, reported through ``sink`` at most every ``every`` seconds.

    Progress is counted in *estimated* worlds per map task (known before a
    task runs) for the bar and the time left, and in worlds for the count shown.
    """

    def __init__(self, estimated: int, sink: Callable[[str], None] | None, every: float = 2.0):
        self.estimated, self.sink, self.every = max(estimated, 1), sink, every
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
        return f"census: [{bar}] {self.count()}, {rate:,.1f} worlds/s, ~{eta} left"

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

"""Running a bench sweep: one checked exploration per planned run, in worker processes, appended to runs.csv.

Part of ``topomark bench`` (:mod:`~topomark.reference.bench.experiments`).  A run's row
records the world (n, m), the cost split by purpose, the explorer's counters,
the bounds, the wall and CPU time, whether it was checked and verified, and
the algorithm, edge policy and lighthouse it ran with.  Runs already in the
file (same key, :func:`~topomark.reference.bench.run_store.row_key`) are skipped.

A kit algorithm (§6.2: it carries its own markers, no lighthouse) runs with its
option set resolved against the world
(:func:`~topomark.reference.bench.plan.resolve_options`); its row adds the
outcome (correct / wrong-map / failed / limit), the markers used — the sum of
the counts the simulator dropped, as its ``op`` events say (:class:`DropCount`)
— the algorithm's stated marker bound for this n and m (``marker_bound``), the
cost bound of its registry entry (``upper_bound``, empty if it states none) and
the world's largest degree (``d_max``, for O(m·d_max)).

Chapter 5 (:mod:`~topomark.reference.bench.reports.chapter5`): a lighthouse algorithm's
option set sets its searched lighthouse's options (``seed=1``: the walk's
seed), and a row records :data:`CHAPTER_5_COLUMNS` where the run has them — the
walk's steps and the world vertex v0 became, and Algorithm 5.1's completed and
peak models and whether the true world is among the completed ones.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path
from typing import Any

from topomark.spec.errors import clip

from topomark.reference.bench.plan import Run, resolve_options, world_for
from topomark.reference.algorithms.bounds import expression_3_3
from topomark.reference.run.explore import explore
from topomark.reference.explorers.policies import Policies
from topomark.reference.explorers.lighthouses import lighthouse
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.bench.run_manifest import Manifest
from topomark.reference.bench.verdict import row_as_expected
from topomark.reference.bench.run_store import Appender, locked, read_runs, rewrite, row_key, write_manifest
from topomark.proofs.census_exec import die_with_leader, worker_count

__all__ = ["run_one", "run_sweep", "Progress", "DropCount", "CHAPTER_5_COLUMNS"]

ERROR_CHARS = 2000
"""A run's error message is clipped to this many characters in its row (the run store reads fields of at most
:data:`~topomark.reference.bench.run_store.MAX_FIELD_CHARS`)."""

CHAPTER_5_COLUMNS = ("walk_steps", "lighthouse_at", "completed_models", "peak_models", "true_world_completed")


class DropCount:
    """A trace sink that keeps only the markers dropped (less those picked up): the sum of the ``count`` of the
    simulator's ``op`` records (``spec/trace.md``), i.e. the markers lying in the world at the end."""

    events = frozenset({"op"})  # explore makes no move or iteration record for this sink

    def __init__(self) -> None:
        self.markers = 0

    def emit(self, record: dict) -> None:
        if record.get("event") == "op" and record.get("op") in ("drop", "pick_up"):
            self.markers += record.get("count", 1) * (1 if record["op"] == "drop" else -1)


def run_one(run: Run, check: bool = True) -> dict:
    t, cpu = time.perf_counter(), time.process_time()
    world = world_for(run.family, run.size, run.seed)
    row = {"experiment": run.family, "size": run.size, "seed": run.seed, "algorithm": run.algorithm,
           "policy": run.policy, "lighthouse": run.lighthouse, "options": run.options, "n": world.n, "m": world.m,
           "d_max": max(world.degree(v) for v in world.vertices), "checked": check, "error": ""}
    drops = None
    try:
        spec = algorithm_spec(run.algorithm)
        options = resolve_options(run.options, world, run.algorithm)
        kwargs: dict[str, Any] = {"sink": (drops := DropCount())}
        if spec.uses_lighthouse:  # a lighthouse algorithm's option set is its searched lighthouse's (seed=1)
            kwargs = {"lighthouse": lighthouse(run.lighthouse).with_options(
                **{k.replace("-", "_"): v for k, v in options.items()}) if options else run.lighthouse}
            options = {}
        out = explore(world, spec, Policies(edge=run.policy), check=check, record=False, keep_hypotheses=False,
                      options=options or None, **kwargs)
    except Exception as exc:  # a crashed run is recorded, never silently dropped
        row.update(cost="", verified=False, outcome="error", error=clip(f"{type(exc).__name__}: {exc}", ERROR_CHARS))
        return row
    stats = getattr(out.explorer, "stats", {})
    row.update(cost=out.cost, cost_per_m=round(out.cost / world.m, 3), verified=out.verified, outcome=out.outcome,
               hypotheses=out.hypotheses, upper_bound="" if out.upper_bound is None else out.upper_bound,
               expression_3_3=round(float(expression_3_3(world.n, world.m))),
               seconds=round(time.perf_counter() - t, 3), cpu_seconds=round(time.process_time() - cpu, 3),
               error=clip(str(out.violation) if out.violation is not None else out.reason or "", ERROR_CHARS))
    summary = out.summary()  # Chapter 5: the walk that found v0, where it is; the model tree's counts
    row.update({k: summary[k] for k in CHAPTER_5_COLUMNS if summary.get(k) is not None})
    if drops is not None and not spec.uses_lighthouse:
        row.update(markers_used=drops.markers, marker_bound=spec.marker_bound_fn(world.n, world.m)
                   if spec.marker_bound_fn else "")
    for p in ("travel", "new", "validation", "retrace", "expansion", "other"):
        row[p] = out.by_purpose.get(p, 0)
    row["drop_trips"] = out.drop_trips  # part of cost (the simulator's accounting rule)
    for s in ("pruned", "rejected_without_motion", "overlap_saved", "recorded"):
        row[s] = stats.get(s, 0)
    row["phase_two"] = stats.get("phase_two", "")  # Case 5: traversals testing phase II's hypotheses
    return row


def _worker(args):
    run, check = args
    return run_one(run, check)


class Progress:
    """A progress bar on stderr (a plain line per 5% when stderr is not a terminal)."""

    def __init__(self, total: int, enabled: bool = True):
        self.total, self.done, self.enabled = total, 0, enabled
        self.start = time.monotonic()
        self.tty = sys.stderr.isatty()
        self.last = -1

    def step(self, row: dict) -> None:
        self.done += 1
        if not self.enabled:
            return
        el = time.monotonic() - self.start
        eta = el / self.done * (self.total - self.done)
        pct = 100 * self.done // max(self.total, 1)
        width = 30
        fill = width * self.done // max(self.total, 1)
        line = (f"[{'#' * fill}{'.' * (width - fill)}] {self.done}/{self.total} runs  {el:6.0f}s elapsed  "
                f"~{eta:5.0f}s left  ({row['experiment']} {row['size']} {row['algorithm']})")
        if self.tty:
            sys.stderr.write("\r" + line[:150].ljust(150))
            if self.done == self.total:
                sys.stderr.write("\n")
        elif pct // 5 != self.last // 5 or self.done == self.total:
            sys.stderr.write(line + "\n")
        self.last = pct
        sys.stderr.flush()


def run_sweep(runs: list[Run], out: Path, jobs: int | None = None, check: bool = True, progress: bool = True,
              parameters: dict | None = None) -> dict:
    """Run what is not yet in ``out/runs.csv`` (append, one whole row per run); return counts.

    The directory is locked for the sweep (a second sweep on it is bad input, exit 2); the rows a killed sweep
    left damaged, and those that fail verification, are dropped with a note (and so run again), and the file is
    rewritten with every row's checksum before anything runs; the manifest ``out/runs.json`` records the sweep's
    ``parameters`` (:mod:`~topomark.reference.bench.run_store`, :mod:`~topomark.reference.bench.run_manifest`).
    """
    out.mkdir(parents=True, exist_ok=True)
    path = out / "runs.csv"
    started = time.monotonic()
    with locked(out):
        existing = read_runs(path, resume=True)
        manifest = existing.manifest or Manifest()
        manifest.add_sweep({**(parameters or {}), "check": check, "planned": len(runs)})
        manifest.rows = len(existing.rows)
        if existing.needs_rewrite and path.exists():  # adds checksums, drops what a resume left out
            rewrite(path, existing, manifest)
        write_manifest(out, manifest)
        # A checked sweep does not accept an unchecked row for the same key (it reruns it; the report then
        # prefers the checked row); an unchecked sweep accepts either.
        have = {row_key(r) for r in existing.rows if str(r.get("checked")) == "True" or not check}
        todo = [r for r in runs if r.key not in have]
        with Appender(path, manifest.store) as store:
            try:
                failures = _run_all(todo, store, jobs or os.cpu_count() or 1, check, Progress(len(todo), progress))
            finally:  # the rows now known to be in the file (a killed sweep leaves the count it started with)
                manifest.rows += store.appended
                write_manifest(out, manifest)
    return {"planned": len(runs), "skipped": len(runs) - len(todo), "ran": len(todo), "failures": failures,
            "seconds": round(time.monotonic() - started, 1)}


def _run_all(todo: list[Run], store: Appender, jobs: int, check: bool, bar: Progress) -> int:
    """Run ``todo`` (in ``jobs`` processes), appending each row as it finishes; the number whose outcome is not what
    its algorithm's entry expects (:mod:`~topomark.reference.bench.verdict`)."""
    failures = 0

    def emit(row):
        nonlocal failures
        store.append(row)
        if check and not row_as_expected(row):
            failures += 1
        bar.step(row)

    if jobs <= 1 or len(todo) <= 1:
        for r in todo:
            emit(run_one(r, check))
    else:
        import multiprocessing as mp
        ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else mp.get_context()
        # workers leave Ctrl-C to the leader (which reports it once) and die with it, as the census's do
        with ctx.Pool(worker_count(jobs, len(todo)), initializer=die_with_leader, initargs=(os.getpid(),)) as pool:
            for row in pool.imap_unordered(_worker, [(r, check) for r in todo], chunksize=1):
                emit(row)
    return failures

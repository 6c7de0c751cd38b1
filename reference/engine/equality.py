"""``python -m topomark.reference.engine.equality``: the engine's cross-check as a command (thesis §3.3).

Runs :mod:`.compare`'s comparison, for each ``--algorithm`` (repeatable;
default ``basic``; every algorithm the engine runs: :data:`ALGORITHMS`) with
``--lighthouse`` (default ``directional-vertex``; the footprint searches of
§6.2.1 use none), over the census's worlds with n ≤
``--max-vertices`` and degrees ≤ ``--max-degree`` and ``--random`` seeded
random worlds up to ``--random-max-vertices``, in ``--jobs`` processes, and
reports the number of run pairs compared per size and the time taken.

Exit 0: every pair agrees; 3: the engine and its reference disagree (each
disagreement named: world, start, policies, first differing action); 2: bad
input (one line, no traceback).  ``--json`` prints the report as JSON.  ``--shards DIR`` keeps each finished
task in DIR (:mod:`.equality_store`), and the same command run again resumes from it; ``seconds`` is then the
time of the last run only.
Without numba the engine's kernels run uncompiled, as plain Python (slow): the
comparison still checks their logic, and a notice on stderr says so.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path
from typing import Any, Callable

from topomark.spec.errors import InvalidInput

from topomark.reference.engine import ENGINE_ALGORITHMS, ENGINE_LIGHTHOUSES, FOOTPRINT_CASES, available, notice
from topomark.reference.engine.compare import census_cases, random_cases, run_cases
from topomark.reference.engine.equality_store import EqualityStore

__all__ = ["main", "check", "ALGORITHMS", "MAX_VERTICES", "MAX_RANDOM_VERTICES"]

ALGORITHMS = ENGINE_ALGORITHMS + FOOTPRINT_CASES
"""What ``--algorithm`` takes: every algorithm the engine runs (:func:`topomark.reference.engine.supports`)."""

MAX_VERTICES = 7
"""The largest ``--max-vertices``: n = 7 at degree ≤ 6 is already hours of reference runs."""
MAX_RANDOM_VERTICES = 500


def check(max_vertices: int, max_degree: int, randoms: int = 0, random_max: int = 60, seed: int = 0, jobs: int = 1,
          progress: Callable[[str], None] | None = None, algorithms: tuple[str, ...] = ("basic",),
          lighthouse: str = "directional-vertex", shards: Path | None = None) -> dict[str, Any]:
    """Compare the engine with the reference on every case, for each of ``algorithms`` (with ``lighthouse`` where
    the algorithm uses one); the report (counts per size and per algorithm, disagreements, seconds).  With
    ``shards`` each task's result is kept there (:class:`.equality_store.EqualityStore`) and a rerun with the
    same arguments resumes: only the tasks not yet finished run."""
    t0 = time.perf_counter()
    store = None if shards is None else EqualityStore(shards, {
        "max_vertices": max_vertices, "max_degree": max_degree, "random": randoms, "random_max_vertices": random_max,
        "seed": seed, "algorithms": list(algorithms), "lighthouse": lighthouse})
    cases: list[tuple] = [("census", units, max_degree) for units in census_cases(max_vertices, max_degree)]
    cases += [("random", text, starts) for text, starts in random_cases(randoms, random_max, seed)]
    jobs_list = [((*job, algorithm, lighthouse), algorithm) for algorithm in algorithms for job in cases]
    counts: dict[str, int] = {}
    per_algorithm: dict[str, int] = {}
    report: dict[str, Any] = {"worlds": 0, "disagreement_count": 0, "disagreements": [], "text": []}

    def take(result: dict[str, Any], algorithm: str, done: int) -> None:
        for group, count in result["counts"].items():
            counts[group] = counts.get(group, 0) + count
            per_algorithm[algorithm] = per_algorithm.get(algorithm, 0) + count
        if algorithm == algorithms[0]:  # the same worlds for every algorithm
            report["worlds"] += result["worlds"]
        report["disagreement_count"] += result["disagreement_count"]
        report["disagreements"] += result["disagreements"]
        report["text"] += result["disagreement_text"]
        if progress is not None:
            progress(f"equality: {done}/{len(jobs_list)} tasks, {sum(counts.values())} run pairs compared, "
                     f"{report['disagreement_count']} disagreeing, {time.perf_counter() - t0:.0f} s")

    kept = {} if store is None else store.finished(len(jobs_list), progress or (lambda _: None))
    for k, t in enumerate(sorted(kept)):
        take(kept[t], jobs_list[t][1], k + 1)
    todo = [t for t in range(len(jobs_list)) if t not in kept]

    def finish(t: int, result: dict[str, Any], done: int) -> None:
        if store is not None:
            store.save(t, result)
        take(result, jobs_list[t][1], done)

    if jobs == 1:
        for k, t in enumerate(todo):
            finish(t, run_cases(jobs_list[t][0]), len(kept) + k + 1)
    else:
        with ProcessPoolExecutor(jobs) as pool:  # as each task finishes, so the progress line is current
            futures = {pool.submit(run_cases, jobs_list[t][0]): t for t in todo}
            for k, future in enumerate(as_completed(futures)):
                finish(futures[future], future.result(), len(kept) + k + 1)
    report.update(algorithms=list(algorithms), lighthouse=lighthouse, compared=sum(counts.values()),
                  tasks=len(jobs_list), resumed=len(kept),
                  by_group=dict(sorted(counts.items())), by_algorithm={a: per_algorithm.get(a, 0) for a in algorithms},
                  seconds=round(time.perf_counter() - t0, 1), disagreements=report["disagreements"][:20],
                  text=report["text"][:20])
    return report


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m topomark.reference.engine.equality",
                                description="Compare the compiled Algorithm 3.1 with the reference, run by run.")
    p.add_argument("--algorithm", action="append", choices=ALGORITHMS, metavar="NAME",
                   help=f"compare this algorithm (repeatable; default basic; one of {', '.join(ALGORITHMS)})")
    p.add_argument("--lighthouse", choices=ENGINE_LIGHTHOUSES, default="directional-vertex",
                   help="the lighthouse of the lighthouse algorithms (default directional-vertex; the footprint "
                        "searches use none)")
    p.add_argument("--max-vertices", type=int, default=5, help="census worlds with n <= this (default 5)")
    p.add_argument("--max-degree", type=int, default=4, help="and degrees <= this (default 4)")
    p.add_argument("--random", type=int, default=0, help="this many seeded random worlds too (default 0)")
    p.add_argument("--random-max-vertices", type=int, default=60, help="their largest n (default 60)")
    p.add_argument("--seed", type=int, default=0, help="seed of the random worlds and their starts")
    p.add_argument("--jobs", type=int, default=1, help="processes (default 1)")
    p.add_argument("--shards", metavar="DIR", help="keep each finished task's result in DIR, and resume from it: "
                   "run again with the same options and only the unfinished tasks run")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("--quiet", action="store_true", help="no progress lines (by default one on stderr after each "
                   "task, with --json too)")
    return p


def _validate(args: argparse.Namespace) -> None:
    if not 2 <= args.max_vertices <= MAX_VERTICES:
        raise InvalidInput(f"--max-vertices must be between 2 and {MAX_VERTICES}, not {args.max_vertices}")
    if args.max_degree < 2:
        raise InvalidInput(f"--max-degree must be at least 2, not {args.max_degree}")
    if args.random < 0 or not 10 <= args.random_max_vertices <= MAX_RANDOM_VERTICES:
        raise InvalidInput(f"--random must be at least 0 and --random-max-vertices between 10 and "
                           f"{MAX_RANDOM_VERTICES}")
    if args.jobs < 1:
        raise InvalidInput(f"--jobs must be at least 1, not {args.jobs}")


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        _validate(args)
    except InvalidInput as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if not available():
        print(notice(uncompiled=True), file=sys.stderr)
    # progress on stderr even with --json (the report is stdout's): a long comparison is never silent
    progress = None if args.quiet else (lambda line: print(line, file=sys.stderr, flush=True))
    try:
        report = check(args.max_vertices, min(args.max_degree, args.max_vertices - 1), args.random,
                       args.random_max_vertices, args.seed, args.jobs, progress,
                       tuple(dict.fromkeys(args.algorithm or ["basic"])), args.lighthouse,
                       None if args.shards is None else Path(args.shards).absolute())
    except InvalidInput as exc:  # a --shards directory of another comparison, or one that cannot be made
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.json:
        print(json.dumps({k: v for k, v in report.items() if k != "text"}, sort_keys=True))
    else:
        sizes = ", ".join(f"{g}: {c}" for g, c in report["by_group"].items())
        algorithms = ", ".join(f"{a}: {c}" for a, c in report["by_algorithm"].items())
        print(f"{', '.join(report['algorithms'])} with {args.lighthouse}: {report['compared']} run pairs compared on "
              f"{report['worlds']} worlds ({sizes}; {algorithms}) in "
              f"{report['seconds']} s; {report['disagreement_count']} disagree"
              + (f" ({report['resumed']} of {report['tasks']} tasks resumed from {args.shards})"
                 if report["resumed"] else ""))
    if report["disagreement_count"]:
        print("topomark failed: its compiled engine and its reference disagree (its own checks disagree):",
              file=sys.stderr)
        for line in report["text"]:
            print(f"  {line}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":  # pragma: no cover - the command, tested through main()
    sys.exit(main())

"""``topomark bench``: the thesis's experiments (Figures 3.10-3.12, Tables 4.1-4.8, the lighthouses, Tables 6.1-6.2
and Figures 6.11-6.13, 6.17, 6.18), checked and resumable."""

from __future__ import annotations

import json
import time
from typing import Any

from topomark.spec.errors import InvalidInput, unknown_name

from topomark.reference.bench.reports.plots import INSTALL_HINT
from topomark.reference.bench.verdict import judge_plan
from topomark.reference.bench.experiments import EXPERIMENTS, HEAVY_GRAPHS, HEAVY_MAX_SIZE, plan, run_sweep, write_report
from topomark.reference.files.outputs import check_output_dir
from topomark.reference.cli.args import MAX_JOBS, check_jobs

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser(
        "bench",
        description="Run EXPERIMENT over fixed-seed worlds, every run checked (invariants after every iteration, "
                    "final isomorphism) unless --no-check; append each run to DIR/runs.csv (a restarted sweep "
                    "skips finished runs; one sweep at a time per DIR) and write DIR/EXPERIMENT.md and plots. "
                    "DIR/runs.json records each sweep's parameters and every row carries a checksum: a sweep "
                    "recomputes a row that fails it, --report-only refuses it. runs.csv must be a regular file "
                    "of at most 64 MiB, no field longer than 10,000 characters. "
                    "Exit 0 when every checked run of the experiment ended as its algorithm's registry entry "
                    "expects (topomark algorithms --json: expected), 1 when one did not, 2 on bad input.")
    p.add_argument("experiment", metavar="EXPERIMENT", help=f"one of: {', '.join(EXPERIMENTS)}")
    p.add_argument("--graphs", type=int, default=30, help="worlds per size (default 30)")
    p.add_argument("--heavy-graphs", type=int, default=HEAVY_GRAPHS,
                   help=f"worlds per size for enh5-d2 on complete(-hole) worlds (default {HEAVY_GRAPHS})")
    p.add_argument("--heavy-max-size", type=int, default=HEAVY_MAX_SIZE,
                   help=f"largest size for enh5-d2 on complete(-hole) worlds (default {HEAVY_MAX_SIZE})")
    p.add_argument("--sizes", type=int, nargs="+", metavar="SIZE", help="only these sizes (the thesis's n)")
    p.add_argument("--jobs", type=int, default=None, metavar="N",
                   help=f"worker processes, 1 to {MAX_JOBS} (default: one per CPU; never more than the runs)")
    p.add_argument("-o", "--out", default="bench-out", metavar="DIR", help="output directory (default bench-out)")
    p.add_argument("--no-check", action="store_true", help="skip the checker (rows record verified=False)")
    p.add_argument("--no-plots", action="store_true", help="do not draw plots")
    p.add_argument("--report-only", action="store_true", help="regenerate the report from the CSV, run nothing")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print a JSON summary")
    p.set_defaults(handler=bench_command)


def bench_command(args) -> int:
    if args.experiment not in EXPERIMENTS:
        raise unknown_name("experiment", args.experiment, EXPERIMENTS)
    if args.graphs < 1 or args.heavy_graphs < 1:
        raise InvalidInput("--graphs and --heavy-graphs must be >= 1")
    if args.jobs is not None:
        check_jobs(args.jobs)
    started = time.monotonic()
    runs = plan(args.experiment, args.graphs, args.sizes, args.heavy_graphs, args.heavy_max_size)
    if not runs:
        raise InvalidInput(f"no runs planned for {args.experiment} with --sizes {' '.join(map(str, args.sizes))} "
                           f"(see topomark bench --help for each experiment's sizes)")
    out = check_output_dir(args.out, create=not args.report_only)
    result: dict[str, Any] = {"planned": len(runs), "ran": 0, "skipped": len(runs), "failures": 0}
    if not args.report_only:
        parameters = {"experiment": args.experiment, "graphs": args.graphs, "sizes": args.sizes,
                      "heavy_graphs": args.heavy_graphs, "heavy_max_size": args.heavy_max_size}
        result = run_sweep(runs, out, args.jobs, check=not args.no_check, progress=not args.quiet,
                           parameters=parameters)
    wall = time.monotonic() - started
    report = write_report(args.experiment, out, None if args.report_only else wall, plots=not args.no_plots)
    text = report.read_text()
    verdict = judge_plan((r.key for r in runs), out / "runs.csv")
    result.update(failures=verdict.failures, outcomes=verdict.to_json())
    result.update(report=str(report), wall_seconds=round(wall, 1), plots_skipped="Plots: skipped" in text)
    if args.json:
        print(json.dumps(result, indent=1, sort_keys=True))
    else:
        print(f"{args.experiment}: {result['ran']} runs done, {result['skipped']} already in {out / 'runs.csv'}, "
              f"{wall:.0f} s; report {report}")
        print(f"{args.experiment}: {verdict.line()}")
        if result["plots_skipped"]:
            print(f"plots skipped: matplotlib is not installed ({INSTALL_HINT})")
    return 1 if result["failures"] else 0

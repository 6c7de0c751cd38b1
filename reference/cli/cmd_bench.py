"""``topomark bench``: the thesis's experiments (Figures 3.10-3.12, Tables 4.1-4.8, the lighthouses, Tables 6.1-6.2
and Figures 6.11-6.13, 6.17, 6.18), checked and resumable.

Its options are :mod:`topomark.reference.cli.options.bench`'s; this module is imported when it runs."""

from __future__ import annotations

import json
import time
from typing import Any

from topomark.spec.errors import InvalidInput, unknown_name

from topomark.reference.bench.reports.plots import INSTALL_HINT
from topomark.reference.bench.verdict import judge_plan
from topomark.reference.bench.experiments import EXPERIMENTS, plan, run_sweep, write_report
from topomark.reference.files.outputs import check_output_dir
from topomark.reference.cli.args import check_jobs

__all__ = ["bench_command"]


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
    text = report.read_text(encoding="utf-8")
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

"""The options of ``topomark bench`` (:mod:`..cmd_bench`)."""

from __future__ import annotations

from topomark.reference.cli.args import MAX_JOBS
from topomark.reference.cli.facts import fact
from topomark.reference.cli.parser import Later

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
    p.add_argument("experiment", metavar="EXPERIMENT", help=f"one of: {', '.join(fact('experiments'))}")
    p.add_argument("--graphs", type=int, default=30, help="worlds per size (default 30)")
    p.add_argument("--heavy-graphs", type=int, default=fact("heavy_graphs"),
                   help=f"worlds per size for enh5-d2 on complete(-hole) worlds (default {fact('heavy_graphs')})")
    p.add_argument("--heavy-max-size", type=int, default=fact("heavy_max_size"),
                   help=f"largest size for enh5-d2 on complete(-hole) worlds (default {fact('heavy_max_size')})")
    p.add_argument("--sizes", type=int, nargs="+", metavar="SIZE", help="only these sizes (the thesis's n)")
    p.add_argument("--jobs", type=int, default=None, metavar="N",
                   help=f"worker processes, 1 to {MAX_JOBS} (default: one per CPU; never more than the runs)")
    p.add_argument("-o", "--out", default="bench-out", metavar="DIR", help="output directory (default bench-out)")
    p.add_argument("--no-check", action="store_true", help="skip the checker (rows record verified=False)")
    p.add_argument("--no-plots", action="store_true", help="do not draw plots")
    p.add_argument("--report-only", action="store_true", help="regenerate the report from the CSV, run nothing")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print a JSON summary")
    p.set_defaults(handler=Later("cmd_bench", "bench_command"))

"""The options of ``topomark distinguish`` and ``topomark census`` (:mod:`..cmd_distinguish`)."""

from __future__ import annotations

from topomark.reference.cli.args import MAX_JOBS
from topomark.reference.cli.facts import fact
from topomark.reference.cli.options import add_marker_bounds
from topomark.reference.cli.parser import Later
from topomark.reference.worstcase.limits import MAX_WORLDS, degree_table

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser("distinguish",
                       description="Exit 0 if some motion sequence gives different perceptions in A and B "
                                   "(prints the shortest), 1 if they are indistinguishable, 2 on bad input. "
                                   "Both files need a start.")
    p.add_argument("a", metavar="A", help="the first world file (with a start)")
    p.add_argument("b", metavar="B", help="the second world file (with a start)")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(handler=Later("cmd_distinguish", "distinguish_command"))
    q = sub.add_parser("census", description="For every embedded world with 2..N vertices and max degree D (up to "
                                   "extended isomorphism), every placement of the marker class and every start, "
                                   "group placements by the robot's language. Exit 0 if no two non-isomorphic "
                                   "marked worlds are indistinguishable, 1 if some are, 2 on bad input, 130 when "
                                   "interrupted. A resumed census verifies every shard file (checksums, census "
                                   "parameters, code version) before trusting it: a damaged task or shard is "
                                   "computed again (said on stderr); a damaged, older-format or other census's "
                                   "manifest is exit 2 naming it; a shard file that is not a regular file (a FIFO, "
                                   "a device) is exit 2 naming it. A seal finds damage, not an edit: a resume also "
                                   "computes again a seeded sample of the kept tasks and shards (1 percent, at least one) "
                                   "and those the reported counterexample rests on, and a kept record they do not "
                                   "reproduce is exit 2 naming its file. Worker processes die with the census. At most "
                                   f"{MAX_WORLDS:,} worlds are enumerated at the largest n, so the largest "
                                   f"--max-degree per --max-vertices is {degree_table()} (exit 2 past it, before "
                                   "work).")
    add_marker_bounds(q, fact("enumerate_max_vertices"))
    q.add_argument("--jobs", type=int, default=1, metavar="N", help=f"worker processes, 1 to {MAX_JOBS} (default 1)")
    q.add_argument("--shards", metavar="DIR", help="keep the map/reduce shards in DIR; a killed census run again "
                   "with the same DIR resumes from its finished, verified tasks (default: a temporary directory)")
    q.add_argument("--scheduler", metavar="ADDRESS", help="run the map and reduce on a Dask cluster "
                   "(tcp://host:8786), or 'local' for a local Dask cluster of J workers (needs Dask: pip install '.[cluster]' from a checkout); "
                   f"exit 2 if no Dask scheduler answers at ADDRESS within {fact('connect_timeout')} s, or it has no "
                   f"worker within {fact('worker_wait')} s")
    q.add_argument("--engine", choices=fact("engines"), default="auto", help="how the map computes each world's "
                   "languages: 'reference' (Python, the definition), 'compiled' (numba; vertex-marker classes only) "
                   "or 'auto' (default: compiled where it applies; without numba the reference, said on stderr). "
                   "Both give the same shards and results")
    q.add_argument("--json", action="store_true", help="machine-readable output")
    q.add_argument("--quiet", action="store_true", help="no progress on stderr")
    q.set_defaults(handler=Later("cmd_distinguish", "census_command"))

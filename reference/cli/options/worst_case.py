"""The options of ``topomark worst-case`` (:mod:`..cmd_worst_case`), ``--search``'s among them
(:mod:`..cmd_worst_search`)."""

from __future__ import annotations

from topomark.reference.cli.args import MAX_JOBS, seed
from topomark.reference.cli.facts import fact
from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

from topomark.reference.worstcase.limits import (MAX_EVALUATIONS, MAX_EXHAUSTIVE, MAX_SEARCH_PRODUCT,
                                                 MAX_SEARCH_VERTICES, MAX_WORLDS, degree_table)

__all__ = ["register", "MAX_EXHAUSTIVE"]


def register(sub) -> None:
    p = sub.add_parser("worst-case", description="Run an algorithm from every start of every embedded world up to a size and "
                                   "degree (exhaustive, exact), or search larger worlds for bad ones (--search, a "
                                   "lower bound); report the largest cost, cost/m and cost / bound per n.")
    p.add_argument("--algorithm", default="basic", metavar="NAME", help="registered algorithm (default basic; "
                                                                         "see topomark algorithms)")
    p.add_argument("--lighthouse", metavar="NAME", help="lighthouse strategy for a Chapter 3-4 algorithm")
    p.add_argument("--policy", action="append", default=[], metavar="KIND=NAME",
                   help="edge, hypothesis or path policy, as for explore (repeatable)")
    p.add_argument("--max-vertices", type=int, metavar="N", help=f"largest world size (exhaustive: 2..{MAX_EXHAUSTIVE})")
    p.add_argument("--max-degree", type=int, default=4, metavar="D",
                   help=f"largest vertex degree (default 4); at most {MAX_WORLDS:,} worlds are enumerated at the "
                        f"largest n, so the largest degree per --max-vertices is {degree_table()}")
    p.add_argument("--min-vertices", type=int, default=2, metavar="M", help="smallest world size (default 2)")
    p.add_argument("--jobs", type=int, default=1, metavar="N", help=f"worker processes, 1 to {MAX_JOBS} (default 1)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="run the tasks on a Dask cluster (an address, or 'local')")
    p.add_argument("--shards", metavar="DIR", help="keep the tasks' results in DIR; run again, it resumes, running again a "
                   "seeded sample of the kept tasks (1 percent, at least one) and those holding a maximum or a problem: a "
                   "task file they do not reproduce (edited and resealed) is exit 2 naming it")
    p.add_argument("--sample", type=float, default=0.001, metavar="FRACTION",
                   help="fraction of the runs re-run checked (default 0.001; every argmax is always re-checked)")
    p.add_argument("--seed", type=seed, default=0, help="seed of the checked sample and of --search (default 0)")
    p.add_argument("--engine", choices=fact("engines"), default="auto",
                   help="what runs the unchecked runs of the exhaustive search and of --search: reference, compiled "
                        "(numba; basic and the Chapter 4 algorithms enh1, enh2, enh3, enh4, enh5-d1, enh5-d2, enh3+4 and "
                        "enh3+5 with the built-in policies and a lighthouse recognised "
                        "without probing: directional-vertex, directional-edge, vertex-and-edge, three-undirected-edge "
                        "or thread; and the footprint searches case-1a, case-1b, case-2, case-4 and case-4-mn), or "
                        "auto (default: compiled when "
                        "numba is installed and it runs the algorithm, else reference); every checked re-run is the "
                        "reference's")
    p.add_argument("--cross-check", action="store_true",
                   help="also run the brute force over labelled rotation systems and require the same maxima (n <= 5)")
    p.add_argument("-o", "--out", metavar="DIR", help="write worst-case.json, the argmax world files, worst-case.md and plots")
    add_force(p)
    p.add_argument("--summarise", nargs="+", metavar="DIR",
                   help="the report over the --out directories of earlier runs, exhaustive and --search: Markdown on "
                        "stdout, or worst-case.md and its plot in -o DIR")
    p.add_argument("--quiet", action="store_true",
                   help="no progress lines on stderr (printed by default, with --json too)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    add_search_arguments(p)
    p.set_defaults(handler=Later("cmd_worst_case", "worst_case_command"))


def add_search_arguments(p) -> None:
    g = p.add_argument_group("adversarial search (--search)")
    g.add_argument("--search", action="store_true", help="search worlds past exhaustive sizes for a bad one "
                   "(the exhaustive search's options --max-vertices, --min-vertices, --jobs, --scheduler, --shards, "
                   "--sample and --cross-check are refused with it)")
    g.add_argument("--vertices", type=int, nargs="+", metavar="N",
                   help=f"world sizes to search (default 20, or the --restart-world's n), 3..{MAX_SEARCH_VERTICES:,}")
    g.add_argument("--evaluations", type=int, default=400, metavar="K",
                   help=f"runs per size for the search, and as many random worlds (default 400), 1..{MAX_EVALUATIONS:,}; "
                        f"each size times K at most {MAX_SEARCH_PRODUCT:,} (a quarter of the runs' worlds are held at "
                        "once)")
    g.add_argument("--objective", choices=fact("objectives"), default="cost",
                   help="what to maximise: cost, cost-per-m, or ratio (cost / the exact bound)")
    g.add_argument("--restart-family", choices=fact("restart_families"), metavar="NAME",
                   help="start the search from this family's world at each size and its neighbours instead of random "
                        "worlds: strip (strip:n=N,cap=1 for even N >= 8, else cap=0), circulant (circulant:n=N,k=2), "
                        "k5e-chain (N a multiple of 5), rewired-strip (rewired-strip:n=N, N even and >= 46), split-strip "
                        "(split-strip:n=N, N even and >= 16) or pendant-strip (pendant-strip:n=N, N >= 13)")
    g.add_argument("--restart-world", metavar="WORLD",
                   help="start the search from this one world (a generator text such as a kept worst world "
                        "worst-case:case=NAME, or a world file) and its neighbours: a search going on from where "
                        "another stopped; --vertices is its n")
    g.add_argument("--world-family", choices=("lattice-hole",),
                   help="search within a family of worlds: lattice-hole (a lattice, which cells are removed)")

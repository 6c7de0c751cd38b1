"""The options of ``topomark explore`` (:mod:`..cmd_explore`): the algorithms, their options, the lighthouses
and the policies, as the registry has them (thesis §3.3–3.5, Chapters 4–6)."""

from __future__ import annotations

from topomark.reference.cli.args import seed as seed_option
from topomark.reference.cli.facts import fact
from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser(
        "explore",
        description="Explore WORLD (a world file or GENERATOR[:NAME=VALUE,...]; default: a built-in 5x5 lattice "
                    "with 2 cells removed) and verify the map. Exit 0 when the map is verified isomorphic, 1 on an "
                    "invariant violation or when the algorithm stops without a map (outcome failed or limit), "
                    "2 on bad input.")
    p.add_argument("world", nargs="?", metavar="WORLD_OR_GENERATOR",
                   help="a world file, or GENERATOR[:NAME=VALUE,...] (default: the built-in world)")
    p.add_argument("--algorithm", default="basic", metavar="NAME",
                   help=f"one of: {', '.join(fact('algorithms'))} (default basic; topomark algorithms lists them)")
    p.add_argument("--lighthouse", default=None, metavar="NAME",
                   help=f"how v0 is marked: {', '.join(fact('lighthouses'))} (default directional-vertex, Algorithm 3.1's; "
                        "for Algorithm 3.1 and the Chapter 4 enhancements only)")
    for name, text, default, takers in fact("parameters"):  # every algorithm taking --NAME, each its default
        own = "" if "(default " in takers else f"; default {default}"  # each taker's own default, where they differ
        p.add_argument(f"--{name}", dest=f"param_{name.replace('-', '_')}", metavar="VALUE",
                       help=f"{text} (for {takers}{own})")
    p.add_argument("--policy", action="append", default=[], metavar="KIND=NAME",
                   help=f"edge={'|'.join(fact('edge_policies'))}, hypothesis={'|'.join(fact('hypothesis_policies'))}, "
                        f"path={'|'.join(fact('path_policies'))}; a bare NAME sets the edge policy (repeatable; only the "
                        "kinds the algorithm takes, topomark algorithms; a kind not given takes the algorithm's "
                        "default)")
    p.add_argument("--seed", type=seed_option, help="seed for a random generator; with a searched lighthouse "
                                            "(undirected-vertex, undirected-edge) the seed of its random walk")
    p.add_argument("--walk-limit", metavar="N", help="a searched lighthouse gives up after N walk steps (default 200, "
                                                     f"§5.1's threshold; at most {fact('max_walk_limit'):,})")
    p.add_argument("--neighbourhood", metavar="D", help="undirected-vertex, local-degree-list: test the neighbours' "
                                                        "views to distance D (default 1, §5.1; at most "
                                                        f"{fact('max_neighbourhood')}: the work grows exponentially with D)")
    p.add_argument("--threshold", metavar="N", help="local-pair, local-degree-list: the least-seen candidate must "
                                                    "be seen fewer than N times (default: the walk's observations, "
                                                    f"§5.2.1; at most {fact('max_threshold'):,})")
    p.add_argument("--no-check", action="store_true", help="skip the per-iteration checks (faster)")
    p.add_argument("--check-mode", default="incremental", choices=("incremental", "full", "both"),
                   help="how I-1/I-2 are evaluated each iteration: per journalled change (default), from scratch, "
                        "or both (they must agree); the final verdict is always from scratch")
    p.add_argument("--trace", metavar="FILE", help="write the JSON Lines trace here")
    p.add_argument("--view", metavar="FILE", help="write the run's viewer page here (as topomark view writes it: one "
                                                 "self-contained HTML file to step through in a browser)")
    p.add_argument("--map", metavar="FILE", help="write the final map (world format, marker included); a run that stops without a map "
                                            "writes none and says so")
    p.add_argument("--models", metavar="DIR", help="write every completed model as a world file, in completion order "
                                                   "(model-0001.json, ...; algorithms that keep models: model-tree)")
    p.add_argument("--breakdown", action="store_true",
                   help="split the cost by iteration too: --json's cost_breakdown gets one row per iteration (its "
                        "per-kind totals are always there), the report a table of the kinds and the costliest "
                        "iterations")
    p.add_argument("--breakdown-plot", metavar="FILE", help="plot the cost of each iteration, stacked by kind of walk "
                                                           "(.png or .svg; needs matplotlib)")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--quiet", action="store_true",
                   help="no progress on stderr (a bar on a terminal, else a line every 10 s; with --json too)")
    p.set_defaults(handler=Later("cmd_explore", "explore_command"))

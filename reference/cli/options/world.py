"""The options of ``topomark world`` and ``topomark iso`` (:mod:`..cmd_world`)."""

from __future__ import annotations

import argparse

from topomark.reference.cli.args import seed as seed_option
from topomark.reference.cli.facts import fact
from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    gens = "; ".join(f"{g}({', '.join(f'{k}={v}' for k, v in p.items())})" for g, p in fact("generators").items())
    p = sub.add_parser("world",
                       description="Generate a world: GENERATOR[:NAME=VALUE,...]. Generators and defaults: " + gens)
    p.add_argument("generator", nargs="?", metavar="GENERATOR", help="generator name with optional :NAME=VALUE,...")
    p.add_argument("--seed", type=seed_option, help="seed for random generators")
    p.add_argument("-o", "--out", dest="output", metavar="FILE", help="write the world here (default: stdout)")
    p.add_argument("--output", dest="output", help=argparse.SUPPRESS)  # the former spelling, still accepted
    add_force(p)
    p.add_argument("--show", metavar="FILE", help="summarise a world file instead")
    p.add_argument("--draw", metavar="GENERATOR_OR_FILE",
                   help="draw a world (a generator or a world file) to -o FILE, .svg or .png by its suffix (PNG needs "
                        "matplotlib): vertex names, exit indices clockwise, markers, the start and the edge it faces; at most "
                        f"{fact('draw_max_vertices'):,} vertices (a larger world is refused, exit 2)")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(handler=Later("cmd_world", "world_command"))
    q = sub.add_parser("iso",
                       description="Exit 0 if A and B are extended-isomorphic (markers preserved; starts ignored), "
                                   "1 if not (with the first mismatch), 2 on bad input.")
    q.add_argument("a", metavar="A", help="the first world or map file")
    q.add_argument("b", metavar="B", help="the second world or map file")
    q.add_argument("--method", choices=("anchored", "networkx", "both"), default="anchored",
                   help="which implementation decides (both: each, and they must agree)")
    q.add_argument("--ignore-markers", action="store_true", help="compare the embedded graphs only")
    q.add_argument("--json", action="store_true", help="machine-readable output")
    q.set_defaults(handler=Later("cmd_world", "iso_command"))

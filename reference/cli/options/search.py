"""The options of ``topomark search`` (:mod:`..cmd_search`)."""

from __future__ import annotations

from topomark.reference.cli.facts import fact
from topomark.reference.cli.options import add_force, add_marker_bounds
from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser(
        "search", description="Search with Z3 for two worlds carrying the marker class that no motion sequence tells "
                    "apart but that are not extended-isomorphic. Exit 0 if found (or, with --prove, if none "
                    "exists within the bounds), 1 otherwise (including unknown/timeout), 2 on bad input.")
    add_marker_bounds(p, fact("search_max_vertices"))
    p.add_argument("--planar", action="store_true", help="only planar embeddings (genus 0), like the figures")
    p.add_argument("--prove", action="store_true", help="report a bounded proof: exit 0 iff UNSAT")
    p.add_argument("--timeout", type=float, default=None, metavar="SECONDS",
                   help="give up after SECONDS (outcome unknown)")
    p.add_argument("-o", "--out", default=None, metavar="DIR", help="write a.json, b.json, relation.json, pair.svg")
    add_force(p)
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(handler=Later("cmd_search", "search_command"))

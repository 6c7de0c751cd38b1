"""The options of ``topomark port solve`` (:mod:`..cmd_port_solve`): maps consistent with an exploration's records."""

from __future__ import annotations

from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(actions) -> None:
    p = actions.add_parser(
        "solve",
        description="Find, with Z3, a map of N rooms consistent with the plans and records of EXCHANGE (the plans "
                    "of an /explore request and the results of its answer: {\"plans\": [...], \"results\": "
                    "[[...]]}), start room 0, rooms numbered in breadth-first order; then look for a second "
                    "consistent map that no plan (marks included) confuses with the first. Exit 0 when the records "
                    "pin the map down (the map is written with -o), 1 when they do not (both maps and a plan that "
                    "separates them, replayed on both), when no map of N rooms gives the records, or when Z3 gives "
                    "up within --timeout (status unknown: not a verdict), 2 on bad input, 3 when topomark's own "
                    "checks disagree.")
    p.add_argument("exchange", metavar="EXCHANGE", help="the JSON file of plans and their records")
    p.add_argument("--rooms", type=int, required=True, metavar="N", help="the number of rooms of the map")
    p.add_argument("--doors", type=int, default=6, metavar="D", help="doors per room (default 6, as the contest)")
    p.add_argument("--alphabet", type=int, default=4, metavar="K",
                   help="colours 0..K-1 (default 4, as the contest)")
    p.add_argument("--no-echo", dest="echo", action="store_false",
                   help="the records do not echo marks (default: each mark [c] is answered with c, as the "
                        "contest's official server did)")
    p.add_argument("-o", "--out", dest="output", metavar="MAP",
                   help="write the map found (the first, when the records do not pin it down) as a contest map "
                        "object")
    add_force(p)
    p.add_argument("--timeout", type=float, default=None, metavar="SECONDS",
                   help="seconds Z3 may spend in all (default: no limit)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_solve", "solve_command"))

"""The options of ``topomark view`` (:mod:`..cmd_view`): a trace stepped through in the browser."""

from __future__ import annotations

from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser(
        "view",
        description="Write one self-contained HTML page (no network; opens from disk) that steps through TRACE "
                    "replayed on its world: the world drawn as world --draw draws it with the robot, its heading, "
                    "the markers and the thread; the map S so far with its unexplored edges; the iteration, the "
                    "hypothesis under test and its walk; the checks at each line; the cost split by kind of walk. "
                    "Exit 0 when replay verifies the trace, 1 when it diverges (the page shows the run up to the "
                    "divergence, the reference's expectation beside the trace's claim), 2 on bad input (replay's "
                    "messages).")
    p.add_argument("trace", metavar="TRACE", help="the JSON Lines trace file (topomark/trace@1 or @2)")
    p.add_argument("--world", metavar="FILE",
                   help="the world file the trace was recorded on (default: the world the trace's own final map "
                        "gives, for a complete Algorithm 3.1 run)")
    p.add_argument("-o", "--out", dest="output", metavar="FILE",
                   help="the HTML page to write (default: TRACE with the suffix .html)")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_view", "view_command"))

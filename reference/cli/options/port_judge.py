"""The options of ``topomark port judge|minimise|suite`` (:mod:`..cmd_port_judge`): two port maps judged exactly,
a map minimised, and the contest's maps as a suite."""

from __future__ import annotations

from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

__all__ = ["register"]

MAP_HELP = "a contest map file ({\"problemName\", \"map\"}) or a bare contest map ({\"rooms\", \"startingRoom\", " \
           "\"connections\"})"


def register(actions) -> None:
    _judge(actions)
    _minimise(actions)
    _suite(actions)


def _judge(actions) -> None:
    p = actions.add_parser(
        "judge",
        description="Judge two port maps exactly: equivalent when no plan, charcoal marks included, gives different "
                    "records on them and they have the same number of rooms (the contest's rule). Exit 0 "
                    "equivalent; 1 different, with the witness (the shortest plan without marks that separates "
                    "them, else the shortest plan with one mark) and its record on each map, replayed on both; 2 "
                    "bad input.")
    p.add_argument("first", metavar="A", help=MAP_HELP)
    p.add_argument("second", metavar="B", help=MAP_HELP)
    p.add_argument("--no-echo", action="store_true",
                   help="records without the official server's echo of each mark (the echo is on by default)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_judge", "judge_command"))


def _minimise(actions) -> None:
    p = actions.add_parser(
        "minimise",
        description="The smallest map equivalent to MAP under plans without marks (its quotient by plain "
                    "equivalence, checked with the judge before it is printed) and, when every block of equivalent "
                    "rooms has the same size k, MAP's copy structure as a k-copy map of the quotient: the rooms of "
                    "each block (its layers) and, per door of each block, where each layer leads. When the blocks "
                    "differ in size no port world of the minimal size exists; the blocks are printed and no map is "
                    "written.")
    p.add_argument("map", metavar="MAP", help=MAP_HELP)
    p.add_argument("-o", "--out", dest="output", metavar="FILE",
                   help="write the quotient as a contest map file (problemName from MAP, else 'minimised')")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_judge", "minimise_command"))


def _suite(actions) -> None:
    p = actions.add_parser(
        "suite",
        description="Run the judge's suite on every contest map file (*.json) under DIR: each map imports, its "
                    "minimal size is the manifest's minimal_rooms, and it is judged against a relabelled copy (must "
                    "be equivalent), a door-permuted copy, two passage swaps and, for copy maps, two layer swaps, "
                    "each verdict timed. Exit 0 when every map imports, has its manifest's minimal size and equals "
                    "its relabelled copy; 1 otherwise.")
    p.add_argument("directory", metavar="DIR", help="a folder of contest map files")
    p.add_argument("--manifest", metavar="FILE",
                   help="a tab-separated manifest with the columns file and minimal_rooms (default: DIR/MANIFEST.tsv "
                        "when there is one)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_judge", "suite_command"))

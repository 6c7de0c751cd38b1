"""The options of ``topomark port import|export|run|show`` (:mod:`..cmd_port_files`): port world files in and
out, plans run on a port world, and a port world's summary."""

from __future__ import annotations

from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later

__all__ = ["register"]

WORLD_HELP = ("a port world file (topomark/port-world@1), a contest map file ({\"problemName\", \"map\"}) or a bare "
              "contest map ({\"rooms\", \"startingRoom\", \"connections\"})")


def register(actions) -> None:
    _import(actions)
    _export(actions)
    _run(actions)
    _show(actions)


def _import(actions) -> None:
    p = actions.add_parser(
        "import",
        description="Convert to topomark's port world format (topomark/port-world@1). 'icfpc2025 FILE' converts one "
                    "contest map file ({\"problemName\", \"map\"}; any other key is refused, its value never shown), "
                    "keeping door numbers exactly as given and problemName as the file's problem; 'icfpc2025 DIR' "
                    "converts every *.json under DIR (recursively) into the directory OUT, mirroring the relative "
                    "paths. Every input is read and checked before anything is written: the first bad file stops "
                    "the import, exit 2 naming the file and its fault, and nothing is written. 'thesis WORLD' "
                    "converts a thesis world (a world file or a generator, as explore takes it) with port i = exit i: "
                    "every room gets as many doors as the largest degree, missing doors are joined to themselves, "
                    "markers and the start's facing are dropped, and the vertex names are kept as room names.")
    p.add_argument("source", choices=("icfpc2025", "thesis"), metavar="SOURCE",
                   help="icfpc2025 (a contest map file or a directory of them) or thesis (a thesis world)")
    p.add_argument("input", metavar="FILE|DIR|WORLD", help="what to import")
    p.add_argument("-o", "--out", dest="output", required=True, metavar="OUT",
                   help="the port world file to write (a directory for icfpc2025 DIR)")
    p.add_argument("--colour", choices=("degree", "none"), default=None,
                   help="thesis only: colour each room with its degree (default), so the port robot senses what the "
                        "thesis's robot senses, or give every room colour 0")
    p.add_argument("--start", metavar="V", help="thesis only: the start vertex (default: the world's start, else its "
                                                "first vertex)")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_files", "import_command"))


def _export(actions) -> None:
    p = actions.add_parser(
        "export",
        description="Write WORLD as a contest map file {\"problemName\", \"map\"} (each passage once, from its "
                    "smaller door-end). The world must have 6 doors a room and colours 0..3.")
    p.add_argument("target", choices=("icfpc2025",), metavar="FORMAT", help="icfpc2025")
    p.add_argument("world", metavar="WORLD", help=WORLD_HELP)
    p.add_argument("--problem", metavar="NAME", help="the problemName to write (default: the world's own problem "
                                                     "name; one of the two is needed)")
    p.add_argument("-o", "--out", dest="output", required=True, metavar="FILE", help="the map file to write")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_files", "export_command"))


def _run(actions) -> None:
    p = actions.add_parser(
        "run",
        description="Run plans on WORLD from its start room and print each plan's record: the start room's colour, "
                    "then the colour of each room entered (a room marked earlier in the plan shows its mark) and, "
                    "unless --no-echo, the colour each mark [c] writes, as the contest's server echoed it. Marks "
                    "last until their plan ends. With --json the output is the contest's /explore answer: "
                    "{\"results\": [[...], ...], \"queryCount\": k} (k = plans + 1). A plan with a character outside "
                    "the world's doors and [c], or over the round's length limit, is exit 2 naming the plan's number "
                    "and the character or the limit.")
    p.add_argument("world", metavar="WORLD", help=WORLD_HELP)
    p.add_argument("plans", nargs="*", metavar="PLAN", help="a plan: door digits and marks [c], e.g. 01[2]34")
    p.add_argument("--plans", dest="plans_file", metavar="FILE",
                   help="a file of plans, one a line (blank lines are skipped), run after the PLANs given")
    p.add_argument("--no-echo", action="store_true", help="records without an entry for each mark")
    p.add_argument("--round", choices=("full", "lightning"), default="full",
                   help="the length limit: full (6 doors a room, the default) or lightning (18 doors a room)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_files", "run_command"))


def _show(actions) -> None:
    p = actions.add_parser(
        "show",
        description="Summarise WORLD: rooms, doors a room, the start, passages (doors joined to themselves, two "
                    "doors of one room joined, passages parallel to another between the same two rooms) and how many "
                    "rooms have each colour.")
    p.add_argument("world", metavar="WORLD", help=WORLD_HELP)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=Later("cmd_port_files", "show_command"))

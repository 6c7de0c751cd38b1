"""The options of the oracle's commands, ``run-external``, ``check-map``, ``replay``, ``drive`` and
``conformance`` (:mod:`..cmd_oracle`).

``run-external``, ``drive`` and ``conformance run`` keep the function that adds their options
(``add_options``): options written between the positionals and ``--`` are parsed with it when they run.
"""

from __future__ import annotations

import argparse

from topomark.reference.cli.args import seed as seed_option
from topomark.reference.cli.facts import fact
from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import JSON_HELP, Later, Parser
from topomark.spec.errors import InvalidInput

__all__ = ["register", "WORLD_HELP"]

WORLD_HELP = "a world file, or a generator GENERATOR[:NAME=VALUE,...] (topomark world --help lists them)"


def register(sub) -> None:
    p = sub.add_parser("run-external",
                       description="Run CMD as the explorer of WORLD (a world file or generator) over JSON Lines on "
                                   "its stdin/stdout (spec/protocol.md). Exit 0 if its map is extended-isomorphic "
                                   "and every snapshot satisfied I-1/I-2, 1 on any failure, 2 on bad input.")
    p.add_argument("world", metavar="WORLD", help=WORLD_HELP)
    p.add_argument("cmd", nargs=argparse.REMAINDER, metavar="-- CMD [ARGS...]",
                   help="the program and its arguments, after --")
    _run_options(p)
    p.set_defaults(handler=Later("cmd_oracle", "run_external_command"), add_options=_run_options)

    q = sub.add_parser("check-map",
                       description="Exit 0 if MAP is extended-isomorphic to WORLD, 1 if not (with the first mismatch "
                                   "in words), 2 on bad input. Markers: compared if the world file has any; else, if "
                                   "the world has a start and the map one directional vertex marker, the lighthouse "
                                   "Algorithm 3.1 drops at the start is added; else ignored.")
    q.add_argument("world", metavar="WORLD", help="the world file")
    q.add_argument("map", metavar="MAP", help="the map file to judge (world format)")
    q.add_argument("--json", action="store_true", help=JSON_HELP)
    q.set_defaults(handler=Later("cmd_oracle", "check_map_command"))

    r = sub.add_parser("replay",
                       description="Replay TRACE on WORLD: every perception, the cost, I-1/I-2 after every "
                                   "iteration (S and U rebuilt from the joins) and the final map. Exit 0 if it "
                                   "holds up, 1 at the first divergence (step, expected, found), 2 on bad input (a "
                                   f"trace of more than {fact('max_trace_records'):,} records, or a line of more "
                                   f"than {fact('max_trace_line_bytes') >> 20} MiB, too).")
    r.add_argument("world", metavar="WORLD", help="the world file the trace was recorded on")
    r.add_argument("trace", metavar="TRACE", help="the JSON Lines trace file to replay")
    r.add_argument("--view", metavar="FILE", help="also write the replayed run's viewer page here (as topomark view "
                                                 "writes it; a divergence is shown beside the run up to it)")
    add_force(r)
    r.add_argument("--json", action="store_true", help=JSON_HELP)
    r.set_defaults(handler=Later("cmd_oracle", "replay_command"))

    d = sub.add_parser("drive",
                       description="Run CMD as the world (spec/protocol.md, provider role): topomark sends motions "
                                   "and marker drops, CMD answers with signatures. Exit 0 when a map was made (and, "
                                   "with --check WORLD, is extended-isomorphic to it), 1 on failure, 2 on bad input.")
    d.add_argument("cmd", nargs=argparse.REMAINDER, metavar="-- CMD [ARGS...]",
                   help="the world provider and its arguments, after --")
    _drive_options(d)
    d.set_defaults(handler=Later("cmd_oracle", "drive_command"), add_options=_drive_options)

    _register_conformance(sub)


def _register_conformance(sub) -> None:
    """``conformance export|lint|run``."""
    c = sub.add_parser("conformance",
                       description="export DIR: write the versioned suite topomark/conformance@2 (worlds, kits, "
                                   "bounds, reference runs: costs, marker operations, maps, traces; Algorithm 3.1's "
                                   "cases and a suite per deterministic algorithm). lint DIR: check a suite (@2 or "
                                   "@1). run DIR -- CMD: run an implementation against Algorithm 3.1's cases through "
                                   "topomark/protocol@1 (or @2 with --protocol 2 or --kit), or with --algorithm/"
                                   "--family against those algorithms' suites through topomark/protocol@2, each "
                                   "case giving its kit in hello (exit 0 iff all pass).")
    csub = c.add_subparsers(dest="action", metavar="ACTION", parser_class=Parser)
    ce = csub.add_parser("export", help="write the suite to DIR (new or empty)")
    ce.add_argument("dir", metavar="DIR", help="the directory to write (new or empty; --force replaces an earlier "
                                              "suite)")
    _suite_choice(ce, "write the suite of the algorithm NAME only (repeatable; default: every deterministic one)")
    add_force(ce, "replace the suite an earlier export wrote in DIR (default: refuse a non-empty DIR, exit 2)")
    ce.add_argument("--json", action="store_true", help=JSON_HELP)
    ce.set_defaults(handler=Later("cmd_oracle", "conformance_export"))
    cl = csub.add_parser("lint", help="check a suite directory")
    cl.add_argument("dir", metavar="DIR", help="the suite directory")
    cl.add_argument("--json", action="store_true", help=JSON_HELP)
    cl.set_defaults(handler=Later("cmd_oracle", "conformance_lint"))
    cr = csub.add_parser("run", help="run CMD on every case (of Algorithm 3.1, or of --algorithm/--family)")
    cr.add_argument("dir", metavar="DIR", help="the suite directory (topomark conformance export DIR)")
    cr.add_argument("cmd", nargs=argparse.REMAINDER, metavar="-- CMD [ARGS...]",
                    help="the implementation under test and its arguments, after --")
    _conformance_options(cr)
    cr.set_defaults(handler=Later("cmd_oracle", "conformance_run"), add_options=_conformance_options)
    c.set_defaults(handler=lambda args: _no_action())


def _run_options(p) -> None:
    _limits(p)
    _protocol_options(p)
    p.add_argument("--seed", type=seed_option, help="seed for a random generator")
    p.add_argument("--map", metavar="FILE", help="write the program's map here")
    add_force(p)
    p.add_argument("--json", action="store_true", help=JSON_HELP)


def _drive_options(p) -> None:
    p.add_argument("--policy", action="append", default=[], metavar="KIND=NAME", help="as for explore")
    p.add_argument("--check", metavar="WORLD", help="judge the map against this world file")
    p.add_argument("--trace", metavar="FILE", help="write the topomark/trace@1 trace here, streamed as the run goes "
                                                    "(without it no trace is kept, only counters)")
    p.add_argument("--map", metavar="FILE", help="write the map here")
    add_force(p)
    p.add_argument("--max-traversals", type=int, default=1_000_000, metavar="N",
                   help="fail after this many edge traversals (default 1,000,000)")
    p.add_argument("--timeout", type=float, default=600.0, metavar="SECONDS", help="wall-time limit (default 600)")
    p.add_argument("--message-timeout", type=float, default=10.0, metavar="SECONDS",
                   help="longest wait for one message (default 10)")
    p.add_argument("--lighthouse", default="directional-vertex", metavar="NAME",
                   help=f"the markers the explorer drops at v0: {', '.join(fact('lighthouses'))} (default directional-vertex; "
                        "another one needs a provider speaking topomark/protocol@2)")
    p.add_argument("--json", action="store_true", help=JSON_HELP)


def _conformance_options(p) -> None:
    _limits(p)
    _protocol_options(p)
    _suite_choice(p, "run the suite of the algorithm NAME through topomark/protocol@2, each case with its own kit "
                     "(repeatable; without it and --family: Algorithm 3.1's cases)")
    p.add_argument("-k", "--select", metavar="TEXT", help="only the cases whose name contains TEXT")
    p.add_argument("--view-failures", metavar="DIR",
                   help="for each failing case, write the program's run to DIR: its trace (CASE.jsonl, the robot "
                        "layer) and its viewer page (CASE.html: the run up to the failure, what the reference "
                        "expected beside what the program did)")
    add_force(p)
    p.add_argument("--json", action="store_true", help=JSON_HELP)


def _suite_choice(p, what: str) -> None:
    p.add_argument("--algorithm", action="append", default=[], metavar="NAME", help=what)
    p.add_argument("--family", action="append", default=[], metavar="FAMILY",
                   help=f"every deterministic algorithm of FAMILY ({', '.join(fact('conformance_families'))}; repeatable)")


def _protocol_options(p) -> None:
    p.add_argument("--protocol", type=int, choices=(1, 2), metavar="1|2",
                   help="the protocol version spoken to the program (default 1; 2 with --kit)")
    p.add_argument("--kit", metavar="JSON", help="the program's marker kit, e.g. '{\"undirected-edge\": 3}' "
                                                  "(implies --protocol 2; default {\"directional-vertex\": 1}; at "
                                                  f"most {fact('max_marker_count'):,} markers of a kind and a thread "
                                                  f"of at most {fact('max_thread'):,} edges)")


def _limits(p) -> None:
    p.add_argument("--max-traversals", type=int, metavar="N",
                   help="fail a program that traverses more edges (default: 4 x the (3.1)+(3.2) bound, >= 1000)")
    p.add_argument("--max-operations", type=int, metavar="N",
                   help="end a run (outcome limit) whose program makes more marker or thread operations; they are "
                        "not traversals and are counted apart (default: 2 x the traversal limit, >= 1000)")
    p.add_argument("--timeout", type=float, default=60.0, metavar="SECONDS",
                   help="the program's time limit: the time topomark waits for it, its own checking not counted "
                        "(default 60)")
    p.add_argument("--message-timeout", type=float, default=10.0, metavar="SECONDS",
                   help="longest wait for one message (default 10)")


def _no_action() -> int:
    raise InvalidInput("conformance needs an action: export DIR, lint DIR or run DIR -- CMD")

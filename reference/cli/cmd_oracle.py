"""topomark as an oracle for other implementations: ``run-external``, ``replay``, ``check-map``,
``conformance``, ``drive`` (thesis §3.1, §3.3–3.4, §3.6).

Exit codes as everywhere: 0 positive verdict, 1 negative verdict, 2 bad input.
Every command takes ``--json``.
"""

from __future__ import annotations

import argparse
import sys

from topomark.spec.errors import InvalidInput
from topomark.spec.jsontext import no_duplicate_keys, parse_json
from topomark.spec.kit import Kit
from topomark.spec.worldfile import load_world, save_world

from topomark.reference.oracle import conformance
from topomark.reference.cli.parser import JSON_HELP, Parser, emit
from topomark.reference.cli.args import check_count, check_seconds
from topomark.reference.cli.args import seed as seed_option
from topomark.reference.cli.cmd_explore import parse_policies
from topomark.reference.oracle.drive import drive
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, lighthouse
from topomark.reference.oracle.run_external import Limits, run_external
from topomark.reference.run.map_check import check_map
from topomark.reference.files.outputs import guarded
from topomark.reference.replay.replay import load_trace, replay
from topomark.reference.oracle.marker_messages import MAX_COUNT
from topomark.reference.worlds.argument import resolve_world

__all__ = ["register"]

WORLD_HELP = "a world file, or a generator GENERATOR[:NAME=VALUE,...] (topomark world --help lists them)"


def _command(args) -> list[str]:
    """The program after ``--``; options written between the positionals and ``--`` are parsed here."""
    cmd = list(args.cmd)
    if "--" in cmd:
        k = cmd.index("--")
        options, cmd = cmd[:k], cmd[k + 1:]
        parser = Parser(prog=f"topomark {args.command}", add_help=False)
        args.add_options(parser)
        parser.parse_args(options, namespace=args)
    if not cmd or cmd[0].startswith("-"):
        raise InvalidInput(f"{args.command}: give the program to run after --, e.g. -- python3 client.py")
    return cmd


def _run_options(p) -> None:
    _limits(p)
    _protocol_options(p)
    p.add_argument("--seed", type=seed_option, help="seed for a random generator")
    p.add_argument("--map", metavar="FILE", help="write the program's map here")
    p.add_argument("--json", action="store_true", help=JSON_HELP)


def _drive_options(p) -> None:
    p.add_argument("--policy", action="append", default=[], metavar="KIND=NAME", help="as for explore")
    p.add_argument("--check", metavar="WORLD", help="judge the map against this world file")
    p.add_argument("--trace", metavar="FILE", help="write the topomark/trace@1 trace here, streamed as the run goes "
                                                    "(without it no trace is kept, only counters)")
    p.add_argument("--map", metavar="FILE", help="write the map here")
    p.add_argument("--max-traversals", type=int, default=1_000_000, metavar="N",
                   help="fail after this many edge traversals (default 1,000,000)")
    p.add_argument("--timeout", type=float, default=600.0, metavar="SECONDS", help="wall-time limit (default 600)")
    p.add_argument("--message-timeout", type=float, default=10.0, metavar="SECONDS",
                   help="longest wait for one message (default 10)")
    p.add_argument("--lighthouse", default="directional-vertex", metavar="NAME",
                   help=f"the markers the explorer drops at v0: {', '.join(LIGHTHOUSES)} (default directional-vertex; "
                        "another one needs a provider speaking topomark/protocol@2)")
    p.add_argument("--json", action="store_true", help=JSON_HELP)


def _conformance_options(p) -> None:
    _limits(p)
    _protocol_options(p)
    _suite_choice(p, "run the suite of the algorithm NAME through topomark/protocol@2, each case with its own kit "
                     "(repeatable; without it and --family: Algorithm 3.1's cases)")
    p.add_argument("-k", "--select", metavar="TEXT", help="only the cases whose name contains TEXT")
    p.add_argument("--json", action="store_true", help=JSON_HELP)


def _suite_choice(p, what: str) -> None:
    p.add_argument("--algorithm", action="append", default=[], metavar="NAME", help=what)
    p.add_argument("--family", action="append", default=[], metavar="FAMILY",
                   help=f"every deterministic algorithm of FAMILY ({', '.join(conformance.FAMILIES)}; repeatable)")


def _protocol_options(p) -> None:
    p.add_argument("--protocol", type=int, choices=(1, 2), metavar="1|2",
                   help="the protocol version spoken to the program (default 1; 2 with --kit)")
    p.add_argument("--kit", metavar="JSON", help="the program's marker kit, e.g. '{\"undirected-edge\": 3}' "
                                                  "(implies --protocol 2; default {\"directional-vertex\": 1})")


def _protocol_choice(args) -> tuple[int, Kit | None]:
    """(version, kit) from --protocol and --kit: a kit implies @2 and cannot go with --protocol 1."""
    if args.kit is None:
        return args.protocol or 1, None
    if args.protocol == 1:
        raise InvalidInput("--kit needs topomark/protocol@2: give --protocol 2 (or leave --protocol out); "
                           "topomark/protocol@1 knows only the kit {\"directional-vertex\": 1}")
    try:  # like a world file, a key named twice is refused (JSON would keep the last silently)
        kit = Kit.from_json(parse_json(args.kit, "--kit", object_pairs_hook=no_duplicate_keys))
    except InvalidInput as exc:
        raise InvalidInput(str(exc) if str(exc).startswith("--kit") else f"--kit: {exc}") from None
    counts = (kit.vertex, kit.edge, kit.either)
    if max(counts) > MAX_COUNT or (sum(counts) == 0 and kit.thread is None):
        raise InvalidInput(f"--kit: give 1..{MAX_COUNT} vertex or edge markers or a thread, got {kit.to_json()}")
    return 2, kit


def _no_action() -> int:
    raise InvalidInput("conformance needs an action: export DIR, lint DIR or run DIR -- CMD")


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


def _make_limits(args) -> Limits:
    for name in ("timeout", "message_timeout"):
        check_seconds(getattr(args, name), f"--{name.replace('_', '-')}")
    for name in ("max_traversals", "max_operations"):
        if getattr(args, name, None) is not None:
            check_count(getattr(args, name), f"--{name.replace('_', '-')}")
    return Limits(args.max_traversals, args.timeout, args.message_timeout, getattr(args, "max_operations", None))


def register(sub) -> None:
    p = sub.add_parser("run-external",
                       description="Run CMD as the explorer of WORLD (a world file or generator) over JSON Lines on "
                                   "its stdin/stdout (spec/protocol.md). Exit 0 if its map is extended-isomorphic "
                                   "and every snapshot satisfied I-1/I-2, 1 on any failure, 2 on bad input.")
    p.add_argument("world", metavar="WORLD", help=WORLD_HELP)
    p.add_argument("cmd", nargs=argparse.REMAINDER, metavar="-- CMD [ARGS...]",
                   help="the program and its arguments, after --")
    _run_options(p)
    p.set_defaults(handler=run_external_command, add_options=_run_options)

    q = sub.add_parser("check-map",
                       description="Exit 0 if MAP is extended-isomorphic to WORLD, 1 if not (with the first mismatch "
                                   "in words), 2 on bad input. Markers: compared if the world file has any; else, if "
                                   "the world has a start and the map one directional vertex marker, the lighthouse "
                                   "Algorithm 3.1 drops at the start is added; else ignored.")
    q.add_argument("world", metavar="WORLD", help="the world file")
    q.add_argument("map", metavar="MAP", help="the map file to judge (world format)")
    q.add_argument("--json", action="store_true", help=JSON_HELP)
    q.set_defaults(handler=check_map_command)

    r = sub.add_parser("replay",
                       description="Replay TRACE on WORLD: every perception, the cost, I-1/I-2 after every "
                                   "iteration (S and U rebuilt from the joins) and the final map. Exit 0 if it "
                                   "holds up, 1 at the first divergence (step, expected, found), 2 on bad input.")
    r.add_argument("world", metavar="WORLD", help="the world file the trace was recorded on")
    r.add_argument("trace", metavar="TRACE", help="the JSON Lines trace file to replay")
    r.add_argument("--json", action="store_true", help=JSON_HELP)
    r.set_defaults(handler=replay_command)

    d = sub.add_parser("drive",
                       description="Run CMD as the world (spec/protocol.md, provider role): topomark sends motions "
                                   "and marker drops, CMD answers with signatures. Exit 0 when a map was made (and, "
                                   "with --check WORLD, is extended-isomorphic to it), 1 on failure, 2 on bad input.")
    d.add_argument("cmd", nargs=argparse.REMAINDER, metavar="-- CMD [ARGS...]",
                   help="the world provider and its arguments, after --")
    _drive_options(d)
    d.set_defaults(handler=drive_command, add_options=_drive_options)

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
    ce.add_argument("dir", metavar="DIR", help="the directory to write (new or empty)")
    _suite_choice(ce, "write the suite of the algorithm NAME only (repeatable; default: every deterministic one)")
    ce.add_argument("--json", action="store_true", help=JSON_HELP)
    ce.set_defaults(handler=conformance_export)
    cl = csub.add_parser("lint", help="check a suite directory")
    cl.add_argument("dir", metavar="DIR", help="the suite directory")
    cl.add_argument("--json", action="store_true", help=JSON_HELP)
    cl.set_defaults(handler=conformance_lint)
    cr = csub.add_parser("run", help="run CMD on every case (of Algorithm 3.1, or of --algorithm/--family)")
    cr.add_argument("dir", metavar="DIR", help="the suite directory (topomark conformance export DIR)")
    cr.add_argument("cmd", nargs=argparse.REMAINDER, metavar="-- CMD [ARGS...]",
                    help="the implementation under test and its arguments, after --")
    _conformance_options(cr)
    cr.set_defaults(handler=conformance_run, add_options=_conformance_options)
    c.set_defaults(handler=lambda args: _no_action())


def run_external_command(args) -> int:
    world = resolve_world(args.world, args.seed)
    command = _command(args)
    version, kit = _protocol_choice(args)
    result = run_external(world, command, _make_limits(args), version=version, kit=kit)
    if args.map and result.map is not None:
        guarded(args.map, lambda: save_world(result.map, args.map))
    data = {"world": args.world, "command": command, **result.to_json()}
    text = (f"{'PASS' if result.passed else 'FAIL'} [{result.reason}] {result.message}\n"
            f"cost {result.cost} traversals (n={world.n}, m={world.m}), {result.snapshots} snapshots checked, "
            f"{result.wall:.2f} s: the program {result.program_seconds:.2f} s (limited by --timeout), "
            f"topomark's checking {result.topomark_seconds:.2f} s")
    if not result.passed and result.stderr:
        text += "\nprogram stderr (tail):\n  " + "\n  ".join(result.stderr[-5:])
    emit(args, data, text)
    return 0 if result.passed else 1


def check_map_command(args) -> int:
    world, map_ = load_world(args.world), load_world(args.map)
    verdict = check_map(world, map_)
    data = {"world": args.world, "map": args.map, **verdict.to_json()}
    emit(args, data, f"{args.map}: {verdict.words()}")
    return 0 if verdict.isomorphic else 1


def replay_command(args) -> int:
    world = load_world(args.world)
    result = replay(world, load_trace(args.trace), args.trace)
    data = {"world": args.world, "trace": args.trace, **result.to_json()}
    emit(args, data, ("VERIFIED " if result.ok else "DIVERGED ") + result.message)
    return 0 if result.ok else 1


def drive_command(args) -> int:
    command = _command(args)
    limits = _make_limits(args)
    policies = parse_policies(args.policy)
    world = load_world(args.check) if args.check else None
    light = lighthouse(args.lighthouse)
    result = drive(command, policies, world, limits.max_traversals, limits.wall, limits.message, light,
                   trace=args.trace or None)
    if args.map and result.map is not None:
        guarded(args.map, lambda: save_world(result.map, args.map))
    data = {"command": command, **result.to_json()}
    text = f"{'PASS' if result.passed else 'FAIL'} [{result.reason}] {result.message}\ncost {result.cost} traversals"
    if not result.passed and result.stderr:
        text += "\nprovider stderr (tail):\n  " + "\n  ".join(result.stderr[-5:])
    emit(args, data, text)
    return 0 if result.passed else 1


def _suite_summary(manifest: dict) -> dict:
    suites = manifest.get("suites", [])
    return {"format": manifest["format"], "version": manifest["version"], "cases": len(manifest["cases"]),
            "policies": list(manifest["policies"]), "algorithms": [s["algorithm"] for s in suites],
            "algorithm_cases": sum(len(s["cases"]) for s in suites)}


def _describe(info: dict) -> str:
    return (f"{info['format']} version {info['version']}, {info['cases']} Algorithm 3.1 cases x "
            f"{len(info['policies'])} policies, {len(info['algorithms'])} algorithm suites "
            f"({info['algorithm_cases']} cases)")


def conformance_export(args) -> int:
    chosen = conformance.suite_algorithms(args.algorithm, args.family)
    manifest = guarded(args.dir, lambda: conformance.export(args.dir, algorithms=chosen))
    info = _suite_summary(manifest)
    emit(args, {"dir": args.dir, **info}, f"wrote {args.dir}: {_describe(info)} (linted)")
    return 0


def conformance_lint(args) -> int:
    info = _suite_summary(conformance.lint(args.dir))
    emit(args, {"dir": args.dir, "ok": True, **info}, f"{args.dir}: ok ({_describe(info)})")
    return 0


def _chosen_algorithms(args) -> list[str]:
    """--algorithm and --family: the algorithms whose suites to run (protocol @2, the cases' own kits)."""
    if not (args.algorithm or args.family):
        return []
    if args.kit is not None or args.protocol == 1:
        raise InvalidInput("--algorithm and --family run each case with its own kit over topomark/protocol@2: "
                           "leave out --kit and --protocol 1")
    return [spec.name for spec in conformance.suite_algorithms(args.algorithm, args.family)]


def conformance_run(args) -> int:
    command = _command(args)
    limits = _make_limits(args)
    algorithms = _chosen_algorithms(args)
    version, kit = _protocol_choice(args)
    show = None if args.json else (lambda row: print(f"  {row.to_json()['case']}: {row.to_json()['verdict']}",
                                                     file=sys.stderr))
    rows, wall = conformance.timed_run(args.dir, command, limits, args.select, show, version, kit, algorithms)
    passed = sum(r.passed for r in rows)
    data = {"dir": args.dir, "command": command, "protocol": 2 if algorithms else version, "algorithms": algorithms,
            "passed": passed, "total": len(rows), "wall_seconds": round(wall, 3), "cases": [r.to_json() for r in rows]}
    table = conformance.render_algorithm_table(rows, wall) if algorithms else conformance.render_table(rows, wall)
    emit(args, data, table)
    return 0 if passed == len(rows) else 1

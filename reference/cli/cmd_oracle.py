"""topomark as an oracle for other implementations: ``run-external``, ``replay``, ``check-map``,
``conformance``, ``drive`` (thesis §3.1, §3.3–3.4, §3.6).

Exit codes as everywhere: 0 positive verdict, 1 negative verdict, 2 bad input.
Every command takes ``--json``.  Their options are :mod:`topomark.reference.cli.options.oracle`'s; this module
is imported when one runs.
"""

from __future__ import annotations

from pathlib import Path
from typing import cast
import sys

from topomark.spec.errors import InvalidInput, Violation
from topomark.spec.jsontext import no_duplicate_keys, parse_json
from topomark.spec.kit import Kit
from topomark.spec.world import World
from topomark.spec.worldfile import load_world, save_world

from topomark.reference.oracle import conformance
from topomark.reference.cli.parser import Parser, emit
from topomark.reference.cli.args import check_count, check_seconds
from topomark.reference.cli.cmd_explore import parse_policies
from topomark.reference.oracle.drive import drive
from topomark.reference.explorers.lighthouses import lighthouse
from topomark.reference.oracle.program_trace import ProgramTrace
from topomark.reference.oracle.run_external import Limits, run_external
from topomark.reference.run.map_check import check_map
from topomark.reference.files.outputs import check_output_dir, guarded, write_output
from topomark.reference.files.overwrite import claim_dir, claim_file
from topomark.reference.replay.replay import ReplayResult, load_trace, replay
from topomark.spec.kit import MAX_COUNT
from topomark.reference.worlds.argument import resolve_world

__all__ = ["run_external_command", "check_map_command", "replay_command", "drive_command",
           "conformance_export", "conformance_lint", "conformance_run"]


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
    if kit.vertex + kit.edge + kit.either == 0 and kit.thread is None:
        raise InvalidInput(f"--kit: give 1..{MAX_COUNT:,} vertex or edge markers or a thread, got {kit.to_json()}")
    past_caps = kit.cap_refusal()
    if past_caps is not None:
        raise InvalidInput(f"--kit: {past_caps}")
    return 2, kit

def _make_limits(args) -> Limits:
    for name in ("timeout", "message_timeout"):
        check_seconds(getattr(args, name), f"--{name.replace('_', '-')}")
    for name in ("max_traversals", "max_operations"):
        if getattr(args, name, None) is not None:
            check_count(getattr(args, name), f"--{name.replace('_', '-')}")
    return Limits(args.max_traversals, args.timeout, args.message_timeout, getattr(args, "max_operations", None))

def run_external_command(args) -> int:
    world = resolve_world(args.world, args.seed)
    command = _command(args)  # the options written after the world are read here: --map is claimed after it
    claim_file(args.map, "--map", args.force)
    version, kit = _protocol_choice(args)
    result = run_external(world, command, _make_limits(args), version=version, kit=kit)
    if args.map is not None and result.map is not None:
        guarded(args.map, lambda: save_world(cast(World, result.map), args.map))
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
    if args.view is not None:
        from topomark.reference.viewer.view import view_trace
        claim_file(args.view, "--view", args.force)
        result = cast(ReplayResult, view_trace(args.trace, world, args.view).result)
    else:
        result = replay(world, load_trace(args.trace), args.trace)
    data = {"world": args.world, "trace": args.trace, **result.to_json()}
    emit(args, data, ("VERIFIED " if result.ok else "DIVERGED ") + result.message)
    return 0 if result.ok else 1


def drive_command(args) -> int:
    command = _command(args)
    claim_file(args.trace, "--trace", args.force)
    claim_file(args.map, "--map", args.force)
    limits = _make_limits(args)
    policies = parse_policies(args.policy)
    world = load_world(args.check) if args.check else None
    light = lighthouse(args.lighthouse)
    result = drive(command, policies, world, cast(int, limits.max_traversals), limits.wall, limits.message, light,
                   trace=args.trace or None)
    if args.map is not None and result.map is not None:
        guarded(args.map, lambda: save_world(cast(World, result.map), args.map))
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
    suite = tuple(sorted({entry.partition("/")[0] for entry in conformance.LAYOUT}))
    claim_dir(args.dir, "conformance export", args.force, replace=suite, alone=True)
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
    claim_dir(args.view_failures, "--view-failures", args.force, replace=("*.jsonl", "*.html"))
    rows, wall = conformance.timed_run(args.dir, command, limits, args.select, show, version, kit, algorithms,
                                       record=args.view_failures is not None)
    passed = sum(r.passed for r in rows)
    data = {"dir": args.dir, "command": command, "protocol": 2 if algorithms else version, "algorithms": algorithms,
            "passed": passed, "total": len(rows), "wall_seconds": round(wall, 3), "cases": [r.to_json() for r in rows]}
    table = conformance.render_algorithm_table(rows, wall) if algorithms else conformance.render_table(rows, wall)
    if args.view_failures is not None:
        pages = _view_failures(args.view_failures, rows)
        data["views"] = pages
        table += f"\n{len(pages)} failing case{'s' if len(pages) != 1 else ''} drawn in {args.view_failures}"
    emit(args, data, table)
    return 0 if passed == len(rows) else 1


def _view_failures(directory: str, rows: list) -> list[str]:
    """Each failing case's trace and viewer page in ``directory`` (:mod:`topomark.reference.viewer`); the pages'
    names."""
    from topomark.reference.trace.records import dump_trace
    from topomark.reference.viewer.view import view_trace

    check_output_dir(directory)
    pages = []
    for row in rows:
        if row.passed:
            continue
        r, program = row.result, cast(ProgramTrace, row.result.program)  # kept: the run was recorded
        name = (row.name if isinstance(row, conformance.Row) else f"{row.algorithm}-{row.case['name']}")
        stem = str(Path(directory) / "".join(c if c.isalnum() or c in "-_." else "_" for c in name))
        write_output(stem + ".jsonl", dump_trace(program.records()))
        failure = r.violation or Violation("conformance", r.reason, "a pass: a correct map within the limits",
                                           r.message, f"the program's verdict: {r.verdict} ({r.reason})")
        view_trace(stem + ".jsonl", program.world, stem + ".html", f"{name}: {r.reason}", failure)
        pages.append(stem + ".html")
    return pages

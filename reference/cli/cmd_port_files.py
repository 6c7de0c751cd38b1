"""``topomark port import|export|run|show``: port world files in and out, plans run, a world summarised.

Its options are :mod:`topomark.reference.cli.options.port_files`'s; this module is imported when it runs."""

from __future__ import annotations

import json
from pathlib import Path

from topomark.spec.errors import InvalidInput, InvalidWorld, require_input
from topomark.spec.jsontext import no_duplicate_keys, parse_json, read_text_file
from topomark.spec.port_icfpc import submission_from_json, submission_to_json
from topomark.spec.port_plan import InvalidPlan, Action, check_length, explore_cost, parse_plan, plan_text, run_plan
from topomark.spec.port_world import PortWorld, from_thesis_world
from topomark.spec.port_worldfile import dumps_port_world

from topomark.reference.cli.parser import emit
from topomark.reference.files.overwrite import claim_dir, claim_file
from topomark.reference.port.files import MAX_PORT_FILE_BYTES, load_port_document_file
from topomark.reference.port.summary import summarise
from topomark.reference.worlds.argument import resolve_world

__all__ = ["import_command", "export_command", "run_command", "show_command", "read_contest_file"]

MAX_PLANS_FILE_BYTES = 64 << 20


def read_contest_file(path: Path) -> tuple[str, PortWorld]:
    """The problem name and world of a contest map file, strictly ({"problemName", "map"} and nothing else)."""
    obj = parse_json(read_text_file(path, InvalidWorld, MAX_PORT_FILE_BYTES), str(path), InvalidWorld,
                     object_pairs_hook=no_duplicate_keys)
    try:
        return submission_from_json(obj)
    except InvalidWorld as e:
        raise InvalidWorld(f"{path}: {e}") from None


def import_command(args) -> int:
    if args.source == "thesis":
        return _import_thesis(args)
    require_input(args.colour is None and args.start is None,
                  f"--{'colour' if args.colour is not None else 'start'} has no effect on an icfpc2025 import")
    src = Path(args.input)
    if src.is_dir():
        files = sorted(p for p in src.rglob("*.json") if p.is_file())
        require_input(bool(files), f"{args.input}: the directory holds no *.json file")
        jobs = [(p.relative_to(src), *read_contest_file(p)) for p in files]  # every file checked before writing
        claim_dir(args.output, "-o", args.force)
        out = Path(args.output)
        for rel, name, world in jobs:
            (out / rel).parent.mkdir(parents=True, exist_ok=True)
            (out / rel).write_text(dumps_port_world(world, problem=name), encoding="utf-8")
    else:
        name, world = read_contest_file(src)
        claim_file(args.output, "-o", args.force)
        Path(args.output).write_text(dumps_port_world(world, problem=name), encoding="utf-8")
        jobs = [(Path(src.name), name, world)]
    sizes = [w.rooms for _, _, w in jobs]
    data = {"imported": len(jobs), "output": args.output, "rooms_min": min(sizes), "rooms_max": max(sizes),
            "files": [{"file": str(rel), "problem": name, "rooms": w.rooms} for rel, name, w in jobs]}
    span = f"{min(sizes)} rooms" if min(sizes) == max(sizes) else f"{min(sizes)} to {max(sizes)} rooms"
    emit(args, data, f"imported {len(jobs)} map{'s' if len(jobs) != 1 else ''} into {args.output} ({span})")
    return 0


def _import_thesis(args) -> int:
    thesis = resolve_world(args.input)
    rotation = {v: list(ns) for v, ns in thesis.rotation.items()}
    default = thesis.start.at if thesis.start is not None else next(iter(rotation))
    start = default if args.start is None else args.start
    require_input(start in rotation, f"--start {start!r} is not a vertex of {args.input}")
    world, names = from_thesis_world(rotation, start, colour_by_degree=args.colour != "none")
    claim_file(args.output, "-o", args.force)
    Path(args.output).write_text(dumps_port_world(world, names=names), encoding="utf-8")
    data = {"imported": 1, "output": args.output, "rooms": world.rooms, "doors": world.doors,
            "alphabet": world.alphabet, "start": names[0]}
    emit(args, data, f"wrote {args.output}: {world.rooms} rooms of {world.doors} doors, start {names[0]!r}, "
                     f"colours {'by degree' if args.colour != 'none' else 'all 0'}")
    return 0


def export_command(args) -> int:
    doc = load_port_document_file(args.world)
    problem = args.problem if args.problem is not None else doc.problem
    require_input(problem is not None, f"{args.world} names no problem; give --problem NAME")
    obj = submission_to_json(str(problem), doc.world)
    submission_from_json(obj)  # the written file must read back (problemName's own rules)
    claim_file(args.output, "-o", args.force)
    Path(args.output).write_text(json.dumps(obj) + "\n", encoding="utf-8")
    emit(args, {"output": args.output, "problem": problem, "rooms": doc.world.rooms},
         f"wrote {args.output}: problem {problem!r}, {doc.world.rooms} rooms")
    return 0


def _plans(args, world: PortWorld) -> list[tuple[str, tuple[Action, ...]]]:
    texts = list(args.plans)
    if args.plans_file is not None:
        text = read_text_file(args.plans_file, InvalidInput, MAX_PLANS_FILE_BYTES)
        texts.extend(line.strip() for line in text.splitlines() if line.strip())
    require_input(bool(texts), "no plan given: name plans as arguments or give --plans FILE")
    plans = []
    for k, text in enumerate(texts, 1):
        try:
            actions = parse_plan(text, doors=world.doors, alphabet=world.alphabet)
            check_length(actions, world.rooms, args.round)
        except InvalidPlan as e:
            raise InvalidPlan(f"plan {k}: {e}") from None
        plans.append((text, actions))
    return plans


def run_command(args) -> int:
    world = load_port_document_file(args.world).world
    plans = _plans(args, world)
    results = [list(run_plan(world, actions, echo_marks=not args.no_echo)) for _, actions in plans]
    cost = explore_cost(len(plans))
    lines = [f"{plan_text(actions) or '(empty)'}: {''.join(map(str, r)) if world.alphabet <= 10 else r}"
             for (_, actions), r in zip(plans, results)]
    lines.append(f"queryCount: {cost}")
    emit(args, {"results": results, "queryCount": cost}, "\n".join(lines))
    return 0


def show_command(args) -> int:
    doc = load_port_document_file(args.world)
    s = summarise(doc.world)
    start = doc.names[doc.world.start] if doc.names is not None else None
    data = {**s, "problem": doc.problem, "start_name": start}
    head = f"{args.world}" + (f" (problem {doc.problem})" if doc.problem is not None else "")
    text = "\n".join([
        head,
        f"rooms {s['rooms']}, doors {s['doors']} a room, start room {s['start']}"
        + (f" ({start})" if start is not None else ""),
        f"passages {s['passages']}: {s['self_joined_doors']} doors joined to themselves, {s['same_room_passages']} "
        f"joining two doors of one room, {s['parallel_passages']} parallel to another",
        "colours " + ", ".join(f"{c}: {n} room{'s' if n != 1 else ''}" for c, n in enumerate(s["colour_counts"])),
    ])
    emit(args, data, text)
    return 0

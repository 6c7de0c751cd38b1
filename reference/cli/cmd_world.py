"""``topomark world`` and ``topomark iso``: make, show and compare worlds (thesis §3.1).

Their options are :mod:`topomark.reference.cli.options.world`'s; this module is imported when one runs."""

from __future__ import annotations

import json
import sys
from collections import Counter
from typing import cast

from topomark.spec.dartgraph import find_isomorphism_nx
from topomark.spec.errors import InvalidInput, TopomarkFault, Violation, unknown_name
from topomark.spec.isomorphism import Witness, find_isomorphism, verify_witness
from topomark.spec.worldfile import dumps_world, load_world, world_to_json

from topomark.reference.worlds.generators import GENERATORS
from topomark.reference.files.outputs import write_output
from topomark.reference.files.overwrite import claim_file
from topomark.reference.worlds.argument import resolve_world

__all__ = ["describe", "world_command", "iso_command", "draw_command"]


def describe(world) -> dict:
    """n, m, degree histogram, genus, faces, markers and start of a world."""
    hist = Counter(world.degree(v) for v in world.vertices)
    data = world_to_json(world)
    return {"n": world.n, "m": world.m, "degree_histogram": {str(k): hist[k] for k in sorted(hist)},
            "faces": world.faces(), "genus": world.genus(), "markers": data.get("markers", []),
            "start": data.get("start")}


def draw_command(args) -> int:
    """``world --draw GENERATOR_OR_FILE -o FILE``: the world drawn (:mod:`topomark.proofs.drawing`); a world
    without a start is drawn with the start exploration gives it (the first vertex facing exit 0)."""
    from topomark.proofs.drawing import save_world
    from topomark.proofs.drawing_png import check_drawable
    from topomark.spec.world import Start

    if args.generator or args.show or args.output is None:
        raise InvalidInput("world --draw GENERATOR_OR_FILE takes -o FILE (.svg or .png) and no other GENERATOR or "
                           "--show")
    claim_file(args.output, "-o", args.force)
    check_drawable(args.output)
    world = resolve_world(args.draw, args.seed)
    note = ""
    if world.start is None:
        at, exit_ = world.start_state()
        world = world.with_start(Start(at, world.neighbour(at, exit_)))
        note = "no start given: drawn at the default, the first vertex facing exit 0"
    save_world(world, args.output, args.draw, note)
    info = describe(world)
    print(json.dumps({"file": args.output, "n": info["n"], "m": info["m"]}) if args.json else
          f"drew {args.output}: n={info['n']} m={info['m']} genus={info['genus']}")
    return 0


def world_command(args) -> int:
    if args.draw:
        return draw_command(args)
    if args.show:
        if args.generator or args.output is not None or args.seed is not None:
            raise InvalidInput("world --show FILE takes no generator, --seed or -o/--out")
        info = describe(load_world(args.show))
        text = (f"{args.show}: n={info['n']} m={info['m']} genus={info['genus']} faces={info['faces']}\n"
                f"degree histogram: " + ", ".join(f"{k}:{v}" for k, v in info["degree_histogram"].items()) +
                f"\nmarkers: {json.dumps(info['markers'])}\nstart: {json.dumps(info['start'])}")
        print(json.dumps(info, indent=1) if args.json else text)
        return 0
    if not args.generator:
        raise InvalidInput(f"world needs a GENERATOR ({', '.join(GENERATORS)}) or --show FILE")
    name = args.generator.partition(":")[0]
    if name not in GENERATORS:
        raise unknown_name("generator", name, GENERATORS)
    claim_file(args.output, "-o", args.force)  # before generating: a large world must not be built for nothing
    world = resolve_world(args.generator, args.seed)
    if args.output is not None:
        write_output(args.output, dumps_world(world))
        info = describe(world)
        msg = f"wrote {args.output}: n={info['n']} m={info['m']} genus={info['genus']}"
        print(json.dumps({"file": args.output, **info}) if args.json else msg)
    else:
        sys.stdout.write(dumps_world(world))
    return 0


def iso_command(args) -> int:
    a, b = load_world(args.a), load_world(args.b)
    markers = not args.ignore_markers
    results = {}
    if args.method in ("anchored", "both"):
        results["anchored"] = find_isomorphism(a, b, markers=markers)
    if args.method in ("networkx", "both"):
        results["networkx"] = find_isomorphism_nx(a, b, markers=markers)
    verdicts = {r.isomorphic for r in results.values()}
    if len(verdicts) != 1:
        raise TopomarkFault(f"the isomorphism implementations disagree: "
                           f"{ {k: r.isomorphic for k, r in results.items()} }",
                            check="isomorphism implementations agree")
    result = next(iter(results.values()))
    if result.isomorphic:
        for name, r in results.items():
            bad = verify_witness(a, b, cast(Witness, r.witness), markers=markers)  # isomorphic: witnessed
            if bad is not None:
                raise TopomarkFault(f"the {name} isomorphism's witness fails re-verification: {bad}",
                                    check="witness re-verification")
        data = {"isomorphic": True, "witness": cast(Witness, result.witness).to_json(), "methods": list(results)}
        text = (f"isomorphic: {args.a} ≅ {args.b} (extended isomorphism"
                + (", markers preserved" if markers else ", markers ignored") + "; witness verified)")
        print(json.dumps(data, indent=1) if args.json else text)
        return 0
    data = {"isomorphic": False, "mismatch": cast(Violation, result.mismatch).to_json(), "methods": list(results)}
    text = f"not isomorphic: {result.mismatch}"
    print(json.dumps(data, indent=1) if args.json else text)
    return 1

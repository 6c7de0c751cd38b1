"""``topomark port judge|minimise|suite``: the exact judge of port maps (:mod:`topomark.reference.port.judge`).

Its options are :mod:`topomark.reference.cli.options.port_judge`'s; this module is imported when it runs."""

from __future__ import annotations

import json
from pathlib import Path

from topomark.reference.cli.parser import emit
from topomark.reference.files.outputs import write_output
from topomark.reference.files.overwrite import claim_file
from topomark.reference.port.files import load_port_file
from topomark.reference.port.judge import judge
from topomark.reference.port.minimise import minimise
from topomark.reference.port.suite import run_suite, summary
from topomark.spec.port_icfpc import submission_to_json

__all__ = ["judge_command", "minimise_command", "suite_command"]


def judge_command(args) -> int:
    _, a = load_port_file(args.first)
    _, b = load_port_file(args.second)
    v = judge(a, b, echo_marks=not args.no_echo, names=(args.first, args.second))
    data = {"equivalent": v.equivalent, "witness": v.witness, "reason": v.reason,
            "records": None if v.records is None else {"a": list(v.records[0]), "b": list(v.records[1])},
            "rooms": {"a": a.rooms, "b": b.rooms}}
    if v.equivalent:
        text = f"equivalent: {v.reason}"
    elif v.witness is None:
        text = f"different: {v.reason}"
    else:
        assert v.records is not None
        text = (f"different: {v.reason}\nplan:      {v.witness}\nrecord on {args.first}: "
                f"{''.join(map(str, v.records[0]))}\nrecord on {args.second}: {''.join(map(str, v.records[1]))}")
    emit(args, data, text)
    return 0 if v.equivalent else 1


def minimise_command(args) -> int:
    claim_file(args.output, "-o", args.force)
    problem, world = load_port_file(args.map)
    m = minimise(world)
    data = {"rooms": world.rooms, "minimal_rooms": len(m.fibres), "copies": m.copies,
            "fibres": [list(f) for f in m.fibres], "output": args.output if m.quotient is not None else None,
            "layers": {f"{b}.{d}": list(m.layers[b * world.doors + d])
                       for b in range(len(m.fibres)) for d in range(world.doors)} if m.copies else None}
    lines = [f"{args.map}: {world.rooms} rooms, {len(m.fibres)} blocks of plainly equivalent rooms"]
    if m.quotient is None:
        sizes = sorted({len(f) for f in m.fibres})
        lines.append(f"the blocks have sizes {sizes}: no port world of {len(m.fibres)} rooms is equivalent "
                     "(door-ends cannot be paired); nothing written")
    else:
        lines.append(f"a {m.copies}-copy map of its {m.quotient.rooms}-room quotient (checked with the judge)")
        if m.copies and m.copies > 1:
            lines += [f"  block {b}: rooms {' '.join(map(str, f))}" for b, f in enumerate(m.fibres)]
            lines.append("per passage B.d-C.e of the quotient, the layer of C that layer 0, 1, ... of B leads to:")
            lines += [f"  {x[0]}.{x[1]}-{y[0]}.{y[1]}: {' '.join(map(str, m.layers[x[0] * world.doors + x[1]]))}"
                      for x, y in m.quotient.passages()]
        if args.output is not None:
            doc = submission_to_json(problem or "minimised", m.quotient)
            write_output(args.output, json.dumps(doc, indent=1) + "\n")
            lines.append(f"wrote {args.output}")
    emit(args, data, "\n".join(lines))
    return 0


def suite_command(args) -> int:
    results = run_suite(Path(args.directory), Path(args.manifest) if args.manifest else None)
    s = summary(results)
    failed = [r for r in results if not r.ok]
    data = {"summary": s, "maps": [{"file": r.file, "ok": r.ok, "rooms": r.rooms, "minimal_rooms": r.minimal,
                                    "manifest_minimal_rooms": r.expected_minimal, "copies": r.copies,
                                    "error": r.error, "problem": r.problem,
                                    "verdicts": [{"kind": t.kind, "equivalent": t.equivalent, "witness": t.witness,
                                                  "ms": round(1000 * t.seconds, 3)} for t in r.trials]}
                                   for r in results]}
    lines = [f"{s['maps']} maps, {s['imported']} imported, {s['minimal_as_manifest']}/{s['with_manifest_size']} "
             f"minimal sizes as the manifest says, {s['ok']} ok; {s['verdicts']} verdicts, median "
             f"{s['median_ms']} ms, max {s['max_ms']} ms"]
    kinds = s["kinds"]
    assert isinstance(kinds, dict)
    lines += [f"  {k}: {v['equivalent']} equivalent, {v['different']} different ({v['with-mark']} need a mark)"
              for k, v in kinds.items()]
    lines += [f"FAILED {r.file}: {r.problem}" for r in failed]
    emit(args, data, "\n".join(lines))
    return 0 if not failed else 1

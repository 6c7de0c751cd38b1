"""``topomark port solve``: a map consistent with an exploration's records, and whether they pin it down
(:mod:`topomark.reference.port.solve`).

Its options are :mod:`topomark.reference.cli.options.port_solve`'s; this module is imported when it runs."""

from __future__ import annotations

import json

from topomark.spec.errors import require_input
from topomark.spec.port_plan import plan_text
from topomark.spec.port_world import CONTEST_ALPHABET, CONTEST_DOORS, MAX_DOORS

from topomark.proofs.port_consistent import MAX_SOLVE_ROOMS

from topomark.reference.cli.parser import emit
from topomark.reference.files.outputs import write_output
from topomark.reference.files.overwrite import claim_file
from topomark.reference.port.solve import read_exchange, solve_records, world_json

__all__ = ["solve_command"]


def solve_command(args) -> int:
    require_input(1 <= args.doors <= min(10, MAX_DOORS), f"--doors: 1 to 10 (a plan names a door by one digit), "
                  f"not {args.doors}")
    require_input(1 <= args.alphabet, f"--alphabet: 1 or more colours, not {args.alphabet}")
    require_input(args.timeout is None or args.timeout > 0, f"--timeout: a positive number of seconds, "
                  f"not {args.timeout}")
    require_input(1 <= args.rooms <= MAX_SOLVE_ROOMS, f"--rooms: 1 to {MAX_SOLVE_ROOMS}, not {args.rooms}")
    require_input(args.output is None or (args.doors == CONTEST_DOORS and args.alphabet <= CONTEST_ALPHABET),
                  f"-o writes a contest map, which has {CONTEST_DOORS} doors a room and at most "
                  f"{CONTEST_ALPHABET} colours; without -o the maps are printed (--json) whatever their shape")
    claim_file(args.output, "-o", args.force)
    plans, records = read_exchange(args.exchange, doors=args.doors, alphabet=args.alphabet)
    solution = solve_records(plans, records, args.rooms, doors=args.doors, alphabet=args.alphabet,
                             echo_marks=args.echo, timeout=args.timeout)
    if args.output is not None and solution.first is not None:
        write_output(args.output, json.dumps(world_json(solution.first), indent=1) + "\n")
    data = {"exchange": args.exchange, "rooms": args.rooms, "doors": args.doors, "alphabet": args.alphabet,
            "echo_marks": args.echo, "plans": len(plans), "output": args.output if solution.first else None,
            **solution.to_json()}
    emit(args, data, _text(args, solution))
    return 0 if solution.status == "pinned" else 1


def _text(args, solution) -> str:
    n = args.rooms
    wrote = f"; wrote {args.output}" if args.output is not None and solution.first is not None else ""
    if solution.status == "none":
        return f"no map of {n} room{'s' if n != 1 else ''} gives these records"
    if solution.status == "unknown":
        return f"unknown: Z3 gave up ({solution.reason}); no verdict"
    first = json.dumps(world_json(solution.first))
    if solution.status == "pinned":
        return f"pinned down: every map of {n} rooms that gives these records is equivalent to\n{first}{wrote}"
    plan = plan_text(solution.witness)
    ra, rb = solution.records
    return (f"not pinned down: two maps of {n} rooms give these records and the plan {plan} tells them apart\n"
            f"map A: {first}\nmap B: {json.dumps(world_json(solution.second))}\n"
            f"{plan} on A: {list(ra)}\n{plan} on B: {list(rb)}{wrote}")

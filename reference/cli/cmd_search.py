"""``topomark search``: bounded SAT search for counterexamples and bounded proofs (thesis §3.2, §3.7, §6.1).

Its options are :mod:`topomark.reference.cli.options.search`'s; this module is imported when it runs.

``topomark search --marker CLASS --max-vertices N --max-degree D`` asks Z3
(:mod:`topomark.proofs.z3search`) for two worlds of the marker class that no
motion sequence tells apart (§3.1.1) yet are not extended-isomorphic.

* without ``--prove``: exit 0 when a counterexample is found (the worlds, the
  relation size and a shared motion/perception sequence in thesis notation are
  printed; ``--out DIR`` writes ``a.json``, ``b.json``, ``relation.json`` and
  ``pair.svg``), exit 1 when there is none within the bounds or the solver
  gave up (``unknown (timeout)``; JSON ``"outcome": "unknown"``);
* with ``--prove`` (for a class the thesis says is sufficient): exit 0 when
  every size pair is UNSAT, 1 when a counterexample is found or the answer is
  unknown.

Bad options exit 2 with one message.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from topomark.proofs import z3search
from topomark.reference.cli.args import check_seconds
from topomark.spec.errors import InvalidInput
from topomark.spec.markerclass import marker_class
from topomark.spec.world import MAX_DEGREE
from topomark.spec.worldfile import save_world

from topomark.reference.files.outputs import guarded
from topomark.reference.files.overwrite import claim_dir

__all__ = ["search_command", "validate_args", "describe_world", "write_outputs"]


def validate_args(args: argparse.Namespace) -> None:
    """Precise messages for options argparse cannot check."""
    marker_class(args.marker)
    if args.max_vertices < 2:
        raise InvalidInput(f"--max-vertices must be at least 2 (a world has two or more vertices), "
                           f"got {args.max_vertices}")
    if args.max_vertices > z3search.MAX_VERTICES:
        raise InvalidInput(f"--max-vertices {args.max_vertices} is too large: at most {z3search.MAX_VERTICES}")
    if args.max_degree < 1:
        raise InvalidInput(f"--max-degree must be at least 1, got {args.max_degree}")
    if args.max_degree > MAX_DEGREE:
        raise InvalidInput(f"--max-degree {args.max_degree} is larger than any world's degree can be "
                           f"(at most {MAX_DEGREE:,}, topomark.spec.world.MAX_DEGREE)")
    if args.timeout is not None:
        check_seconds(args.timeout, "--timeout")
    claim_dir(args.out, "-o", args.force)


def describe_world(name: str, world) -> str:
    rot = "; ".join(f"{v}: {' '.join(ns)}" for v, ns in world.rotation.items())
    marks = ", ".join(repr(m) for m in world.markers) or "no markers"
    return (f"{name}: n={world.n} m={world.m} genus={world.genus()} start {world.start.at} facing "
            f"{world.start.facing}; {marks}\n   rotation {rot}")


def write_outputs(result: z3search.SearchResult, out: str) -> list[str]:
    """a.json, b.json, relation.json and pair.svg for a found pair; returns the paths."""
    from topomark.proofs.drawing import save_pair

    d = Path(out)
    d.mkdir(parents=True, exist_ok=True)
    assert result.worlds is not None and result.motions is not None and result.perceptions is not None
    a, b = result.worlds
    save_world(a, d / "a.json")
    save_world(b, d / "b.json")
    (d / "relation.json").write_text(json.dumps(z3search.relation_to_json(result.relation)) + "\n", encoding="utf-8")
    caption = (f"{result.marker}: M = ({','.join(map(str, result.motions))}) gives "
               f"P = ({', '.join(map(str, result.perceptions))}) in both worlds")
    save_pair(a, b, d / "pair.svg", titles=("A", "B"), caption=caption)
    return [str(d / f) for f in ("a.json", "b.json", "relation.json", "pair.svg")]


def _text(result: z3search.SearchResult, report) -> str:
    checks = ", ".join(f"{c.n_a}+{c.n_b}:{c.verdict}" for c in result.checks)
    head = f"{result.marker}, N <= {result.max_vertices}, D <= {result.max_degree}" \
        + (" (planar only): " if result.planar else ": ")
    if result.outcome == "unknown":
        body = f"unknown ({result.reason or 'timeout'}) after {result.seconds:.1f} s [{checks}]"
    elif result.outcome == "none":
        body = f"no counterexample within the bounds ({result.seconds:.1f} s) [{checks}]"
    else:  # found: the pair and its certificate are there
        assert result.worlds is not None and result.relation is not None and result.motions is not None \
            and result.perceptions is not None
        a, b = result.worlds
        body = ("counterexample found (indistinguishable, not extended-isomorphic; re-checked)\n"
                + describe_world("A", a) + "\n" + describe_world("B", b) + "\n"
                + f"relation: {len(result.relation)} related state pairs\n"
                + f"M = ({','.join(map(str, result.motions))})\n"
                + f"P = ({', '.join(map(str, result.perceptions))}) in both worlds")
    if report is not None:
        body += f"\nproof: {report.outcome} ({report.solver}, {report.seconds:.1f} s)"
    return head + body


def search_command(args: argparse.Namespace) -> int:
    validate_args(args)
    report = None
    if args.prove:
        report = z3search.prove(args.marker, args.max_vertices, args.max_degree, args.timeout, args.planar)
        result = report.search
        data = report.to_json()
    else:
        result = z3search.search(args.marker, args.max_vertices, args.max_degree, args.timeout,
                                 planar=args.planar)
        data = result.to_json()
    if result.found and args.out is not None:
        data["files"] = guarded(args.out, lambda: write_outputs(result, args.out))
    if args.json:
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        print(_text(result, report))
    if args.prove:
        return 0 if report is not None and report.proved else 1
    return 0 if result.found else 1

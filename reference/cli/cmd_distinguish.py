"""``topomark distinguish`` and ``topomark census`` (thesis §3.2, §3.3, §3.7, §6.1).

Their options are :mod:`topomark.reference.cli.options.distinguish`'s; this module is imported when one runs.

* ``distinguish A B``: exit 0 with the shortest motion sequence whose
  perceptions differ (printed in thesis notation), exit 1 when A and B are
  indistinguishable (with the size of the bisimulation relation certifying it).
* ``census --marker CLASS --max-vertices N --max-degree D``: the language
  census of :mod:`topomark.proofs.census`, run as map and reduce over shards
  on disk (:mod:`topomark.proofs.census_run`; ``--jobs``, ``--shards DIR`` to
  keep and resume them, ``--scheduler`` for Dask, ``--engine`` for the
  compiled or the reference map: :mod:`topomark.proofs.census_compiled`); exit 0 when the class has no
  counterexample up to N, 1 when it has one (printed with the smallest pair).
"""

from __future__ import annotations

import argparse
import json
import tempfile
from typing import Any, cast

from topomark.proofs.bisim import bisimulation, check_relation, distinguishing_sequence
from topomark.proofs.census import CensusResult, stderr_progress
from topomark.proofs.census_compiled import resolve_engine
from topomark.proofs.census_run import sharded_census
from topomark.proofs.enumerate import MAX_VERTICES
from topomark.reference.cli.args import check_jobs, check_max_degree
from topomark.reference.files.overwrite import named_path
from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.markerclass import marker_class
from topomark.spec.worldfile import load_world, world_to_json

__all__ = ["distinguish_command", "census_command", "format_motions", "format_perceptions",
           "census_table"]


def format_motions(motions) -> str:
    return "M = (" + ",".join(map(str, motions)) + ")"


def format_perceptions(name: str, perceptions) -> str:
    return f"P_{name} = (" + ", ".join(map(str, perceptions)) + ")"


def _load_started(path: str):
    world = load_world(path)
    if world.start is None:
        raise InvalidInput(f"{path}: the world has no start (distinguish needs \"start\": {{\"at\", \"facing\"}})")
    return world


def distinguish_command(args: argparse.Namespace) -> int:
    a, b = _load_started(args.a), _load_started(args.b)
    found = distinguishing_sequence(a, b)
    if found is not None:
        data: dict[str, Any] = {"distinguishable": True, "motions": list(found.motions),
                                "perceptions_a": [str(s) for s in found.perceptions_a],
                                "perceptions_b": [str(s) for s in found.perceptions_b]}
        lead = ("the start signatures differ" if not found.motions
                else f"distinguishable in {len(found.motions)} motion(s)")
        text = "\n".join([f"{args.a} and {args.b}: {lead}", format_motions(found.motions),
                          format_perceptions("A", found.perceptions_a), format_perceptions("B", found.perceptions_b)])
        _emit(args, data, text)
        return 0
    relation = cast(frozenset[tuple[tuple[str, int], tuple[str, int]]], bisimulation(a, b))  # indistinguishable
    violation = check_relation(a, b, relation)
    if violation is not None:
        raise CheckFailure(violation)
    _emit(args, {"distinguishable": False, "relation_size": len(relation)},
          f"{args.a} and {args.b}: indistinguishable (every motion sequence gives the same perceptions); "
          f"certified by a bisimulation of {len(relation)} state pairs")
    return 1


def _emit(args: argparse.Namespace, data: dict[str, Any], text: str) -> None:
    print(json.dumps(data, indent=1, sort_keys=True) if args.json else text)


def _validate(args: argparse.Namespace) -> None:
    marker_class(args.marker)
    if args.max_vertices < 2:
        raise InvalidInput(f"--max-vertices must be at least 2, not {args.max_vertices}")
    if args.max_vertices > MAX_VERTICES:
        raise InvalidInput(f"--max-vertices {args.max_vertices} is too large: the census enumerates worlds "
                           f"of at most {MAX_VERTICES} vertices")
    check_max_degree(args.max_degree)
    from topomark.reference.worstcase.limits import exhaustive_refusal
    refusal = exhaustive_refusal(args.max_vertices, args.max_degree)  # the plan's memory: bounded before work
    if refusal:
        raise InvalidInput(refusal)
    check_jobs(args.jobs)
    resolve_engine(args.engine, args.marker)  # an unknown or unusable engine is exit 2 before work
    named_path(args.shards, "--shards")  # resumed, not claimed: a census's shards are reused on purpose


def census_table(result: CensusResult) -> str:
    """The census as a text table plus the smallest counterexample."""
    lines = [f"census of marker class {result.marker!r}, n <= {result.max_vertices}, max degree <= "
             f"{result.max_degree} ({result.seconds:.1f} s)",
             f"{'n':>3} {'worlds':>9} {'placements':>11} {'languages':>10} {'langs<=n':>10} {'ambiguous<=n':>13}"]
    for r in result.rows:
        lines.append(f"{r.n:>3} {r.worlds:>9} {r.placements:>11} {r.languages:>10} {r.languages_upto:>10} "
                     f"{r.ambiguous_upto:>13}")
    pair = result.smallest_counterexample
    if pair is None:
        lines.append("no two non-isomorphic marked worlds are indistinguishable")
    else:
        lines.append("smallest counterexample (indistinguishable, not isomorphic):")
        for name, w in zip("AB", pair):
            lines.append(f"  {name}: " + json.dumps(world_to_json(w), sort_keys=True))
    return "\n".join(lines)


def census_command(args: argparse.Namespace) -> int:
    _validate(args)
    progress = None if args.quiet else stderr_progress
    if args.shards is not None:
        result = sharded_census(args.marker, args.max_vertices, args.max_degree, args.shards, jobs=args.jobs,
                                scheduler=args.scheduler, progress=progress, engine=args.engine)
    else:
        with tempfile.TemporaryDirectory(prefix="topomark-census-") as root:
            result = sharded_census(args.marker, args.max_vertices, args.max_degree, root, jobs=args.jobs,
                                    scheduler=args.scheduler, progress=progress, engine=args.engine)
    pair = result.smallest_counterexample
    data = {"marker": result.marker, "max_vertices": result.max_vertices, "max_degree": result.max_degree,
            "rows": [r.to_json() for r in result.rows], "languages": result.languages,
            "ambiguous": result.ambiguous, "seconds": round(result.seconds, 3),
            "smallest_counterexample": None if pair is None else [world_to_json(w) for w in pair]}
    _emit(args, data, census_table(result))
    return 0 if pair is None else 1

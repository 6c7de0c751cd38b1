"""``topomark census-count``: how many embedded worlds the census will meet, per n (thesis §3.1.1, §3.1.3).

Its options are :mod:`topomark.reference.cli.options.count`'s; this module is imported when it runs.

``topomark census-count --max-vertices N --max-degree D`` prints, for each n
from 2 (or ``--min-vertices``) to N, the number of connected graphs with max
degree ≤ D (:mod:`topomark.proofs.graphs`) and of embedded worlds on them up
to extended isomorphism (mirror images distinct, no start, no markers), counted
by Burnside's lemma (:mod:`topomark.proofs.burnside`) without listing a world —
so it predicts the size of a census before the census runs.  ``--enumerate``
also lists the worlds (:mod:`topomark.proofs.enumerate`) and checks that both
counts agree (exit 3 if they do not: a bug in topomark).

Exit 0 on success, 2 on bad input (one message), 3 if the two counts differ.

Examples
--------
``topomark census-count --max-vertices 8 --max-degree 4`` ends with
``8  1929  7149942``.
"""

from __future__ import annotations

import argparse
import json

from topomark.proofs import burnside, enumerate as enumeration, graphs
from topomark.reference.cli.args import check_max_degree, check_min_vertices
from topomark.spec.errors import InvalidInput, TopomarkFault

__all__ = ["count_command", "validate_args"]


def validate_args(args: argparse.Namespace) -> None:
    """Precise messages for options argparse cannot check."""
    if args.max_vertices < 2:
        raise InvalidInput(f"--max-vertices must be at least 2 (a world has two or more vertices), "
                           f"not {args.max_vertices}")
    if args.max_vertices > graphs.MAX_VERTICES:
        raise InvalidInput(f"--max-vertices {args.max_vertices} is too large: graphs are generated for at most "
                           f"{graphs.MAX_VERTICES} vertices")
    if args.enumerate and args.max_vertices > enumeration.MAX_VERTICES:
        raise InvalidInput(f"--enumerate lists worlds of at most {enumeration.MAX_VERTICES} vertices, "
                           f"not {args.max_vertices}")
    check_min_vertices(args.min_vertices, args.max_vertices)
    check_max_degree(args.max_degree)


def count_command(args: argparse.Namespace) -> int:
    validate_args(args)
    degree = min(args.max_degree, args.max_vertices - 1)  # a larger bound changes nothing
    worlds = burnside.count_by_size(args.max_vertices, degree, args.min_vertices)
    rows = [{"n": n, "graphs": graphs.count(n, degree), "worlds": w} for n, w in worlds.items()]
    if args.enumerate:
        listed = enumeration.count_by_size(args.max_vertices, degree, args.min_vertices)
        if listed != worlds:
            raise TopomarkFault(f"Burnside's lemma counts {worlds} embedded worlds but the enumeration "
                                f"lists {listed}", check="Burnside count and enumeration agree")
        for row in rows:
            row["enumerated"] = listed[row["n"]]
    total = sum(row["worlds"] for row in rows)
    if args.json:
        print(json.dumps({"max_degree": args.max_degree, "rows": rows, "total_worlds": total,
                          "method": "burnside" + ("+enumeration" if args.enumerate else "")},
                         indent=1, sort_keys=True))
        return 0
    lines = [f"embedded worlds up to extended isomorphism (mirror images distinct), max degree <= {args.max_degree}"
             + (", checked by enumeration" if args.enumerate else ""),
             f"{'n':>3}  {'graphs':>8}  {'worlds':>12}"]
    lines += [f"{row['n']:>3}  {row['graphs']:>8}  {row['worlds']:>12}" for row in rows]
    lines.append(f"total {total} worlds")
    print("\n".join(lines))
    return 0

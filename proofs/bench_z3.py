"""Benchmark of the Z3 counterexample search and bounded proofs (thesis §3.2, §3.3, §3.7, §6.1, §6.2).

``python -m topomark.proofs.bench_z3 [--stretch] [--planar] [--cross-check] [--json]`` measures

* the time to the smallest counterexample of every insufficient class
  (none, undirected-vertex, two-undirected-vertex, undirected-edge) with up
  to 6 vertices and degree 4 (target: under 60 s for undirected-vertex);
* the bounded proof of every sufficient class (directional-vertex,
  three-undirected-vertex, directional-edge, vertex-and-edge) for N <= 5,
  D <= 4 (target: under 10 minutes), and with ``--stretch`` for N <= 6;
* with ``--planar``, the smallest *planar* counterexamples (both worlds of
  genus 0, as the thesis draws them) with up to 6 vertices and degree 3;
* with ``--cross-check``, the brute-force enumeration (all embedded worlds,
  every placement, grouped by the robot's language, pairs confirmed with
  :func:`topomark.proofs.bisim.is_counterexample`) for N <= 5, D <= 4,
  compared with Z3's found/none verdict and smallest size.

Measured 2026-11-23 with z3 5.4.1 on 2 cores shared with other jobs (load
average 8-10, so wall times are 3-4x the CPU times):

=========================  ==============  ===============================================
class                      bound           result (wall)
=========================  ==============  ===============================================
none                       N<=6, D<=4      found C3 / C4, 2.5 s
undirected-vertex          N<=6, D<=4      found 4+4: two embeddings of K4 (genus 1, 0), 5.2 s
two-undirected-vertex      N<=6, D<=4      found 5+5: two embeddings of K5, 15.7 s
undirected-edge            N<=6, D<=4      found 5+5: two embeddings of K5, 13.1 s
directional-vertex         N<=5 / N<=6     proved, 15 s / 168 s
three-undirected-vertex    N<=5 / N<=6     proved, 15 s / 161 s
directional-edge           N<=5 / N<=6     proved, 20 s / 152 s
vertex-and-edge            N<=5 / N<=6     proved, 19 s / 199 s
directional-vertex         N<=7, D<=4      proved, 350 s (135 s CPU)
directional-vertex         N<=8, D<=4      proved, 486 s (320 s CPU); D<=3: 78 s (52 s CPU)
three-undirected-vertex    N<=7 / N<=8     proved, 196 s (130 s CPU) / 551 s (325 s CPU)
directional-edge           N<=7 / N<=8     proved, 199 s (133 s CPU) / 551 s (368 s CPU)
vertex-and-edge            N<=7 / N<=8     proved, 221 s (146 s CPU) / 560 s (339 s CPU)
planar undirected-vertex   N<=6, D<=4      none (107 s); N<=7, D<=3: found 7+7 (52 s)
planar two-undirected      N<=6, D<=3      found 6+6 (theta graph vs. two bridged triangles)
planar undirected-edge     N<=6, D<=3      found 6+6 (the same two graphs)
=========================  ==============  ===============================================

The N >= 7 rows come from :func:`topomark.proofs.z3search.prove` directly (not
run by this script).  The brute-force cross-check agreed for all eight classes
at N <= 5, D <= 4.
"""

from __future__ import annotations

import argparse
import itertools
import json
import sys
import time
from typing import Any

import z3

from topomark.proofs import bisim, z3search
from topomark.proofs.enumerate import embedded_worlds
from topomark.spec.markerclass import MARKER_CLASSES
from topomark.spec.robot import sense, step

__all__ = ["INSUFFICIENT", "bench_smallest", "bench_proofs", "bench_cross_check", "brute_force_smallest",
           "language_key", "main"]

INSUFFICIENT = ("none", "undirected-vertex", "two-undirected-vertex", "undirected-edge")


def _row(kind: str, marker: str, n: int, d: int, res: z3search.SearchResult, outcome: str) -> dict[str, Any]:
    row = {"kind": kind, "marker": marker, "max_vertices": n, "max_degree": d, "outcome": outcome,
           "seconds": round(res.seconds, 2), "cpu_seconds": round(sum(c.cpu_seconds for c in res.checks), 2),
           "largest_pair_seconds": round(max(c.seconds for c in res.checks), 2) if res.checks else 0.0}
    if res.found:
        a, b = res.worlds
        row.update({"sizes": [a.n, b.n], "edges": [a.m, b.m], "genus": [a.genus(), b.genus()],
                    "relation": len(res.relation), "walk": len(res.motions)})
    return row


def bench_smallest(max_vertices: int = 6, max_degree: int = 4, timeout: float | None = None,
                   planar: bool = False) -> list[dict]:
    kind = "planar" if planar else "smallest"
    return [_row(kind, m, max_vertices, max_degree, r, r.outcome)
            for m in INSUFFICIENT for r in [z3search.search(m, max_vertices, max_degree, timeout, planar=planar)]]


def bench_proofs(max_vertices: int, max_degree: int = 4, timeout: float | None = None) -> list[dict]:
    rows = []
    for m in z3search.SUFFICIENT:
        rep = z3search.prove(m, max_vertices, max_degree, timeout)
        rows.append(_row("proof", m, max_vertices, max_degree, rep.search, rep.outcome))
    return rows


def language_key(world) -> tuple:
    """Canonical minimal Moore machine reachable from the start (equal iff bisimilar)."""
    states = [(v, j) for v in world.vertices for j in range(world.degree(v))]
    block = {s: str(sense(world, s)) for s in states}
    while True:
        key = {s: (block[s], tuple(block[step(world, s, l)] for l in range(world.degree(s[0])))) for s in states}
        ids = {k: i for i, k in enumerate(sorted(set(key.values()), key=repr))}
        new = {s: ids[key[s]] for s in states}
        if len(set(new.values())) == len(set(block.values())):
            break
        block = new
    first = world.start_state()
    rep, todo, code = {block[first]: 0}, [first], []
    while todo:
        s = todo.pop(0)
        succ = []
        for l in range(world.degree(s[0])):
            t = step(world, s, l)
            if block[t] not in rep:
                rep[block[t]] = len(rep)
                todo.append(t)
            succ.append(rep[block[t]])
        code.append((str(sense(world, s)), tuple(succ)))
    return tuple(code)


def brute_force_smallest(marker: str, max_vertices: int, max_degree: int) -> int | None:
    """Smallest n (size of the larger world) with a counterexample by enumeration, or None."""
    groups: dict[tuple, list] = {}
    for world in embedded_worlds(max_vertices, max_degree):
        for placed in MARKER_CLASSES[marker].placements(world):
            groups.setdefault(language_key(placed), []).append(placed)
    best = None
    for members in groups.values():
        for a, b in itertools.combinations(members, 2):
            size = max(a.n, b.n)
            if (best is None or size < best) and bisim.is_counterexample(a, b):
                best = size
    return best


def bench_cross_check(max_vertices: int = 5, max_degree: int = 4) -> list[dict]:
    rows = []
    for m in MARKER_CLASSES:
        t0 = time.monotonic()
        brute = brute_force_smallest(m, max_vertices, max_degree)
        t1 = time.monotonic()
        res = z3search.search(m, max_vertices, max_degree)
        z3_size = max(w.n for w in res.worlds) if res.found else None
        rows.append({"kind": "cross-check", "marker": m, "max_vertices": max_vertices, "max_degree": max_degree,
                     "brute_force": brute, "z3": z3_size, "z3_outcome": res.outcome,
                     "agree": res.outcome != "unknown" and brute == z3_size,
                     "brute_seconds": round(t1 - t0, 2), "seconds": round(res.seconds, 2)})
    return rows


def _print(row: dict) -> None:
    extra = {k: v for k, v in row.items() if k not in ("kind", "marker", "max_vertices", "max_degree")}
    print(f"{row['kind']:<12} {row['marker']:<24} N<={row['max_vertices']} D<={row['max_degree']}  "
          + "  ".join(f"{k}={v}" for k, v in extra.items()), flush=True)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m topomark.proofs.bench_z3", description=__doc__.splitlines()[0])
    ap.add_argument("--stretch", action="store_true", help="also prove the sufficient classes for N <= 6")
    ap.add_argument("--planar", action="store_true", help="smallest planar counterexamples, N <= 6, D <= 3")
    ap.add_argument("--cross-check", action="store_true", help="compare with brute force for N <= 5, D <= 4")
    ap.add_argument("--timeout", type=float, default=None, help="per search, seconds")
    ap.add_argument("--json", action="store_true", help="also print every row as one JSON list")
    args = ap.parse_args(argv)
    print(f"z3 {z3.get_version_string()}", flush=True)
    rows: list[dict] = []
    for row in bench_smallest(6, 4, args.timeout):
        rows.append(row), _print(row)
    if args.planar:
        for row in bench_smallest(6, 3, args.timeout, planar=True):
            rows.append(row), _print(row)
    for n in (5, 6) if args.stretch else (5,):
        for row in bench_proofs(n, 4, args.timeout):
            rows.append(row), _print(row)
    if args.cross_check:
        for row in bench_cross_check(5, 4):
            rows.append(row), _print(row)
    if args.json:
        print(json.dumps(rows, indent=1))
    return 0 if all(r.get("agree", True) for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())

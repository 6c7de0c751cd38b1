"""Measurements of the thread algorithms of §6.3 (Table 6.3, Figures 6.23 and 6.24) and the search that decides
whether a thread of length c(G) suffices for Algorithm 6.7 (guide §8.3, §10 item 26).

``python3 -m topomark.reference.bench_threads search [--worlds N]`` — Algorithm 6.7 given exactly
``--thread-length c(G)`` (computed here, by search, for small worlds) on N generated worlds with a cycle, at
random starts: how many run out of thread, and the smallest that does.

``python3 -m topomark.reference.bench_threads table [--sizes 4,6,8]`` — cost, cost/m and cost/(mn) of every
thread class on k×k lattices and lattice-hole worlds (10% of edges removed), as Figure 6.23.

``python3 -m topomark.reference.bench_threads lengths [--worlds 5] [--size 20]`` — Figure 6.24 in small:
Algorithm 6.8 on size×size lattices with 10% of edges removed, l = 1, 2, 4, ... up to the first l ≥ n.

Every run is checked (the outcome is the checker's); ``--json`` prints the rows as JSON.  Speed is
measured and printed, never asserted.

Examples
--------
>>> from topomark.reference import generators
>>> circumference(generators.cycle(5)), circumference(generators.chain(4)), circumference(generators.complete(4))
(5, 0, 4)
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import sys
import time

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World

from . import generators as g
from .explore import explore

__all__ = ["circumference", "longest_path_from", "search_circumference", "table", "lengths", "CIRCUMFERENCE_LIMIT"]

CIRCUMFERENCE_LIMIT = 40
"""The largest world (vertices) whose circumference is computed: the search is exponential."""

THREADS = ("thread-carried", "thread-circumference", "thread-knots", "thread-explore")


def _longest(world: World, start: str, closing: bool, within: set[str] | None = None) -> int:
    """The longest simple path from ``start`` (``closing``: the longest simple cycle through ``start``, on
    vertices of ``within``), by depth-first search over simple paths."""
    best, on = 0, {start}

    def dfs(v: str, length: int) -> None:
        nonlocal best
        for w in world.rotation[v]:
            if closing and w == start and length >= 2:
                best = max(best, length + 1)
            if w in on or (within is not None and w not in within):
                continue
            on.add(w)
            if not closing:
                best = max(best, length + 1)
            dfs(w, length + 1)
            on.discard(w)

    dfs(start, 0)
    return best


def circumference(world: World) -> int:
    """c(G): the number of edges of a longest simple cycle (0 for a forest; footnote 18, L2052)."""
    if world.n > CIRCUMFERENCE_LIMIT:
        raise InvalidInput(f"the circumference is computed by search for worlds of at most {CIRCUMFERENCE_LIMIT} "
                           f"vertices; this one has {world.n}")
    names = sorted(world.rotation)
    best = 0
    for k, v in enumerate(names):  # cycles whose least vertex is v
        best = max(best, _longest(world, v, True, set(names[k:])))
    return best


def longest_path_from(world: World, v: str) -> int:
    """The number of edges of a longest simple path starting at ``v``."""
    return _longest(world, v, False)


def _small_worlds(count: int, seed: int):
    """``count`` generated worlds with a cycle, at most 12 vertices, from the thesis's families, random starts."""
    rng, made = random.Random(seed), 0
    while made < count:
        s = rng.randrange(10**6)
        family = rng.choice(["lattice-hole", "random", "complete-hole", "small-world"])
        if family == "lattice-hole":
            w = g.lattice_hole(rng.randint(3, 4), rng.randint(3, 4), 0.2, rng.choice(["vertices", "edges"]), s)
        elif family == "random":
            w = g.random_graph(rng.randint(5, 9), rng.choice([0.4, 0.6]), s)
        elif family == "complete-hole":
            w = g.complete_hole(rng.randint(4, 6), 0.3, s)
        else:
            w = g.small_world(rng.randint(6, 12), 2, 0.2, s)
        if w.m < w.n:  # a tree: c(G) = 0, no thread to speak of
            continue
        v = rng.choice(sorted(w.rotation))
        made += 1
        yield World(w.rotation, (), Start(v, w.rotation[v][rng.randrange(len(w.rotation[v]))]))


def search_circumference(count: int = 200, seed: int = 0) -> dict:
    """Algorithm 6.7 with l = c(G) on ``count`` small worlds: how many run out, the smallest that does, and
    whether every world that ran out has a path from v0 longer than c(G) − 1 (c(G) < longest path + 1)."""
    ran_out, smallest, rows = 0, None, []
    for w in _small_worlds(count, seed):
        c = circumference(w)
        out = explore(w, "thread-circumference", options={"thread-length": c}, record=False)
        need = longest_path_from(w, w.start_state()[0]) + 1
        rows.append({"n": w.n, "m": w.m, "c": c, "longest_path_plus_1": need, "outcome": out.outcome})
        if out.outcome == "failed":
            ran_out += 1
            if smallest is None or (w.n, w.m) < (smallest["n"], smallest["m"]):
                smallest = {"n": w.n, "m": w.m, "c": c, "rotation": w.rotation, "start": w.start_state()[0],
                            "reason": out.reason}
        elif out.outcome != "correct":
            raise RuntimeError(f"thread-circumference on a world of {w.n} vertices: {out.outcome} {out.violation}")
    return {"worlds": count, "ran_out": ran_out, "smallest": smallest,
            "never_longer_than_path_bound": all(r["outcome"] == "correct" or r["c"] < r["longest_path_plus_1"]
                                                for r in rows)}


def _run(w: World, name: str, **kw) -> dict:
    t = time.perf_counter()
    out = explore(w, name, record=False, **kw)
    if out.outcome != "correct":
        raise RuntimeError(f"{name} on a world of {w.n} vertices: {out.outcome} {out.violation or out.reason}")
    return {"cost": out.cost, "cost/m": round(out.cost / w.m, 3), "cost/mn": round(out.cost / (w.m * w.n), 4),
            "bound": out.upper_bound, "seconds": round(time.perf_counter() - t, 2)}


def table(sizes=(4, 6, 8), worlds: int = 3, fixed: bool = True) -> list[dict]:
    """Figure 6.23: every thread class on k×k lattices and lattice-hole worlds (10% of edges removed)."""
    rows = []
    for k in sizes:
        kinds = [("lattice", g.lattice(k, k))] + [("lattice-hole", g.lattice_hole(k, k, 0.1, "edges", s))
                                                   for s in range(worlds)]
        for kind, w in kinds:
            runs = {name: _run(w, name) for name in THREADS}
            runs["thread-explore"]["l"] = 2
            if fixed:
                runs["fixed-thread (Algorithm 3.1)"] = _run(w, "basic", lighthouse="thread")
            for name, r in runs.items():
                rows.append({"world": kind, "size": k, "n": w.n, "m": w.m, "algorithm": name, **r})
    return rows


def lengths(worlds: int = 5, size: int = 20) -> list[dict]:
    """Figure 6.24 in small: Algorithm 6.8's cost against l on size×size lattices, 10% of edges removed."""
    ws = [g.lattice_hole(size, size, 0.1, "edges", s) for s in range(worlds)]
    ls, l = [], 1
    while True:
        ls.append(l)
        if l >= size * size:
            break
        l *= 2
    rows = []
    for l in ls:
        costs = [explore(w, "thread-explore", options={"thread-length": l}, record=False) for w in ws]
        if any(o.outcome != "correct" for o in costs):
            raise RuntimeError(f"thread-explore l={l}: {[o.outcome for o in costs]}")
        c = [o.cost for o in costs]
        rows.append({"l": l, "mean_cost": round(statistics.mean(c), 1), "sd": round(statistics.pstdev(c), 1),
                     "mean_cost/m": round(statistics.mean(o.cost / ws[k].m for k, o in enumerate(costs)), 2),
                     "costs": c})
    return rows


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="bench_threads", description=__doc__.split("\n\n")[0])
    p.add_argument("what", choices=("search", "table", "lengths"))
    p.add_argument("--worlds", type=int, default=None)
    p.add_argument("--size", type=int, default=20)
    p.add_argument("--sizes", default="4,6,8")
    p.add_argument("--no-fixed", action="store_true", help="leave out Algorithm 3.1 with the fixed thread")
    p.add_argument("--json", action="store_true")
    a = p.parse_args(argv)
    t = time.perf_counter()
    if a.what == "search":
        out = search_circumference(a.worlds or 200)
    elif a.what == "table":
        out = table(tuple(int(x) for x in a.sizes.split(",")), a.worlds or 3, not a.no_fixed)
    else:
        out = lengths(a.worlds or 5, a.size)
    if a.json:
        print(json.dumps(out, sort_keys=True))
    elif isinstance(out, list):
        for row in out:
            print("  ".join(f"{k}={v}" for k, v in row.items()))
    else:
        print(json.dumps(out, indent=1, sort_keys=True))
    print(f"# {time.perf_counter() - t:.0f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Whether a thread of length c(G) suffices for Algorithm 6.7 (§6.3.2 against footnote 18, §6.3.2): the search.

``python3 -m topomark.reference.bench.measure.thread_length [--worlds N] [--json]`` — Algorithm 6.7 given exactly
``--thread-length c(G)`` (computed here, by search, for small worlds) on N generated worlds with a cycle, at
random starts: how many run out of thread, and the smallest that does.

Every run is checked (the outcome is the checker's).  The measurements of Table 6.3 and Figures 6.23 and 6.24
are the bench's (``topomark bench table-6.3``, ``figure-6.24``, ``comparison``:
:mod:`~topomark.reference.bench.reports.section63`).

Examples
--------
>>> from topomark.reference.worlds import generators
>>> circumference(generators.cycle(5)), circumference(generators.chain(4)), circumference(generators.complete(4))
(5, 0, 4)
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import time

from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start, World

from topomark.reference.worlds import generators as g
from topomark.reference.run.explore import explore

__all__ = ["circumference", "longest_path_from", "search_circumference", "CIRCUMFERENCE_LIMIT"]

CIRCUMFERENCE_LIMIT = 40
"""The largest world (vertices) whose circumference is computed: the search is exponential."""



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
    """c(G): the number of edges of a longest simple cycle (0 for a forest; footnote 18, §6.3.2)."""
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
    """``count`` generated worlds with a cycle, at most 12 vertices, from the thesis's world families, random starts."""
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


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m topomark.reference.bench.measure.thread_length",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--worlds", type=int, default=200, help="worlds searched (default 200)")
    p.add_argument("--json", action="store_true", help="one JSON line instead of indented JSON")
    a = p.parse_args(argv)
    t = time.perf_counter()
    out = search_circumference(a.worlds)
    print(json.dumps(out, sort_keys=True) if a.json else json.dumps(out, indent=1, sort_keys=True))
    print(f"# {time.perf_counter() - t:.0f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())

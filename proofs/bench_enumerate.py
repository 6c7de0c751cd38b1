"""Every embedded world up to a size, timed, and counted twice (thesis §3.1.1, §3.1.3).

Lists the worlds of :func:`topomark.proofs.world_batches.embedded_batches`
(graphs from nauty's geng where installed, orbit-least rotation systems from
the compiled kernel where numba is installed) and compares the number per n
with :func:`topomark.proofs.burnside.count_by_size`, which counts the same
orbits without listing them, on graphs from our own generator.  Prints one
JSON object: per n the graphs, worlds, Burnside's count and seconds; the
generator and whether the kernel was compiled; the peak resident memory.
Speed is measured here and reported in docs/census.md, never asserted by a test.

Exit 0 when every count agrees, 3 when they do not (topomark's own two counts
disagree), 2 on bad input.

Example (the n = 8 figure of docs/census.md)::

    python -m topomark.proofs.bench_enumerate 8 4 --min-vertices 8
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import time

from topomark.proofs.burnside import count_by_size
from topomark.proofs.enumerate import MAX_VERTICES, check_bounds
from topomark.proofs.geng import source
from topomark.proofs.orbit_kernel import compiled
from topomark.proofs.world_batches import embedded_batches, graphs_of
from topomark.spec.errors import EXIT_BAD_INPUT, EXIT_FAULT, EXIT_OK, InvalidInput

__all__ = ["measure", "main"]


def measure(max_vertices: int, max_degree: int, min_vertices: int = 2) -> dict:
    """Enumerate, time and count per n; ``agree`` says whether every count is Burnside's."""
    check_bounds(max_vertices, max_degree)
    if not 2 <= min_vertices <= max_vertices:
        raise InvalidInput(f"min vertices must be between 2 and max vertices ({max_vertices}), not {min_vertices}")
    t0 = time.perf_counter()
    sizes = {}
    for n in range(min_vertices, max_vertices + 1):
        t = time.perf_counter()
        worlds = sum(len(b) for b in embedded_batches(n, max_degree, n))
        sizes[n] = {"graphs": len(graphs_of(n, max_degree)), "worlds": worlds,
                    "seconds": round(time.perf_counter() - t, 2)}
    seconds = round(time.perf_counter() - t0, 2)
    burnside = count_by_size(max_vertices, max_degree, min_vertices)
    for n, row in sizes.items():
        row["burnside"] = burnside[n]
    return {"max_vertices": max_vertices, "max_degree": max_degree, "graphs_from": source(),
            "compiled": compiled() is not None, "sizes": sizes, "seconds": seconds,
            "peak_rss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024),
            "agree": all(row["worlds"] == row["burnside"] for row in sizes.values())}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m topomark.proofs.bench_enumerate",
                                 description=(__doc__ or "").split("\n\n")[0])
    ap.add_argument("max_vertices", metavar="N", type=int, help=f"largest number of vertices (2..{MAX_VERTICES})")
    ap.add_argument("max_degree", metavar="D", type=int, help="largest degree (at least 1)")
    ap.add_argument("--min-vertices", type=int, default=2, help="smallest number of vertices (default 2)")
    args = ap.parse_args(argv)
    try:
        result = measure(args.max_vertices, args.max_degree, args.min_vertices)
    except InvalidInput as exc:
        print(f"topomark: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    print(json.dumps(result))
    if not result["agree"]:
        print("topomark: fault in topomark itself: the enumeration's world counts differ from Burnside's lemma's",
              file=sys.stderr)
        return EXIT_FAULT
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())

"""Connected graphs from nauty's ``geng`` where it is installed, our own generator otherwise (thesis §3.1.1).

The sufficiency questions of §3.2, §3.7 and §6.1 range over every connected
simple graph with n vertices and maximum degree ≤ D.  nauty's ``geng``
(B. D. McKay and A. Piperno, *Practical graph isomorphism II*, J. Symbolic
Computation 60, 2014) lists them far faster than
:mod:`topomark.proofs.graphs`; Debian's ``nauty`` package installs it as
``nauty-geng`` (upstream builds call it ``geng``).  topomark runs it as a
program (``geng -c -q -D{D} n``, graph6 on standard output, read with
networkx) and never links nauty, so no licence but MIT's reaches topomark.

:func:`graph_classes` is the one entry point: geng's graphs when geng is on
the ``PATH``, :func:`topomark.proofs.graphs.classes` (vertex augmentation)
otherwise, and the two give the *same tuple*:

* **Order and labelling.**  A witness ``(graph index, rank)`` names a world
  only if the graph's index and its vertex labels (on which the rank, a
  position in the product order of rotation systems, depends) do not depend
  on which generator ran.  Decision: each of geng's graphs is relabelled by
  our canonical form (:func:`topomark.proofs.graphs.canonical`, which also
  yields its automorphism group) and the classes are sorted by
  :func:`topomark.proofs.graphs.ordered` — the order and labelling
  :func:`~topomark.proofs.graphs.classes` already uses.  geng's own order
  (its canonical augmentation) is not used.
* **Automorphisms.**  The canonical search that relabels a graph finds its
  whole automorphism group on the way, so nauty is not asked for it
  (``dreadnaut`` per graph would add a process per graph and, through
  pynauty, a GPL dependency).  The relabelling costs well under 1 ms per graph
  at n = 8, 9.
* **n ≤ 7.**  :func:`topomark.proofs.enumerate.connected_graphs` keeps
  networkx's atlas there (its order fixes the census's pinned figures); geng
  is checked against the atlas there, not used in its place.
* **Checks.**  Every graph geng gives must have n vertices, be connected,
  have degrees ≤ D and be of a class not seen before; otherwise topomark
  stops with :class:`~topomark.spec.errors.TopomarkFault` (exit 3) rather
  than enumerate a wrong list.  tests/test_geng.py compares the two
  generators class by class (by canonical certificate) for n ≤ 8.

Examples
--------
>>> [len(graph_classes(n, 3)) for n in range(1, 9)]
[1, 1, 2, 6, 10, 29, 64, 194]
>>> graph_classes(7, 4) == classes(7, 4)
True
"""

from __future__ import annotations

import shutil
import subprocess
from functools import lru_cache

import networkx as nx

from topomark.proofs.graphs import GraphClass, canonical, classes, ordered
from topomark.spec.errors import InvalidInput, TopomarkFault

__all__ = ["GENG_NAMES", "geng_program", "graph6_lines", "from_geng", "graph_classes", "source"]

GENG_NAMES = ("geng", "nauty-geng")
"""The names geng is installed under: upstream's, then Debian's."""


def geng_program() -> str | None:
    """The path of nauty's geng on the ``PATH``, or None when it is not installed."""
    for name in GENG_NAMES:
        found = shutil.which(name)
        if found is not None:
            return found
    return None


def _exists(n: int, max_degree: int) -> bool:
    """Whether a connected graph with n vertices and degrees ≤ D exists (geng refuses the other cases)."""
    return n == 1 or (n == 2 and max_degree >= 1) or max_degree >= 2


def graph6_lines(program: str, n: int, max_degree: int) -> list[bytes]:
    """geng's connected graphs on ``n`` vertices with degrees ≤ ``max_degree``, one graph6 line each."""
    if not _exists(n, max_degree):
        return []
    try:
        run = subprocess.run([program, "-c", "-q", f"-D{max_degree}", str(n)], capture_output=True, check=False)
    except OSError as exc:
        raise TopomarkFault(f"nauty's geng ({program}) could not run: {exc}") from None
    if run.returncode != 0:
        raise TopomarkFault(f"nauty's geng ({program}) failed with exit code {run.returncode}: "
                            f"{run.stderr.decode(errors='replace').strip()[:200]}")
    return run.stdout.split()


def _adjacency(line: bytes, n: int, max_degree: int) -> tuple[int, ...]:
    """One graph6 line as bit masks, checked to be a connected graph on n vertices with degrees ≤ D."""
    try:
        g = nx.from_graph6_bytes(line)
    except (nx.NetworkXError, ValueError) as exc:
        raise TopomarkFault(f"nauty's geng wrote {line[:40]!r}, which is not graph6: {exc}") from None
    if g.number_of_nodes() != n or not nx.is_connected(g) or max((d for _, d in g.degree()), default=0) > max_degree:
        raise TopomarkFault(f"nauty's geng wrote {line.decode(errors='replace')[:40]}, which is not a connected "
                            f"graph on {n} vertices with degrees <= {max_degree}")
    return tuple(sum(1 << w for w in g[v]) for v in range(n))


def from_geng(program: str, n: int, max_degree: int) -> tuple[GraphClass, ...]:
    """geng's graphs as :class:`~topomark.proofs.graphs.GraphClass` es, in :func:`~topomark.proofs.graphs.classes`'s
    order and canonical labelling, each checked (connected, n vertices, degrees ≤ D, no class twice)."""
    found: dict[tuple[int, ...], GraphClass] = {}
    for line in graph6_lines(program, n, max_degree):
        c = canonical(_adjacency(line, n, max_degree))
        if c.adjacency in found:
            raise TopomarkFault(f"nauty's geng listed one isomorphism class twice ({line.decode(errors='replace')})")
        found[c.adjacency] = c
    return ordered(found.values())


@lru_cache(maxsize=None)
def graph_classes(n: int, max_degree: int) -> tuple[GraphClass, ...]:
    """The connected graphs on ``n`` vertices with degrees ≤ ``max_degree``: geng's if installed, else ours.

    The same tuple either way (order, canonical labelling, automorphisms).
    """
    if n < 1 or max_degree < 0:
        raise InvalidInput(f"graphs need at least 1 vertex and max degree at least 0, not n = {n}, D = {max_degree}")
    program = geng_program()
    return classes(n, max_degree) if program is None else from_geng(program, n, max_degree)


def source() -> str:
    """Which generator :func:`graph_classes` uses here: ``"geng"`` (with its path) or ``"augmentation"``."""
    program = geng_program()
    return "augmentation" if program is None else f"geng ({program})"

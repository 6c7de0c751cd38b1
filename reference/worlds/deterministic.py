"""The deterministic world families: cycles (§3.2.1), chains, lattices and complete graphs (§3.5.3), and the
wheel whose hub a closest-first explorer finds last.

Each generator checks its parameters (:func:`integer_param` and friends, shared
with :mod:`~topomark.reference.worlds.holes` and
:mod:`~topomark.reference.worlds.random_worlds`), computes n and m and refuses a
world above the size limits before building anything
(:func:`~topomark.spec.world.check_size`), then embeds the graph with
:func:`~topomark.reference.worlds.embedding.from_positions`.  Impossible parameters
raise :class:`~topomark.spec.errors.InvalidInput` naming the parameter.

>>> lattice(3, 4).n, lattice(3, 4).m
(12, 17)
>>> lattice(2, 2).rotation["0,0"]
('0,1', '1,0')
"""

from __future__ import annotations

import math
from numbers import Integral, Real
from typing import Any

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World, check_size

from topomark.reference.worlds.embedding import from_positions, on_circle

__all__ = ["cycle", "chain", "lattice", "complete", "wheel_hub_last", "integer_param", "real_param", "fraction_param", "seed_param",
           "lattice_graph", "lattice_size"]


# -- parameter checks -------------------------------------------------------------
def integer_param(name: str, value: Any, minimum: int) -> int:
    """``value`` as an int of at most 18 digits (like every JSON and CLI integer) and ``>= minimum``."""
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise InvalidInput(f"{name} must be an integer, got {value!r}")
    if abs(int(value)) >= 10**18:  # checked first: a 5,000-digit int cannot even be printed in the message
        raise InvalidInput(f"{name} is out of range (at most 18 digits)")
    if value < minimum:
        raise InvalidInput(f"{name} must be >= {minimum}, got {value}")
    return int(value)


def real_param(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value):
        raise InvalidInput(f"{name} must be a finite number, got {value!r}")
    return float(value)


def fraction_param(value: Any, name: str = "fraction") -> float:
    f = real_param(name, value)
    if not 0.0 <= f < 1.0:
        raise InvalidInput(f"{name} must be in [0, 1), got {value!r}")
    return f


def seed_param(value: Any) -> int:
    return integer_param("seed", value, -(2**63))


# -- cycles and chains ---------------------------------------------------------------
def cycle(n: int) -> World:
    """The cycle C_n (n >= 3), the indistinguishable worlds of Figure 3.3 (§3.2.1).

    Vertex ``k`` is joined to ``k±1 (mod n)``; drawn on a circle.
    """
    n = integer_param("n", n, 3)
    check_size(n, n, f"cycle:n={n}")
    return on_circle(n, ((k, (k + 1) % n) for k in range(n)))


def chain(n: int) -> World:
    """The path ("chain") of n >= 2 vertices ``0 - 1 - ... - n-1``, drawn on a horizontal line."""
    n = integer_param("n", n, 2)
    check_size(n, n - 1, f"chain:n={n}")
    return from_positions([(k, k + 1) for k in range(n - 1)], {k: (float(k), 0.0) for k in range(n)})


# -- lattices ---------------------------------------------------------------------------
def lattice_graph(rows: int, cols: int) -> tuple[nx.Graph, dict]:
    graph = nx.grid_2d_graph(rows, cols)
    return graph, {(r, c): (float(c), float(-r)) for r, c in graph.nodes}


def lattice_size(rows: Any, cols: Any) -> tuple[int, int]:
    rows = integer_param("rows", rows, 1)
    cols = integer_param("cols", cols, 1)
    if rows * cols < 2:
        raise InvalidInput(f"a {rows}x{cols} lattice has a single vertex of degree 0; it needs at least 2 cells")
    check_size(rows * cols, rows * (cols - 1) + cols * (rows - 1), f"the {rows}x{cols} lattice")
    return rows, cols


def lattice(rows: int, cols: int) -> World:
    """The rows x cols lattice (grid) graph of §3.5.3 (Figure 3.10(a)).

    Cell ``"r,c"`` is drawn at x = c, y = -r (row 0 at the top), so the
    clockwise order at a cell is north, east, south, west (those present).
    n = rows*cols and m = rows*(cols-1) + cols*(rows-1); the embedding is planar.
    """
    rows, cols = lattice_size(rows, cols)
    graph, pos = lattice_graph(rows, cols)
    return from_positions(graph, pos)


# -- complete graphs ----------------------------------------------------------------------
def complete(n: int) -> World:
    """The complete graph K_n (n >= 2), a densely connected world of §3.5.3 (Figure 3.10(b)).

    Embedding rule: vertex ``k`` sits on the unit circle at angle 2πk/n
    (:func:`~topomark.reference.worlds.embedding.circle_positions`) and each vertex lists its
    neighbours clockwise by the angle at which it sees them
    (:func:`~topomark.reference.worlds.embedding.from_positions`).  At vertex k the
    neighbours are thus ordered by position around the circle.  The embedding
    is planar for n <= 3 only.
    """
    n = integer_param("n", n, 2)
    check_size(n, n * (n - 1) // 2, f"K_{n}")
    return on_circle(n, ((i, j) for i in range(n) for j in range(i + 1, n)))


# -- wheels ---------------------------------------------------------------------------------
def wheel_hub_last(n: int) -> World:
    """The wheel of n >= 4 vertices — a hub joined to every vertex of a rim cycle — embedded so that a robot
    at the first vertex, facing exit 0, exploring closest-first finds the hub *last*.

    Rim vertices are ``"0"`` … ``str(n - 2)``, the hub ``str(n - 1)``; m = 2(n − 1), the hub has degree
    n − 1 = d_max.  Rim vertex i lists (i + 1, hub, i − 1) clockwise, so exit 0 leads on along the rim and,
    entered from i − 1, the next rim vertex comes before the spoke: the ``nearest`` edge policy (§3.3) walks
    the whole rim before its first spoke, and the hub is the n-th new place.  That is where §6.2's Σ_{k=1}^{n−1} k
    algorithms run out of markers and leave the place blank (Algorithm 6.2 lines 14–16, §6.2.1 Case 3a): a blank of
    degree d_max, the worst place for the blank.  The hub lists the rim in ascending order: the embedding is
    planar.

    >>> w = wheel_hub_last(5)
    >>> w.n, w.m, w.rotation["0"], w.rotation["4"], w.genus()
    (5, 8, ('1', '4', '3'), ('0', '1', '2', '3'), 0)
    """
    n = integer_param("n", n, 4)
    check_size(n, 2 * (n - 1), f"wheel-hub-last:n={n}")
    k = n - 1  # rim vertices
    hub = str(k)
    rotation: dict[str, tuple[str, ...]] = {str(i): (str((i + 1) % k), hub, str((i - 1) % k)) for i in range(k)}
    rotation[hub] = tuple(str(i) for i in range(k))
    return World(rotation, (), None)

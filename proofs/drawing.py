"""Draw worlds and world pairs like the thesis figures, as hand-written SVG (Figures 3.3, 3.4, 3.21, 6.1).

The thesis draws each world as a plane graph with exit indices at the edge
ends (Figure 3.1), a marked vertex as a filled disc, a directional vertex
marker as an arrow towards the exit it points at (Figure 3.2(c)), an edge
marker as a bar across the edge (Figure 6.1(a)) with an arrowhead towards its
head (Figure 6.1(b)), and the robot's start at ``v_0`` facing an edge.

Layout: when the rotation system is planar (genus 0, §3.1.1) the vertices
are placed with networkx's straight-line drawing of *that* embedding and
mirrored if needed so that exits run clockwise on screen, as in the thesis;
otherwise (the embedding lives on a torus or higher surface) a spring layout
is used and only the exit labels carry the rotation.  No plotting library is
needed for SVG, written by hand; a PNG is the same drawing rendered by matplotlib
(:mod:`~topomark.proofs.drawing_png`).  Each vertex's disc fits its name, exit
indices sit just outside it beside their edges (clockwise on screen when the
layout is faithful), and the start's arrow runs beside the edge it faces with its
label "start" past its tip, clear of the vertex's name.

>>> from topomark.spec.world import World, Start
>>> w = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, start=Start("a", "b"))
>>> world_svg(w).startswith("<svg")
True
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path
from typing import Sequence
from xml.sax.saxutils import escape

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.marker import EdgeMarker
from topomark.spec.world import World

from topomark.proofs.drawing_png import save_drawing

__all__ = ["layout", "positions", "world_svg", "pair_svg", "save_pair", "save_world", "drawing_size", "clockwise_ok",
           "MAX_DRAW_VERTICES", "check_draw_size"]

MAX_DRAW_VERTICES = 1000
"""The most vertices a world may have to be drawn.  Laying out and checking a drawing grows faster than
linearly with its size: a 32x32 lattice (1,024 vertices) takes about 8 s and 70 MB, a 45x45 one 25 s, and a
100x100 one over 2 minutes and 1.5 GB; and a drawing of more than a thousand vertices is no longer legible."""

SIZE = 320          # drawing area of one world (px)
MARGIN = 40
RADIUS = 11         # vertex radius


def _graph(world: World) -> nx.Graph:
    g: nx.Graph[str] = nx.Graph()
    g.add_nodes_from(world.vertices)
    g.add_edges_from(world.edges())
    return g


def _faces(world: World) -> list[list[str]]:
    """Faces of the embedding as vertex cycles (trace: from dart (v, i) go to (w, j + 1))."""
    seen, faces = set(), []
    for dart in world.darts():
        face, d = [], dart
        while d not in seen:
            seen.add(d)
            face.append(d[0])
            w, j = world.target(d)
            d = (w, (j + 1) % world.degree(w))
        if face:
            faces.append(face)
    return faces


def _named_grid(world: World) -> dict[str, tuple[float, float]] | None:
    """Vertices named "row,col" (the lattice generators' names) at their row and column, if every name is one."""
    pos = {}
    for v in world.vertices:
        parts = str(v).split(",")
        if len(parts) != 2 or not all(p.strip().lstrip("-").isdigit() for p in parts):
            return None
        pos[v] = (float(parts[1]), float(parts[0]))
    return pos


def _tutte_positions(world: World, outer: list[str]) -> dict[str, tuple[float, float]] | None:
    """Tutte's barycentric drawing with the face ``outer`` as a convex outer polygon (planar worlds only)."""
    import numpy as np

    if len(set(outer)) != len(outer) or len(outer) < 3:
        return None
    pos = {v: (math.cos(2 * math.pi * k / len(outer)), math.sin(2 * math.pi * k / len(outer)))
           for k, v in enumerate(outer)}
    inner = [v for v in world.vertices if v not in pos]
    if inner:
        idx = {v: k for k, v in enumerate(inner)}
        m = np.zeros((len(inner), len(inner)))
        rhs = np.zeros((len(inner), 2))
        for v in inner:
            m[idx[v], idx[v]] = world.degree(v)
            for w in world.rotation[v]:
                if w in idx:
                    m[idx[v], idx[w]] -= 1
                else:
                    rhs[idx[v]] += pos[w]
        try:
            sol = np.linalg.solve(m, rhs)
        except np.linalg.LinAlgError:
            return None
        pos.update({v: (float(sol[idx[v], 0]), float(sol[idx[v], 1])) for v in inner})
    return pos


def _crossing_free(world: World, pos) -> bool:
    """No two vertices nearly coincide and no two non-adjacent edges cross."""
    pts = list(pos.values())
    if any(math.dist(p, q) < 1e-3 for p, q in zip(pts, pts[1:])) or \
            len({(round(x, 4), round(y, 4)) for x, y in pts}) < len(pts):
        return False

    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    edges = list(world.edges())
    for (a, b), (c, d) in ((e, f) for k, e in enumerate(edges) for f in edges[k + 1:]):
        if {a, b} & {c, d}:
            continue
        p, q, r, t = pos[a], pos[b], pos[c], pos[d]
        if orient(p, q, r) * orient(p, q, t) < 0 and orient(r, t, p) * orient(r, t, q) < 0:
            return False
    return True


def _planar_candidates(world: World) -> list[dict[str, tuple[float, float]]]:
    """Straight-line drawings of a planar rotation system: the lattice's own grid (vertices named "row,col"),
    Tutte's with the longest face that gives a clean one as the outer face, then networkx's grid one."""
    if world.genus() != 0 or world.n < 3:
        return []
    named = _named_grid(world)
    out = [named] if named is not None and _crossing_free(world, named) else []
    for face in sorted(_faces(world), key=len, reverse=True)[:8]:  # the longest simple face that draws cleanly
        tutte = _tutte_positions(world, face)
        if tutte is not None and _crossing_free(world, tutte):
            out.append(tutte)
            break
    grid = _grid_positions(world)
    return out + ([grid] if grid is not None else [])


def _grid_positions(world: World) -> dict[str, tuple[float, float]] | None:
    emb: nx.PlanarEmbedding[str] = nx.PlanarEmbedding()
    emb.set_data({v: list(ns) for v, ns in world.rotation.items()})
    try:
        emb.check_structure()
        pos = nx.combinatorial_embedding_to_pos(emb)
    except (nx.NetworkXException, KeyError):
        return None
    return {v: (float(x), float(y)) for v, (x, y) in pos.items()}


def clockwise_ok(world: World, pos: dict[str, tuple[float, float]]) -> bool:
    """True if, in screen coordinates (y down), every vertex's exits appear clockwise in index order."""
    for v, ns in world.rotation.items():
        if len(ns) < 3:
            continue
        x0, y0 = pos[v]
        angles = [math.atan2(pos[w][1] - y0, pos[w][0] - x0) for w in ns]
        order = sorted(range(len(ns)), key=lambda i: angles[i])
        if any(abs(angles[order[k + 1]] - angles[order[k]]) < 1e-6 for k in range(len(ns) - 1)):
            return False  # two exits drawn on top of each other
        k = order.index(0)
        if order[k:] + order[:k] != list(range(len(ns))):
            return False
    return True


def _fit(pos: dict, size: float) -> dict[str, tuple[float, float]]:
    xs = [p[0] for p in pos.values()]
    ys = [p[1] for p in pos.values()]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    scale = (size - 2 * MARGIN) / span
    return {v: (MARGIN + (x - min(xs)) * scale, MARGIN + (y - min(ys)) * scale) for v, (x, y) in pos.items()}


def layout(world: World, size: float = SIZE) -> tuple[dict[str, tuple[float, float]], bool]:
    """Vertex positions in a ``size`` square and whether they show the rotation system faithfully."""
    for pos in _planar_candidates(world):
        for flip in (False, True):
            cand = _fit({v: (x, -y if flip else y) for v, (x, y) in pos.items()}, size)
            if clockwise_ok(world, cand):
                return cand, True
    if world.n == 2:
        a, b = world.vertices
        return {a: (MARGIN, size / 2), b: (size - MARGIN, size / 2)}, True
    try:
        raw = nx.spring_layout(_graph(world), seed=7)
    except ModuleNotFoundError as exc:  # networkx lays out 500 vertices or more with scipy, an optional library
        raise InvalidInput(f"world --draw: a world of {world.n:,} vertices that is not planar is laid out with "
                           f"networkx's sparse spring layout, which needs {exc.name} (not installed)") from exc
    cand = _fit({v: (float(x), float(y)) for v, (x, y) in raw.items()}, size)
    return cand, clockwise_ok(world, cand)


def _radius(v: str) -> float:
    """The disc of vertex ``v``: wide enough for its name at font size 9 ("10,12" of a lattice)."""
    return max(RADIUS, 2.7 * len(str(v)) + 4)


def _along(p, q, t: float, side: float = 0.0):
    """The point a fraction t from p to q, shifted ``side`` px to the right of the direction."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    length = math.hypot(dx, dy) or 1.0
    nx_, ny_ = -dy / length, dx / length
    return (p[0] + dx * t + nx_ * side, p[1] + dy * t + ny_ * side)


def _arrow(p, q, colour: str, width: float = 2.5) -> list[str]:
    """A line p -> q with an arrowhead at q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    length = math.hypot(dx, dy) or 1.0
    ux, uy = dx / length, dy / length
    left = (q[0] - 8 * ux + 4 * uy, q[1] - 8 * uy - 4 * ux)
    right = (q[0] - 8 * ux - 4 * uy, q[1] - 8 * uy + 4 * ux)
    return [f'<line x1="{p[0]:.1f}" y1="{p[1]:.1f}" x2="{q[0]:.1f}" y2="{q[1]:.1f}" stroke="{colour}" '
            f'stroke-width="{width}"/>',
            f'<polygon points="{q[0]:.1f},{q[1]:.1f} {left[0]:.1f},{left[1]:.1f} {right[0]:.1f},{right[1]:.1f}" '
            f'fill="{colour}"/>']


def _edges(world: World, pos) -> list[str]:
    out = []
    for u, v in world.edges():
        (x1, y1), (x2, y2) = pos[u], pos[v]
        out.append(f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" stroke="#444" stroke-width="1.5"/>')
    return out


def _exit_labels(world: World, pos) -> list[str]:
    out = []
    for v, ns in world.rotation.items():
        for i, w in enumerate(ns):
            x, y = _along(pos[v], pos[w], 0.0, 0.0)
            dist = math.dist(pos[v], pos[w]) or 1.0
            lx, ly = _along(pos[v], pos[w], min(0.45, (_radius(v) + 9) / dist), 7.0)
            out.append(f'<text x="{lx:.1f}" y="{ly + 3:.1f}" font-size="10" fill="#1f4e9e" '
                       f'text-anchor="middle">{i}</text>')
    return out


def _edge_markers(world: World, pos) -> list[str]:
    out = []
    for m in world.markers:
        if not isinstance(m, EdgeMarker):  # the world's markers are vertex or edge markers
            continue
        u, v = m.between
        p, q = pos[u], pos[v]
        a, b = _along(p, q, 0.5, -7.0), _along(p, q, 0.5, 7.0)
        out.append(f'<line x1="{a[0]:.1f}" y1="{a[1]:.1f}" x2="{b[0]:.1f}" y2="{b[1]:.1f}" stroke="#c0392b" '
                   f'stroke-width="4"/>')
        if m.count > 1:
            c = _along(p, q, 0.5, 14.0)
            out.append(f'<text x="{c[0]:.1f}" y="{c[1]:.1f}" font-size="10" fill="#c0392b">x{m.count}</text>')
        if m.head is not None:
            tail, head = (u, v) if m.head == v else (v, u)
            out += _arrow(_along(pos[tail], pos[head], 0.5), _along(pos[tail], pos[head], 0.68), "#c0392b")
    return out


def _vertices(world: World, pos) -> list[str]:
    out = []
    for v in world.vertices:
        x, y = pos[v]
        r = _radius(v)
        mark = world.vertex_mark(v)
        fill = "#fff" if mark is None else "#222"
        out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{r:.1f}" fill="{fill}" stroke="#222" stroke-width="1.5"/>')
        if mark is not None and mark.count > 1:
            out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{r + 4:.1f}" fill="none" stroke="#222" '
                       f'stroke-width="1.5"/>')
            out.append(f'<text x="{x + r + 6:.1f}" y="{y + r + 10:.1f}" font-size="10">x{mark.count}</text>')
        if mark is not None and mark.head is not None:
            w = world.neighbour(v, mark.head)
            out += _arrow(pos[v], _along(pos[v], pos[w], min(0.4, 34 / (math.dist(pos[v], pos[w]) or 1))), "#e67e22")
        colour = "#fff" if mark is not None else "#222"
        out.append(f'<text x="{x:.1f}" y="{y + 3.5:.1f}" font-size="9" fill="{colour}" '
                   f'text-anchor="middle">{escape(v)}</text>')
    return out


def _start(world: World, pos) -> list[str]:
    if world.start is None:
        return []
    v, w = world.start.at, world.start.facing
    p = pos[v]
    dist = math.dist(p, pos[w]) or 1.0
    r = _radius(v)
    a = _along(p, pos[w], (r + 2) / dist, -10.0)
    b = _along(p, pos[w], min(0.45, (r + 26) / dist), -10.0)
    # The label sits past the arrow's tip, further off the edge than the arrow: never over v0's name or disc.
    c = _along(p, pos[w], min(0.5, (r + 40) / dist), -17.0)
    return _arrow(a, b, "#27ae60", 2.0) + [
        f'<text x="{c[0]:.1f}" y="{c[1] + 3:.1f}" font-size="9" fill="#27ae60" text-anchor="middle">start</text>']


def positions(world: World, size: float = SIZE, dx: float = 0.0) -> tuple[dict[str, tuple[float, float]], bool]:
    """Where :func:`world_svg` (and :func:`pair_svg` at ``dx``) puts each vertex: :func:`layout`'s positions below
    the title line; and whether they show the rotation faithfully.  A drawing laid over a world's own (the run
    viewer's robot and markers) takes its coordinates from here."""
    pos, faithful = layout(world, size)
    return {v: (x + dx, y + 18) for v, (x, y) in pos.items()}, faithful


def _world_group(world: World, title: str, dx: float, size: float, note: str = "",
                 crop: bool = False) -> tuple[list[str], float]:
    """The drawing of one world at ``dx``, and the height it takes (``crop``: only as tall as the layout, not
    ``size``); ``note`` follows the n, m, genus line under it."""
    pos, faithful = positions(world, size, dx)
    bottom = (max(y for _, y in pos.values()) + MARGIN - 6) if crop else size + 30
    note = ("" if faithful else " (non-planar embedding: exit labels give the rotation)") + \
        (f"; {note}" if note else "")
    caption = textwrap.wrap(f"n={world.n}, m={world.m}, genus {world.genus()}{note}", int((size - 16) / 5))
    parts = [f'<text x="{dx + 8:.1f}" y="16" font-size="12" font-weight="bold">{escape(title)}</text>']
    parts += [f'<text x="{dx + 8:.1f}" y="{bottom + 12 * k:.1f}" font-size="9" fill="#666">{escape(line)}</text>'
              for k, line in enumerate(caption)]
    bottom += 12 * (len(caption) - 1)
    return parts + _edges(world, pos) + _edge_markers(world, pos) + _exit_labels(world, pos) + \
        _vertices(world, pos) + _start(world, pos), bottom + 10


def _svg(body: list[str], width: float, height: float) -> str:
    head = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height:.0f}" '
            f'viewBox="0 0 {width:.0f} {height:.0f}" font-family="sans-serif">')
    return "\n".join([head, f'<rect width="100%" height="100%" fill="white"/>'] + body + ["</svg>"]) + "\n"


def world_svg(world: World, title: str = "", size: float = SIZE, note: str = "") -> str:
    """One world as an SVG document, as tall as its layout; ``note`` follows the n, m, genus line."""
    body, height = _world_group(world, title, 0.0, size, note, crop=True)
    return _svg(body, size, height)


def pair_svg(a: World, b: World, titles: Sequence[str] = ("(a)", "(b)"), caption: str = "",
             size: float = SIZE) -> str:
    """Two worlds side by side with an optional caption (e.g. the shared M and P), as in Figure 3.4."""
    (left, ha), (right, hb) = _world_group(a, titles[0], 0.0, size), _world_group(b, titles[1], size + 20, size)
    body, height = left + right, max(ha, hb) + 10
    lines = [caption[i:i + 110] for i in range(0, len(caption), 110)]
    for k, line in enumerate(lines):
        body.append(f'<text x="8" y="{height + 14 * k + 4:.1f}" font-size="10">{escape(line)}</text>')
    return _svg(body, 2 * size + 20, height + 14 * len(lines) + 8)


def save_pair(a: World, b: World, path: str | Path, **kwargs) -> Path:
    """Write :func:`pair_svg` to ``path``: ``.svg``, or ``.png`` with matplotlib
    (:func:`~topomark.proofs.drawing_png.save_drawing`)."""
    return save_drawing(pair_svg(a, b, **kwargs), path)


def drawing_size(world: World) -> float:
    """The side of a drawing of one world: :data:`SIZE`, larger for a larger world so its discs do not touch."""
    return max(SIZE, 64 * math.sqrt(world.n))


def save_world(world: World, path: str | Path, title: str = "", note: str = "") -> Path:
    """Write :func:`world_svg` of ``world`` (sized by :func:`drawing_size`) to ``path``, ``.svg`` or ``.png``;
    a world above :data:`MAX_DRAW_VERTICES` vertices is refused (:func:`check_draw_size`)."""
    check_draw_size(world)
    return save_drawing(world_svg(world, title, drawing_size(world), note), path)


def check_draw_size(world: World) -> None:
    """Raise InvalidInput if ``world`` has more than :data:`MAX_DRAW_VERTICES` vertices to draw.

    >>> from topomark.reference.worlds.generators import cycle
    >>> check_draw_size(cycle(MAX_DRAW_VERTICES + 1))
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: world --draw: the world has 1,001 vertices; at most 1,000 are drawn
    """
    if world.n > MAX_DRAW_VERTICES:
        raise InvalidInput(f"world --draw: the world has {world.n:,} vertices; at most {MAX_DRAW_VERTICES:,} "
                           "are drawn")

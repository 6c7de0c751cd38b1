"""Write a drawing of :mod:`~topomark.proofs.drawing` as SVG, or as PNG through matplotlib, by the file's suffix.

:mod:`~topomark.proofs.drawing` writes its worlds as hand-written SVG made of five elements only (``rect``,
``line``, ``polygon``, ``circle``, ``text``).  A PNG is that same drawing replayed element by element on a
matplotlib canvas of the SVG's size (1 SVG pixel = 1 point, so font sizes and stroke widths keep their ratio) at
:data:`DPI`: one drawing, two formats, never two layouts.  matplotlib is optional (the ``plot`` extra); without
it a PNG is bad input naming how to install it (:data:`INSTALL_HINT`).

>>> svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20"><rect width="100%" height="100%" '
...        'fill="white"/><text x="2" y="12" font-size="9">v0</text></svg>')
>>> [e[0] for e in elements(svg)]
['rect', 'text']
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from topomark.spec.errors import InvalidInput

__all__ = ["save_drawing", "check_drawable", "elements", "INSTALL_HINT", "DPI", "SUFFIXES"]

DPI = 200
SUFFIXES = (".svg", ".png")
INSTALL_HINT = "pip install matplotlib (from a checkout: pip install '.[plot]')"
_NS = "{http://www.w3.org/2000/svg}"
_ANCHOR = {"start": "left", "middle": "center", "end": "right"}


def elements(svg: str) -> list[tuple[str, dict, str]]:
    """The drawing's elements in order: (tag, attributes, text)."""
    root = ET.fromstring(svg)
    return [(e.tag.removeprefix(_NS), dict(e.attrib), e.text or "") for e in root]


def check_drawable(path: str | Path):
    """Bad input unless a drawing can be written to ``path`` (``.svg``; ``.png`` with matplotlib installed);
    matplotlib's pyplot for a PNG, else None."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise InvalidInput(f"cannot draw to {str(path)!r}: the drawing is written as .svg or .png (by the suffix)")
    if suffix == ".svg":
        return None
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise InvalidInput(f"drawing {str(path)!r} as PNG needs matplotlib: {INSTALL_HINT}; or draw to a .svg "
                           f"file, which needs nothing") from None
    return plt


def save_drawing(svg: str, path: str | Path) -> Path:
    """Write ``svg`` to ``path``: as is for ``.svg``, rendered for ``.png`` (:func:`check_drawable`)."""
    path = Path(path)
    plt = check_drawable(path)
    if plt is None:
        path.write_text(svg, encoding="utf-8")
    else:
        _render(plt, svg, path)
    return path


def _render(plt, svg: str, path: Path) -> None:
    root = ET.fromstring(svg)
    width, height = float(root.get("width", 300)), float(root.get("height", 300))
    fig = plt.figure(figsize=(width / 72, height / 72))
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, width)
    ax.set_ylim(height, 0)  # SVG's y runs down
    ax.set_axis_off()
    for z, (tag, a, text) in enumerate(elements(svg)):
        _element(plt, ax, tag, a, text, z)
    fig.savefig(path, dpi=DPI, facecolor="white")
    plt.close(fig)


def _element(plt, ax, tag: str, a: dict, text: str, z: int) -> None:
    def f(k: str, d: float = 0.0) -> float:  # a number attribute
        return float(a.get(k, d))

    if tag == "line":
        ax.plot([f("x1"), f("x2")], [f("y1"), f("y2")], color=a.get("stroke", "black"), lw=f("stroke-width", 1),
                solid_capstyle="butt", zorder=z)
    elif tag == "polygon":
        pts = [tuple(map(float, p.split(","))) for p in a["points"].split()]
        ax.add_patch(plt.Polygon(pts, closed=True, color=a.get("fill", "black"), lw=0, zorder=z))
    elif tag == "circle":
        fill = a.get("fill", "black")
        ax.add_patch(plt.Circle((f("cx"), f("cy")), f("r"), facecolor="none" if fill == "none" else fill,
                                edgecolor=a.get("stroke", "none"), lw=f("stroke-width", 0), zorder=z))
    elif tag == "text":
        ax.text(f("x"), f("y"), text, fontsize=f("font-size", 10), color=a.get("fill", "black"),
                ha=_ANCHOR.get(a.get("text-anchor", "start"), "left"), va="baseline",
                fontweight=a.get("font-weight", "normal"), zorder=z)

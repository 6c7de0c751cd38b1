"""The run viewer's page: one self-contained HTML file stepping through a replayed run (thesis §3.3, §3.5.2).

:func:`page` writes the frames of :mod:`~topomark.reference.viewer.frames` as
one HTML file that opens from disk in any current browser: scripts and styles
inline (the package's ``viewer.js``, ``panels.js`` and ``viewer.css``), no
request to any server.  The world is drawn by ``world --draw``'s own code
(:func:`topomark.proofs.drawing.world_svg`, at
:func:`~topomark.proofs.drawing.positions`), the robot, markers, thread and
walk laid over it; beside it the map S as built so far, each map vertex at
the world vertex it stands for, the unexplored darts U as dashed stubs.

The frames are not a JSON dump of the trace: each per-frame column (record
kind, the robot's vertex and entry exit, kind of walk, hypothesis under test)
is a little-endian 32-bit integer array in base 64, about 27 characters a
frame; the markers, the thread and the iterations are listed only where they
change.
"""

from __future__ import annotations

import base64
import json
import sys
from array import array
from importlib import resources
from typing import Any
from xml.sax.saxutils import escape

from topomark.spec.kit import Kit
from topomark.proofs.drawing import check_draw_size, drawing_size, positions, world_svg

from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.run.breakdown import KINDS
from topomark.reference.viewer.frames import RECORD_KINDS, RunFrames

__all__ = ["page", "run_data", "CHECKS"]

CHECKS: dict[str, dict[str, list[str]]] = {
    "robot": {"op": ["the kit and the world allow the operation", "the signature sensed after it is the world's"],
              "drop": ["the signature sensed after the drop is the world's"],
              "move": ["step number: one more than the traversals so far",
                       "pose: the perception is the world's at the robot's true vertex (§3.1.1)"],
              "end": ["cost: the traversals replayed (§3.1.2)"]},
    "algorithm-3.1": {"op": ["the lighthouse's operations, at the start only (line 1)"],
                      "drop": ["one drop, before any move (line 1)"],
                      "move": ["the purpose fits the loop body (lines 5-28)"],
                      "iteration": ["e taken from U (line 5)", "by_marker: v_u shows the lighthouse's signature or not",
                                    "H: each e' in U with v_u's signature, in the policy's order (line 9)",
                                    "M a simple path of S to v0, P^E its signatures; Lemma 1",
                                    "outcomes agree with the perceptions (lines 13-20)",
                                    "I-1 after the join (§3.4)", "I-2 after the join (§3.4)"],
                      "end": ["m iterations, U empty",
                              "extended isomorphism: S and the world with its markers (§3.1.3)"]},
    "re-run": {"op": ["the re-run's next record"], "move": ["the re-run's next record"],
               "end": ["the end's verdict is the re-run's"]},
}
"""What replay checks on each kind of record, by layer (``spec/trace.md``): a frame lists its record's checks
with replay's verdict — passed up to the divergence, the divergence's own check failed on its frame."""

LEGEND = ("World: the robot (green disc; its arrow is its entry, relative exit 0), this iteration's walk (blue), "
          "the walk of the hypothesis under test (orange), a vertex marker (orange ring; its arrow points at the "
          "exit it marks, Figure 3.2(c)), an edge marker (red bar; its arrow toward its head, Figure 6.1), the "
          "thread (purple, from the square where it is tied, §6.3).  Map S: each map vertex drawn at the world "
          "vertex it stands for (v0 filled), joined edges solid, the unexplored darts U dashed red.")


def _column(values: array) -> str:
    data = array("i", values)
    if sys.byteorder == "big":
        data.byteswap()
    return base64.b64encode(data.tobytes()).decode("ascii")


def _events(f: RunFrames) -> list[list[Any]]:
    """The timeline: [frame, type, words] for each marker or thread operation, iteration, and the end or the
    failure."""
    events: list[list[Any]] = []
    events += [[frame, "marker", words] for frame, words in f.ops]
    for it in f.iterations:
        rejected = sum(h[3] in ("case 1", "case 2") for h in it["hypotheses"])
        note = f", {rejected} hypothes{'is' if rejected == 1 else 'es'} rejected" if rejected else ""
        kind = "vertex" if it["augmentation"] == "non-loop" else "loop"
        what = f"vertex v{it['joined'][1][0]} added" if kind == "vertex" else "loop closed"
        events.append([it["frame"], "rejected" if rejected else kind, f"iteration {it['iteration']}: {what}{note}"])
    failure, bad, _ = f.judged()
    if failure is not None:
        events.append([bad, "violation", f"failed: {failure.check}"])
    elif f.frames:
        events.append([f.frames - 1, "end", "end: " + ("verified" if f.result and f.result.ok else "not verified")])
    return sorted(events, key=lambda e: e[0])


def _checks(layers: tuple[str, ...]) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for layer in layers:
        for record, checks in CHECKS.get(layer, {}).items():
            out.setdefault(record, []).extend(checks)
    return out


def _kit(header: dict[str, Any]) -> str:
    """The kit in words, with the lighthouse it establishes and where the thesis defines it."""
    name = header.get("lighthouse", "directional-vertex" if "family" not in header else None)
    kit = Kit.from_json(header["kit"]).describe() if "kit" in header else "1 directional vertex marker"
    light = LIGHTHOUSES.get(name) if isinstance(name, str) else None
    return kit + ("" if light is None else f"; lighthouse {light.name} ({light.thesis}): {light.drops}")


def run_data(f: RunFrames, size: float) -> dict[str, Any]:
    """Everything the page's scripts read, as one JSON object."""
    world, result = f.world, f.result
    assert result is not None, "the frames were taken by a replay"
    pos, _ = positions(world, size)
    index = {v: k for k, v in enumerate(world.vertices)}
    div, bad, _ = f.judged()
    return {
        "vertices": list(world.vertices), "pos": [[round(pos[v][0], 1), round(pos[v][1], 1)] for v in world.vertices],
        "rotation": [[index[w] for w in world.rotation[v]] for v in world.vertices], "m": world.m,
        "frames": f.frames, "records": list(RECORD_KINDS), "kinds": list(KINDS),
        "cols": {name: _column(getattr(f, name)) for name in ("kind", "vertex", "entry", "walk", "hyp")},
        "markers": f.markers, "thread": f.thread, "iterations": f.iterations, "v0": f.v0,
        "events": _events(f), "checks": _checks(result.layers),
        "verdict": {"ok": div is None, "message": result.message, "frame": bad,
                    "divergence": None if div is None else div.to_json()},
        "open": bad or 0}


def _asset(name: str) -> str:
    return resources.files("topomark.reference.viewer").joinpath(name).read_text(encoding="utf-8")


def _drawings(f: RunFrames, title: str, size: float) -> tuple[str, str]:
    """The world as ``world --draw`` draws it, with an overlay group; the map's drawing of the same size."""
    svg = world_svg(f.world, title, size)
    defs = "".join(f'<marker id="tm-arrow-{k}" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="4" markerHeight="4" '
                   f'orient="auto"><path d="M0,0L10,5L0,10z" fill="{c}"/></marker>'
                   for k, c in (("o", "#e67e22"), ("r", "#c0392b"), ("g", "#16a085")))
    head, _, rest = svg.partition(">")
    overlay = rest.replace("</svg>", '<g id="tm-overlay"/></svg>')
    world = f'{head} id="tm-world"><defs>{defs}</defs>{overlay}'
    width, height = head.split('width="')[1].split('"')[0], head.split('height="')[1].split('"')[0]
    pos, _ = positions(f.world, size)
    skeleton = "".join(f'<line x1="{pos[u][0]:.1f}" y1="{pos[u][1]:.1f}" x2="{pos[v][0]:.1f}" y2="{pos[v][1]:.1f}" '
                       f'stroke="#ddd" stroke-width="1.5"/>' for u, v in f.world.edges())
    the_map = (f'<svg xmlns="http://www.w3.org/2000/svg" id="tm-map" width="{width}" height="{height}" '
               f'font-family="sans-serif"><rect width="100%" height="100%" fill="white"/>'
               f'<text x="8" y="16" font-size="12" font-weight="bold">the map S</text>{skeleton}<g id="tm-map-g"/></svg>')
    return world, the_map


def _divergence(f: RunFrames) -> str:
    """The divergence side by side: what the reference (the world, the specification, topomark's re-run)
    expected and what the program's trace claims, at the line where they first differ."""
    v, _, line = f.judged()
    if v is None:
        return ""
    how = "Diverged" if f.failure is None else "Failed"
    return (f'<section id="tm-divergence"><h2>{how} at line {line} ({escape(v.where)}): {escape(v.check)}</h2>'
            f'<div class="side"><div><h3>the reference expected</h3><pre id="tm-expected">{escape(v.expected)}</pre>'
            f'</div><div><h3>the program\'s trace claims</h3><pre id="tm-found">{escape(v.found)}</pre></div></div>'
            f'<p>{escape(v.detail)}</p><p>The frames run up to this line; the run before it is verified.</p></section>')


def page(f: RunFrames, title: str) -> str:
    """The page of one replayed run, titled ``title`` (the trace's name)."""
    check_draw_size(f.world)
    size = drawing_size(f.world)
    world, the_map = _drawings(f, title, size)
    data = json.dumps(run_data(f, size), separators=(",", ":")).replace("</", "<\\/")
    r, h = f.result, f.header
    assert r is not None, "the frames were taken by a replay"
    verdict = ("VERIFIED " if r.ok else "DIVERGED ") + r.message
    if r.ok and f.failure is not None:
        verdict = f"FAILED {f.failure} (the trace's robot layer replays: {r.message})"
    body = _asset("body.html").format(
        title=escape(title), algorithm=escape(h.get("algorithm", "")), kit=escape(_kit(h)),
        layers=escape(", ".join(r.layers)), verdict=escape(verdict), world=world, map=the_map, legend=escape(LEGEND),
        divergence=_divergence(f), policies=escape(json.dumps(h.get("policies", {}), sort_keys=True)))
    return ("<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>topomark run: {escape(title)}</title><style>{_asset('viewer.css')}</style></head><body>"
            f"{body}<script type=\"application/json\" id=\"run-data\">{data}</script>"
            f"<script>{_asset('panels.js')}</script><script>{_asset('viewer.js')}</script></body></html>\n")

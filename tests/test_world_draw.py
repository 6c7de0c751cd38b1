"""``topomark world --draw``: one world drawn as SVG or PNG (vertex names, exit indices, markers, the start), and
the pair drawing of ``search --out`` with its start label clear of v0."""

from __future__ import annotations

import math
import sys
import xml.etree.ElementTree as ET

from topomark.proofs.drawing import pair_svg, world_svg
from topomark.proofs.drawing_png import elements
from topomark.reference.cli.main import main
from topomark.spec.marker import VertexMarker
from topomark.spec.world import Start, World
from topomark.spec.worldfile import save_world

SVG = "{http://www.w3.org/2000/svg}"


def _texts(root) -> list[tuple[float, float, str]]:
    return [(float(t.get("x")), float(t.get("y")), t.text) for t in root.iter(f"{SVG}text")]


def test_a_generated_lattice_is_drawn_with_every_name_and_exit_index_and_the_default_start(tmp_path, capsys):
    out = tmp_path / "w.svg"
    assert main(["world", "--draw", "lattice:rows=3,cols=4", "-o", str(out)]) == 0
    assert capsys.readouterr().out.startswith(f"drew {out}: n=12 m=17")
    root = ET.parse(out).getroot()
    words = [t for _, _, t in _texts(root)]
    assert {f"{r},{c}" for r in range(3) for c in range(4)} <= set(words)
    assert sum(w.isdigit() for w in words) == 2 * 17  # an exit index at each end of every edge
    assert "start" in words and any("no start given" in w for w in words)
    discs = {float(c.get("r")) for c in root.iter(f"{SVG}circle")}
    assert min(discs) >= 2.7 * len("0,0") + 4 - 0.05  # each disc fits its name (written to 0.1 px)


def test_the_start_label_is_off_the_start_vertex_and_markers_are_drawn(tmp_path):
    world = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, [VertexMarker("a")], start=Start("a", "b"))
    for svg in (world_svg(world), pair_svg(world, world)):
        root = ET.fromstring(svg)
        centres = [(float(c.get("cx")), float(c.get("cy")), float(c.get("r"))) for c in root.iter(f"{SVG}circle")]
        assert any(c.get("fill") == "#222" for c in root.iter(f"{SVG}circle"))  # the marked vertex, filled
        for x, y, word in _texts(root):
            if word == "start":
                assert all(math.dist((x, y), (cx, cy)) > r + 8 for cx, cy, r in centres)
    path = tmp_path / "w.json"
    save_world(world, path)
    assert main(["world", "--draw", str(path), "-o", str(tmp_path / "w.png")]) == 0
    assert (tmp_path / "w.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_png_is_the_svg_drawing_replayed():
    svg = world_svg(World({"a": ["b"], "b": ["a"]}, start=Start("a", "b")))
    tags = [tag for tag, _, _ in elements(svg)]
    assert set(tags) <= {"rect", "line", "polygon", "circle", "text"} and tags.count("circle") == 2


def test_bad_draw_requests_exit_2_with_one_message(tmp_path, capsys, monkeypatch):
    assert main(["world", "--draw", "wheel-a", "-o", str(tmp_path / "w.gif")]) == 2
    assert ".svg or .png" in capsys.readouterr().err
    assert main(["world", "--draw", "wheel-a"]) == 2
    assert "-o FILE" in capsys.readouterr().err
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # matplotlib not installed
    assert main(["world", "--draw", "wheel-a", "-o", str(tmp_path / "w.png")]) == 2
    err = capsys.readouterr().err
    assert "pip install '.[plot]'" in err and "pip install matplotlib" in err and err.count("\n") == 1
    assert not (tmp_path / "w.png").exists()
    assert main(["world", "--draw", "wheel-a", "-o", str(tmp_path / "w.svg")]) == 0  # SVG needs nothing

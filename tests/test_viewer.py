"""The run viewer without a browser: its frames against the specification, its page's form, ``topomark view``'s
exit codes and messages, and the world a trace gives by itself (``reference/viewer/``)."""

from __future__ import annotations

import json
import re
from collections import Counter
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.replay.replay import parse_trace
from topomark.reference.run.breakdown import KINDS
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.viewer.frames import take_frames
from topomark.reference.viewer.page import page
from topomark.reference.worlds import generators as g
from topomark.spec.worldfile import dumps_world

from viewer_truth import truths

RUNS = [("basic", None), ("enh1", None), ("basic", "directional-edge"), ("basic", "vertex-and-edge")]


def _run(world, algorithm="basic", lighthouse=None):
    from topomark.reference.explorers.lighthouses import LIGHTHOUSES
    light = None if lighthouse is None else LIGHTHOUSES[lighthouse]
    return explore(world, algorithm, lighthouse=light) if light else explore(world, algorithm)


@pytest.mark.parametrize("algorithm,lighthouse", RUNS)
def test_the_frames_show_the_robot_markers_map_and_cost_of_the_specification(algorithm, lighthouse):
    world = g.lattice(3, 4)
    o = _run(world, algorithm, lighthouse)
    records = parse_trace(dump_trace(o.trace))
    f = take_frames(world, iter(records), "t")
    assert f.result is not None and f.result.ok and f.frames == len(records)
    names = f.world.vertices
    for k, truth in enumerate(truths(world, records)):
        assert names[f.vertex[k]] == truth.vertex, k
    # the kinds of walk add up to the run's own cost breakdown, kind by kind
    split = Counter(KINDS[w] for w in f.walk if w >= 0)
    assert {k: v for k, v in o.breakdown.by_kind().items() if v} == dict(split)


def test_a_move_tests_the_hypothesis_its_iteration_records():
    world = g.lattice(3, 3)
    f = take_frames(world, iter(explore(world).trace), "t")
    tested = [k for k in range(f.frames) if f.hyp[k] >= 0]
    assert tested, "the lattice's run tests hypotheses"
    for k in tested:
        it = next(i for i in f.iterations if i["frame"] > k)
        assert f.hyp[k] < len(it["hypotheses"])
        if KINDS[f.walk[k]].startswith("validation case"):
            assert KINDS[f.walk[k]].endswith(it["hypotheses"][f.hyp[k]][3])


def test_the_page_is_self_contained_and_compact():
    world = g.lattice(4, 4)
    f = take_frames(world, iter(explore(world).trace), "t")
    html = page(f, "lattice")
    assert html.count("<script") == 3 and "<link" not in html and "src=" not in html
    assert set(re.findall(r"https?://[^\"' ]+", html)) == {"http://www.w3.org/2000/svg"}  # a namespace, no request
    data = json.loads(html.split('id="run-data">')[1].split("</script>")[0])
    assert data["frames"] == f.frames and len(data["cols"]["kind"]) <= 4 * ((4 * f.frames + 2) // 3)


def _files(tmp_path, world, trace):
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "t.jsonl").write_text(dump_trace(trace))
    return str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")


def test_view_exit_codes_and_the_divergence(tmp_path, capsys):
    world = g.lattice(3, 3)
    w, t = _files(tmp_path, world, explore(world).trace)
    assert main(["view", t, "--world", w, "-o", str(tmp_path / "a.html"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["verified"] is True
    assert main(["view", t, "--world", w, "-o", str(tmp_path / "a.html")]) == 2  # no --force: not overwritten
    assert "exists" in capsys.readouterr().err
    bad = explore(world).trace
    move = [r for r in bad if r["event"] == "move"][10]
    move["perception"] = "[9,A,A]"
    _, t2 = _files(tmp_path, world, bad)
    assert main(["view", t2, "--world", w, "-o", str(tmp_path / "d.html")]) == 1
    html = (tmp_path / "d.html").read_text()
    assert 'id="tm-divergence"' in html and "perception [9,A,A]" in html.split('id="tm-found">')[1][:40]


BAD = [
    (lambda lines: lines[:-1], "exactly one end event"),
    (lambda lines: [lines[0].replace("trace@1", "trace@7")] + lines[1:], "format"),
    (lambda lines: lines[:3] + ["{"] + lines[3:], "line 4"),
]


@pytest.mark.parametrize("edit,words", BAD)
def test_bad_traces_are_exit_2_with_replays_own_message(tmp_path, capsys, edit, words):
    world = g.cycle(5)
    w, t = _files(tmp_path, world, explore(world).trace)
    lines = (tmp_path / "t.jsonl").read_text().splitlines()
    (tmp_path / "t.jsonl").write_text("\n".join(edit(lines)) + "\n")
    assert main(["replay", w, t]) == 2
    replayed = capsys.readouterr().err
    assert main(["view", t, "--world", w, "-o", str(tmp_path / "v.html")]) == 2
    assert capsys.readouterr().err == replayed and words in replayed
    assert not (tmp_path / "v.html").exists()


def test_a_world_that_does_not_match_is_replays_message(tmp_path, capsys):
    w, t = _files(tmp_path, g.cycle(5), explore(g.lattice(2, 3)).trace)
    assert main(["view", t, "--world", w, "-o", str(tmp_path / "v.html")]) == 2
    assert "recorded on a world with n=6, m=7" in capsys.readouterr().err


def test_without_a_world_the_trace_gives_its_own(tmp_path, capsys):
    world = g.lattice(3, 3)
    _, t = _files(tmp_path, world, explore(world, "enh1").trace)
    assert main(["view", t, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["verified"] is True and out["page"] == str(tmp_path / "t.html")


def test_a_trace_that_does_not_give_its_world_is_refused(tmp_path, capsys):
    world = g.lattice(3, 3)
    trace = explore(world).trace
    cut = [r for r in trace if r["event"] != "iteration" or r["iteration"] != 7]  # one join fewer: S not complete
    _, t = _files(tmp_path, world, cut)
    assert main(["view", t, "-o", str(tmp_path / "v.html")]) == 2
    assert "its map is not complete" in capsys.readouterr().err
    _, t = _files(tmp_path, world, explore(world, "dudek").trace)  # a kit algorithm's: the robot family
    assert main(["view", t, "-o", str(tmp_path / "v.html")]) == 2
    assert "family robot records no map" in capsys.readouterr().err


def test_explore_and_replay_write_the_same_page(tmp_path, capsys):
    world = g.lattice(3, 3)
    (tmp_path / "w.json").write_text(dumps_world(world))
    w = str(tmp_path / "w.json")
    assert main(["explore", w, "--trace", str(tmp_path / "t.jsonl"), "--view", str(tmp_path / "e.html"),
                 "--quiet", "--json"]) == 0
    assert main(["replay", w, str(tmp_path / "t.jsonl"), "--view", str(tmp_path / "r.html")]) == 0
    capsys.readouterr()
    strip = lambda text: re.sub(r"<title>.*?</title>|<h1>.*?</h1>|<text x=\"8.0\" y=\"16\"[^>]*>[^<]*</text>", "", text)
    assert strip((tmp_path / "e.html").read_text()) == strip((tmp_path / "r.html").read_text())


def test_the_docs_example_page_is_current(tmp_path, capsys):
    """``docs/viewer-example.html``, linked from the tutorial, is what ``explore --view`` writes today."""
    out = tmp_path / "viewer-example.html"
    assert main(["explore", "lattice:rows=4,cols=4", "--view", str(out), "--quiet"]) == 0
    capsys.readouterr()
    docs = Path(__file__).resolve().parents[1] / "docs" / "viewer-example.html"
    assert out.read_text() == docs.read_text(), ("regenerate it: topomark explore lattice:rows=4,cols=4 --view "
                                                 "docs/viewer-example.html --force")


def test_a_stopped_run_or_a_moving_lighthouse_does_not_give_its_world(tmp_path, capsys):
    from topomark.reference.explorers.lighthouses import LIGHTHOUSES
    world = g.lattice(3, 3)
    moved = explore(world, lighthouse=LIGHTHOUSES["three-undirected-vertex"]).trace  # walks to mark a neighbour
    _, t = _files(tmp_path, world, moved)
    assert main(["view", t, "-o", str(tmp_path / "v.html")]) == 2
    assert "the lighthouse moved the robot before v0 was established" in capsys.readouterr().err
    assert main(["view", t, "--world", str(tmp_path / "w.json"), "-o", str(tmp_path / "v.html")]) == 0
    capsys.readouterr()
    stopped = explore(g.cycle(6), lighthouse=LIGHTHOUSES["undirected-vertex"]).trace  # outcome failed
    assert stopped[-1].get("outcome") == "failed"
    _, t = _files(tmp_path, g.cycle(6), stopped)
    assert main(["view", t, "-o", str(tmp_path / "s.html")]) == 2
    assert "the run stopped before its map was complete (failed)" in capsys.readouterr().err


def test_the_page_is_never_written_over_its_trace(tmp_path, capsys):
    world = g.cycle(4)
    w, _ = _files(tmp_path, world, explore(world).trace)
    (tmp_path / "t.html").write_text(dump_trace(explore(world).trace))
    assert main(["view", str(tmp_path / "t.html"), "--world", w, "--force"]) == 2
    assert "written over the trace" in capsys.readouterr().err


def test_a_divergence_at_the_header_is_a_page_of_one_line(tmp_path, capsys):
    """Replay's re-run layer judges the header's kit before any record: the page still has its first line."""
    world = g.lattice(3, 3)
    trace = explore(world, "dudek").trace
    trace[0]["kit"] = {"movable": True, "undirected-vertex": 2}
    w, t = _files(tmp_path, world, trace)
    assert main(["view", t, "--world", w, "-o", str(tmp_path / "v.html")]) == 1
    assert "wrote" in capsys.readouterr().out
    f = take_frames(world, iter(parse_trace(dump_trace(trace))), "t")
    assert f.frames == 1 and f.divergence_frame == 0 and f.judged()[0].check == "marker kit"

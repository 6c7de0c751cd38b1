"""The contest server (``reference/contest/``) on the loopback address, driven through its HTTP interface only.

The example explorer (``reference/contest/examples/explorer.py``, standard library only) runs unchanged against
it and is judged correct on generated problems and on shared contest maps; a wrong guess gets ``correct: false``
with a witness that the server's own ``/explore`` confirms; many sessions run at once; every malformed request is
a 400 naming the fault (never the id) while the server goes on serving; the per-problem log holds what was said;
``topomark contest serve`` starts, answers and stops on Ctrl-C with exit 130.  All requests go to 127.0.0.1.
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import urllib.error
import urllib.request
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from types import SimpleNamespace

import pytest

from topomark.reference.contest.app import build_app
from topomark.reference.contest.game import Contest
from topomark.reference.contest.problems import PROBLEMS, Problems, distinct_rooms
from topomark.reference.contest.serve import serving
from topomark.reference.port.files import load_port_file
from topomark.reference.port.judge import judge
from topomark.spec.port_icfpc import map_to_json
from topomark.spec.port_plan import parse_plan, run_plan
from topomark.spec.port_world import from_joins

ROOT = Path(__file__).resolve().parents[1]
EXPLORER = ROOT / "reference" / "contest" / "examples" / "explorer.py"
MAPS = ROOT / "tests" / "data" / "icfpc2025"
SECRET = "team-secret-7f3a"


def post(url: str, path: str, body: object, *, raw: bytes | None = None, method: str = "POST") -> tuple[int, dict]:
    """One request to the server: the status and the JSON answer."""
    data = raw if raw is not None else json.dumps(body).encode()
    request = urllib.request.Request(url + path, data=data if method == "POST" else None, method=method,
                                     headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(request, timeout=30) as answer:
            return answer.status, json.load(answer)
    except urllib.error.HTTPError as e:
        text = e.read().decode()
        return e.code, json.loads(text) if text.startswith("{") else {"text": text}


def explorer(url: str, problem: str, *extra: str) -> tuple[int, dict]:
    done = subprocess.run([sys.executable, str(EXPLORER), "--server", url, "--problem", problem, *extra],
                          capture_output=True, text=True, timeout=60)
    return done.returncode, json.loads(done.stdout)


@pytest.fixture
def server(tmp_path):
    """A function starting a server (a context manager yielding its URL) with the given Problems and options."""
    def start(problems: Problems | None = None, judge_with=judge, **options):
        options.setdefault("log_dir", str(tmp_path))
        return serving(build_app(Contest(problems or Problems(seed=5), judge_with, **options)))
    return start


def test_the_explorer_solves_generated_and_shared_maps(server):
    with server() as url:
        for problem in ("probatio", "primus"):
            code, out = explorer(url, problem)
            assert (code, out["correct"], out["rooms"]) == (0, True, PROBLEMS[problem][0]), out
    with server(Problems(maps=MAPS)) as url:
        for problem in ("probatio", "primus"):
            code, out = explorer(url, problem, "--seed", "3")
            assert (code, out["correct"]) == (0, True), out


def test_many_sessions_at_once(server, tmp_path):
    with server() as url, ThreadPoolExecutor(6) as pool:
        outs = list(pool.map(lambda k: explorer(url, ("probatio", "primus")[k % 2], "--seed", str(k)), range(6)))
    assert all(code == 0 and out["correct"] is True for code, out in outs), outs
    logs = sorted(tmp_path.glob("*.json"))
    assert len(logs) == 6 and all(json.loads(p.read_text())["verdict"] == {"correct": True} for p in logs)


def test_a_wrong_guess_gets_a_witness_the_server_confirms(server):
    """The hidden map is a world by file; the guess differs in one room's colour.  After the guess, the same
    problem is selected again and the witness plan explored: the server's record is the witness's."""
    _, hidden = load_port_file(MAPS / "primus" / "000.json")
    colours = list(hidden.colours)
    colours[5] = (colours[5] + 1) % 4
    wrong = from_joins(colours, list(hidden.passages()), hidden.start)
    with server(Problems(worlds={"mine": hidden})) as url:
        post(url, "/select", {"id": SECRET, "problemName": "mine"})
        status, answer = post(url, "/guess", {"id": SECRET, "map": map_to_json(wrong)})
        assert status == 200 and answer["correct"] is False and answer["reason"], answer
        witness = answer["witness"]
        actions = parse_plan(witness["plan"])
        assert witness["hidden"] == list(run_plan(hidden, actions)) != witness["guess"] == list(run_plan(wrong, actions))
        assert post(url, "/explore", {"id": SECRET, "plans": ["0"]})[0] == 400  # the guess ended the problem
        post(url, "/select", {"id": SECRET, "problemName": "mine"})
        status, answer = post(url, "/explore", {"id": SECRET, "plans": [witness["plan"]]})
        assert status == 200 and answer["results"] == [witness["hidden"]]


def test_a_copy_map_guessed_by_its_base_is_wrong_and_told_apart_with_marks(server):
    with server(Problems(maps=MAPS)) as url:
        code, out = explorer(url, "aleph", "--rooms", "6")  # learns the base: no plan without marks tells them apart
        assert (code, out["correct"]) == (1, False) and "[" in out["witness"]["plan"], out
        post(url, "/select", {"id": SECRET, "problemName": "aleph"})
        _, hidden = load_port_file(MAPS / "aleph" / "000.json")
        _, base = load_port_file(MAPS / "primus" / "000.json")
        status, answer = post(url, "/guess", {"id": SECRET, "map": map_to_json(base)})
    assert status == 200 and answer["correct"] is False and answer["witness"]["hidden"] != answer["witness"]["guess"]


def test_a_witness_that_does_not_separate_is_never_sent(server):
    """Seeded fault: a judge whose witness gives the same record on both maps.  The server replays every
    witness, answers 500 instead, and goes on serving."""
    def lying(hidden, guess):
        return SimpleNamespace(equivalent=False, witness="", reason="lying judge")
    _, hidden = load_port_file(MAPS / "probatio" / "000.json")
    with server(Problems(worlds={"p": hidden}), judge_with=lying) as url:
        post(url, "/select", {"id": SECRET, "problemName": "p"})
        status, answer = post(url, "/guess", {"id": SECRET, "map": map_to_json(hidden)})
        assert status == 500 and "same record on both maps" in answer["error"]
        assert post(url, "/select", {"id": SECRET, "problemName": "p"}) == (200, {"problemName": "p"})


def test_queries_are_counted_as_the_contest_counted_them_and_marks_echoed_or_not(server):
    _, hidden = load_port_file(MAPS / "probatio" / "000.json")
    problems = Problems(worlds={"p": hidden})
    with server(problems) as url, server(problems, echo_marks=False) as quiet:
        post(url, "/select", {"id": SECRET, "problemName": "p"})
        assert post(url, "/explore", {"id": SECRET, "plans": ["0", "1", "2"]})[1]["queryCount"] == 4
        answer = post(url, "/explore", {"id": SECRET, "plans": ["[1]0"]})[1]
        assert answer["queryCount"] == 6 and answer["results"] == [list(run_plan(hidden, parse_plan("[1]0")))]
        assert len(answer["results"][0]) == 3
        post(url, "/select", {"id": SECRET, "problemName": "p"})
        assert post(url, "/explore", {"id": SECRET, "plans": []})[1] == {"results": [], "queryCount": 1}
        post(quiet, "/select", {"id": SECRET, "problemName": "p"})
        answer = post(quiet, "/explore", {"id": SECRET, "plans": ["[1]0"]})[1]
        assert answer["results"] == [list(run_plan(hidden, parse_plan("[1]0"), echo_marks=False))]
        assert len(answer["results"][0]) == 2


BAD = [  # (endpoint, body or raw bytes, what the message must say)
    ("/select", b"{not json", "malformed JSON"),
    ("/select", b"[1, 2]", "not a JSON object"),
    ("/select", b"\xff\xfe", "not UTF-8"),
    ("/select", b'{"id": "x", "id": "y", "problemName": "p"}', "duplicate key 'id'"),
    ("/select", {"id": SECRET, "problemName": "p", "seed": 3}, "unknown key 'seed'"),
    ("/select", {"problemName": "p"}, "the key 'id' is missing"),
    ("/select", {"id": 12, "problemName": "p"}, "id is not a string"),
    ("/select", {"id": SECRET, "problemName": "nonesuch"}, "unknown problem 'nonesuch'"),
    ("/explore", {"id": "never-selected", "plans": ["0"]}, "no problem is selected"),
    ("/guess", {"id": "never-selected", "map": {}}, "no problem is selected"),
    ("/explore", {"id": SECRET, "plans": "012"}, "plans is not a list"),
    ("/explore", {"id": SECRET, "plans": [12]}, "plans[0] is not a string"),
    ("/explore", {"id": SECRET, "plans": ["0", "017"]}, "plans[1]: plan character 3 ('7')"),
    ("/explore", {"id": SECRET, "plans": ["0[4]"]}, "plans[0]: plan character 2 starts a mark"),
    ("/explore", {"id": SECRET, "plans": ["0" * 19]}, "19 doors, over the full round's limit of 18"),
    ("/guess", {"id": SECRET, "map": {"rooms": [0], "startingRoom": 0, "connections": [], "id": SECRET}},
     "unknown key 'id'"),
    ("/guess", {"id": SECRET, "map": {"rooms": [0, 1], "startingRoom": 0, "connections": [
        {"from": {"room": 0, "door": 0}, "to": {"room": 1, "door": 0}},
        {"from": {"room": 0, "door": 0}, "to": {"room": 1, "door": 1}}]}}, "door-end (0, 0) is used twice"),
    ("/guess", {"id": SECRET, "map": {"rooms": [0, 7], "startingRoom": 0, "connections": [
        {"from": {"room": 0, "door": d}, "to": {"room": 1, "door": d}} for d in range(6)]}},
     "colour 7 is outside the alphabet"),
    ("/guess", {"id": SECRET, "map": {"rooms": [0], "startingRoom": 3, "connections": [
        {"from": {"room": 0, "door": d}, "to": {"room": 0, "door": d}} for d in range(6)]}}, "start room 3"),
]


def test_every_bad_request_is_a_400_naming_the_fault_and_the_server_keeps_serving(server):
    _, hidden = load_port_file(MAPS / "probatio" / "000.json")
    with server(Problems(worlds={"p": hidden})) as url:
        for endpoint, body, says in BAD:
            post(url, "/select", {"id": SECRET, "problemName": "p"})
            raw = body if isinstance(body, bytes) else None
            status, answer = post(url, endpoint, body, raw=raw)
            assert status == 400 and says in answer["error"], (endpoint, body, answer)
            assert SECRET not in answer["error"] and answer["error"].startswith(endpoint), answer
        assert post(url, "/select", {"id": SECRET}, method="GET")[0] == 405
        assert post(url, "/nowhere", {"id": SECRET})[0] == 404
        post(url, "/select", {"id": SECRET, "problemName": "p"})
        assert post(url, "/explore", {"id": SECRET, "plans": ["0" * 18]})[0] == 200  # at the limit: served


def test_the_lightning_round_allows_18n_doors_and_no_marks(server):
    _, hidden = load_port_file(MAPS / "probatio" / "000.json")
    with server(Problems(worlds={"p": hidden}), round_name="lightning") as url:
        post(url, "/select", {"id": SECRET, "problemName": "p"})
        assert post(url, "/explore", {"id": SECRET, "plans": ["0" * 54]})[0] == 200
        status, answer = post(url, "/explore", {"id": SECRET, "plans": ["0" * 55]})
        assert status == 400 and "lightning round's limit of 54" in answer["error"]
        status, answer = post(url, "/explore", {"id": SECRET, "plans": ["[1]0"]})
        assert status == 400 and "charcoal marks are not part of the lightning round" in answer["error"]


def test_the_log_holds_every_exchange_the_hidden_map_and_the_verdict_and_never_the_id(server, tmp_path):
    _, hidden = load_port_file(MAPS / "primus" / "000.json")
    with server(Problems(worlds={"primus": hidden})) as url:
        code, out = explorer(url, "primus", "--id", SECRET)
    assert code == 0
    (path,) = tmp_path.glob("*.json")
    text = path.read_text()
    log = json.loads(text)
    assert SECRET not in text and path.name == "00001-primus.json"
    assert (log["format"], log["problem"], log["round"], log["echo_marks"]) == ("topomark/contest-log@1", "primus",
                                                                              "full", True)
    assert log["hidden"] == map_to_json(hidden) and log["verdict"] == {"correct": True}
    endpoints = [e["endpoint"] for e in log["exchanges"]]
    assert endpoints[0] == "/select" and endpoints[-1] == "/guess" and set(endpoints[1:-1]) == {"/explore"}
    assert log["queryCount"] == out["queryCount"] == log["exchanges"][-2]["answer"]["queryCount"]
    explored = [e for e in log["exchanges"] if e["endpoint"] == "/explore"]
    assert sum(len(e["request"]["plans"]) + 1 for e in explored) == log["queryCount"]


def test_generated_problems_have_the_contests_sizes_and_single_maps_are_minimal():
    problems = Problems(seed=11)
    for name, (rooms, copies) in PROBLEMS.items():
        world = problems.draw(name)
        assert world.rooms == rooms * copies and distinct_rooms(world) == rooms, name


def test_the_same_seed_serves_the_same_maps():
    a, b = Problems(seed=4), Problems(seed=4)
    assert [a.draw("secundus") for _ in range(3)] == [b.draw("secundus") for _ in range(3)]
    assert Problems(seed=5).draw("secundus") != Problems(seed=4).draw("secundus")


def test_the_command_serves_and_stops_on_ctrl_c(tmp_path):
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.Popen([sys.executable, "-m", "topomark", "contest", "serve", "--port", "0", "--seed", "1",
                             "--log-dir", str(tmp_path / "logs")], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=env)
    try:
        line = proc.stdout.readline()
        url = re.search(r"http://127\.0\.0\.1:\d+", line).group(0)
        assert post(url, "/select", {"id": SECRET, "problemName": "probatio"}) == (200, {"problemName": "probatio"})
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=20)
    finally:
        proc.kill()
    assert proc.returncode == 130 and err.strip().endswith("topomark: interrupted"), err
    assert len(list((tmp_path / "logs").glob("*.json"))) == 1


@pytest.mark.parametrize("argv, says", [
    (["--host", "0.0.0.0"], "not a loopback address"),
    (["--world", "x y=f.json"], "a problem name is 1 to 64"),
    (["--maps", "/nonexistent-maps"], "not a directory"),
    (["--port", "70000"], "not a port"),
])
def test_bad_options_are_exit_2(capsys, argv, says):
    from topomark.reference.cli.main import main

    assert main(["contest", "serve", *argv]) == 2
    assert says in capsys.readouterr().err


def test_a_non_empty_log_dir_needs_force(tmp_path, capsys):
    from topomark.reference.cli.main import main

    (tmp_path / "other.txt").write_text("x")
    assert main(["contest", "serve", "--log-dir", str(tmp_path), "--port", "-1"]) == 2
    assert "give --force" in capsys.readouterr().err


def test_the_explorer_imports_the_standard_library_only():
    import ast

    tree = ast.parse(EXPLORER.read_text(encoding="utf-8"))
    names = {a.name for node in ast.walk(tree) if isinstance(node, ast.Import) for a in node.names}
    names |= {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom) and node.module}
    assert names and {n.partition(".")[0] for n in names} <= set(sys.stdlib_module_names) - {"topomark"}


def test_distinct_rooms_agrees_with_the_judges_partition_refinement():
    """Two implementations of "how many rooms does a plan without marks tell apart" (the generator keeps a map only
    when it is its room count): this module's and the judge's refinement on the map beside itself."""
    from topomark.reference.port.generate import cover, random_port_world
    from topomark.reference.port.plain import refine

    worlds = [random_port_world(seed, rooms, doors=doors, alphabet=alphabet)
              for seed in range(40) for rooms, doors, alphabet in ((5, 3, 2), (7, 2, 1), (6, 6, 4), (4, 2, 2))]
    worlds += [cover(w, 2, seed=1) for w in worlds[:10]]
    counts = [distinct_rooms(w) for w in worlds]
    assert counts == [len(set(refine(w, w)[1][:w.rooms])) for w in worlds]
    assert min(counts) < max(counts) and any(c < w.rooms for c, w in zip(counts, worlds))

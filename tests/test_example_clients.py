"""The example clients of ``reference/oracle/examples/`` for four marker kits, run through ``topomark
run-external`` over protocol @2 with the kit their algorithm is registered with: Algorithm 3.1's directional
vertex marker (``client.py``, §3.3, ``basic``), Dudek's movable marker (``client_dudek.py``, §2.3.1), Case 1a's
m edge markers (``client_edge_markers.py``, §6.2.1) and the carried l = ε thread (``client_thread.py``, §6.3.1).
Each maps the small worlds and passes its algorithm's conformance suite, and a copy with one line changed (a
seeded fault) fails with exit 1 and the reason that names the fault."""

from __future__ import annotations

import ast
import json
import sys
from pathlib import Path

import pytest

from conftest import FIGURE_3_4, make_world
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.cli.main import main

EXAMPLES = Path(__file__).resolve().parents[1] / "reference" / "oracle" / "examples"
CLIENTS = {"basic": "client.py", "dudek": "client_dudek.py", "case-1a": "client_edge_markers.py",
           "thread-carried": "client_thread.py"}
WORLDS = ("cycle:n=3", "cycle:n=7", "chain:n=2", "chain:n=5", "lattice-hole:rows=4,cols=4,seed=1", *FIGURE_3_4,
          "complete:n=4")
CHIRAL = "lattice-hole:rows=4,cols=4,seed=1"  # its mirror image is not extended-isomorphic to it (the wheels', K4's is)
TWO_ON_E = ('"exit": 0, "count": 1}', '"exit": 0, "count": 2}')  # the drop on e, with one marker more
MIRROR = ("[names[w] for w, _ in row]", "[names[w] for w, _ in reversed(row)]")


def kit(algorithm: str, world: str, short: int = 0) -> str:
    """The kit ``algorithm`` is registered with on ``world`` (``short`` markers fewer), as ``--kit`` JSON."""
    w = make_world(world)
    given = algorithm_spec(algorithm).kit_for(w.n, w.m, {}).to_json()
    return json.dumps({k: v - short if k.endswith("-edge") else v for k, v in given.items()})


def run(capsys, client: Path, world: str, kit_json: str) -> tuple[int, dict]:
    """``topomark run-external WORLD --kit KIT --json -- python CLIENT``: the exit code and the JSON report."""
    code = main(["run-external", world, "--kit", kit_json, "--json", "--", sys.executable, str(client)])
    return code, json.loads(capsys.readouterr().out)


def seeded(tmp_path: Path, algorithm: str, old: str, new: str) -> Path:
    """A copy of ``algorithm``'s client with the one line holding ``old`` changed to hold ``new``."""
    text = (EXAMPLES / CLIENTS[algorithm]).read_text()
    assert text.count(old) == 1, f"{old!r} must occur once in {CLIENTS[algorithm]}"
    path = tmp_path / CLIENTS[algorithm]
    path.write_text(text.replace(old, new))
    return path


@pytest.mark.parametrize("algorithm", CLIENTS)
def test_each_client_is_standalone_standard_library_only(algorithm):
    tree = ast.parse((EXAMPLES / CLIENTS[algorithm]).read_text())
    imported = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                for alias in node.names}
    imported |= {node.module.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
    assert imported <= {"json", "re", "sys", "collections"}  # the standard library only, no topomark


@pytest.mark.parametrize("world", WORLDS)
@pytest.mark.parametrize("algorithm", CLIENTS)
def test_each_client_maps_each_small_world_with_its_registered_kit(capsys, algorithm, world):
    code, report = run(capsys, EXAMPLES / CLIENTS[algorithm], world, kit(algorithm, world))
    assert (code, report["verdict"], report["reason"]) == (0, "pass", "ok"), report["message"]
    w = make_world(world)
    assert report["snapshots"] == w.m  # one per iteration, every one held I-1 and I-2
    assert report["cost"] <= algorithm_spec(algorithm).bound_for(w.n, w.m)  # within the registered exact bound


@pytest.mark.parametrize("algorithm, other", [("dudek", "case-1a"), ("case-1a", "thread-carried"),
                                              ("thread-carried", "dudek")])
def test_a_client_refuses_a_kit_it_cannot_use(capsys, algorithm, other):
    code, report = run(capsys, EXAMPLES / CLIENTS[algorithm], "cycle:n=3", kit(other, "cycle:n=3"))
    assert (code, report["reason"]) == (1, "crash") and "I need topomark/protocol@2" in report["message"]


FAULTS = [  # (algorithm, old, new, world, reason, words in the verdict)
    pytest.param("dudek", '            self.step((i - self.pos[1]) % len(self.exits[vk]))\n            self.operate(',
                 "            self.operate(", "complete:n=4", "marker", "there is no vertex marker here to pick up",
                 id="dudek-pick-up-where-nothing-lies"),
    pytest.param("case-1a", *TWO_ON_E, "chain:n=2", "marker", "holds 1 edge marker(s): 1 left, 2 asked for",
                 id="case-1a-one-marker-too-many-for-the-kit"),
    pytest.param("case-1a", *TWO_ON_E, "complete:n=4", "invariant", "expected 1 edge marker(s) on exit 0, found 2",
                 id="case-1a-one-marker-too-many-on-an-edge"),
    pytest.param("thread-carried", '            self.thread("leave")\n', "", "complete:n=4", "marker",
                 "the thread would run out", id="thread-moves-holding-an-epsilon-thread"),
    pytest.param("thread-carried", '                self.thread("untie")\n                x, j', "                x, j",
                 "complete:n=4", "invariant", "found the thread", id="thread-left-tied-after-a-loop"),
    *(pytest.param(algorithm, *MIRROR, CHIRAL, "not-isomorphic", "extended isomorphism violated",
                   id=f"{algorithm}-mirrored-map") for algorithm in CLIENTS),
]


@pytest.mark.parametrize("algorithm, old, new, world, reason, words", FAULTS)
def test_a_seeded_fault_fails_with_its_reason(capsys, tmp_path, algorithm, old, new, world, reason, words):
    code, report = run(capsys, seeded(tmp_path, algorithm, old, new), world, kit(algorithm, world))
    assert (code, report["verdict"], report["reason"]) == (1, "fail", reason), report["message"]
    assert words in report["message"]


def test_the_edge_marker_client_one_marker_short_stops_and_the_world_refuses_the_drop_it_did_not_count(capsys,
                                                                                                        tmp_path):
    short = kit("case-1a", "cycle:n=3", short=1)  # two markers for three edges
    code, report = run(capsys, EXAMPLES / CLIENTS["case-1a"], "cycle:n=3", short)
    assert (code, report["reason"]) == (1, "crash") and "out of edge markers" in report["message"]
    blind = seeded(tmp_path, "case-1a", "if self.markers == 0:", "if False:")
    code, report = run(capsys, blind, "cycle:n=3", short)
    assert (code, report["reason"]) == (1, "marker") and "holds 2 edge marker(s): none left, 1 asked for" in report["message"]


@pytest.mark.slow
@pytest.mark.parametrize("algorithm", CLIENTS)
def test_each_client_passes_its_algorithms_conformance_suite(algorithm, tmp_path, capsys):
    """``conformance export --algorithm NAME`` then ``conformance run --algorithm NAME -- python CLIENT``: every
    case of the algorithm's own suite, each with the kit the registry gives it on that world, passes — including a
    case where the budget runs out, which passes only if the client reports failure."""
    suite = tmp_path / "suite"
    assert main(["conformance", "export", str(suite), "--algorithm", algorithm]) == 0
    capsys.readouterr()
    code = main(["conformance", "run", str(suite), "--algorithm", algorithm, "--json", "--",
                 sys.executable, str(EXAMPLES / CLIENTS[algorithm])])
    report = json.loads(capsys.readouterr().out)
    assert code == 0, report
    assert len(report["cases"]) >= 4 and all(r["verdict"] == "pass" for r in report["cases"])

"""Exit 3 writes a fault report: one JSON file holding what topomark's maintainers need to reproduce the fault.

The fault is seeded where topomark checks itself: under ``--check-mode both`` the checker evaluates I-1/I-2
incrementally and from scratch and the two must agree (``reference/run/checker.py``); here the from-scratch
I-1 reports a violation at one iteration that the incremental check does not see, so topomark's own checks
disagree, exit 3.  An unexpected exception (a ZeroDivisionError in the explorer) is the other kind of fault.
The report must name the command line, inline the world file, hold the trace up to the fault (the same
records a run without the fault makes, up to that point), and name the check that failed; an unwritable
place still exits 3 and says so; exits 0, 1 and 2 write none.
"""

from __future__ import annotations

import datetime
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from topomark.reference.cli import fault_report
from topomark.reference.cli.fault_report import FORMAT, build_report, write_report
from topomark.reference.cli.main import main
from topomark.reference.run import checker as checker_module
from topomark.reference.run import explore as explore_module
from topomark.reference.run.explore import explore
from topomark.reference.trace.flight import FlightRecorder, run_of
from topomark.reference.worlds.argument import resolve_world
from topomark.spec.errors import CheckFailure, TopomarkFault, Violation
from topomark.spec.worldfile import dumps_world, world_to_json

ROOT = Path(__file__).resolve().parents[1]
WORLD = "lattice-hole:rows=4,cols=5,seed=3"
FIELDS = {"format", "written", "topomark", "python", "platform", "cwd", "argv", "inputs", "run", "failure"}
AT = 4
"""The call of the from-scratch I-1 check that reports the seeded violation (the start's is the first)."""

SEED_DISAGREEMENT = f"""
from topomark.reference.run import checker as _checker
from topomark.spec.errors import Violation as _Violation
_real, _calls = _checker.check_I1, []
def _skewed(*args):
    _calls.append(1)
    return _Violation("I-1", "seeded", "a", "b") if len(_calls) == {AT} else _real(*args)
_checker.check_I1 = _skewed
"""


@pytest.fixture
def world_file(tmp_path) -> Path:
    path = tmp_path / "world.json"
    path.write_text(dumps_world(resolve_world(WORLD)))
    return path


@pytest.fixture
def reports(tmp_path, monkeypatch) -> Path:
    """The directory fault reports go to in this test (TOPOMARK_FAULT_DIR); the current directory is another."""
    folder = tmp_path / "reports"
    folder.mkdir()
    monkeypatch.setenv("TOPOMARK_FAULT_DIR", str(folder))
    here = tmp_path / "cwd"
    here.mkdir()
    monkeypatch.chdir(here)
    return folder


def seed_disagreement(monkeypatch) -> None:
    namespace: dict = {}
    exec(SEED_DISAGREEMENT, namespace)  # the one seeded fault, shared with the subprocess test
    monkeypatch.setattr(checker_module, "check_I1", namespace["_skewed"])


def seed_exception(monkeypatch) -> None:
    from topomark.reference.explorers.algorithm31 import LighthouseExplorer
    real, steps = LighthouseExplorer.step, []

    def step(self):
        steps.append(1)
        if len(steps) == 3:
            raise ZeroDivisionError("seeded division by zero")
        return real(self)
    monkeypatch.setattr(LighthouseExplorer, "step", step)


def shown_report(err: str) -> str:
    """The report's path as the message gives it."""
    found = re.search(r"A report was written to (\S+) \(", err)
    assert found, err
    return found.group(1)


def named_report(err: str) -> Path:
    return Path(shown_report(err))


def the_trace(world_file: Path) -> list[dict]:
    """The records a checked run of the world makes when nothing fails."""
    return explore(resolve_world(str(world_file)), "basic", check_mode="both").trace


def assert_complete(report: dict, argv: list[str], world_file: Path) -> None:
    assert set(report) == FIELDS and report["format"] == FORMAT
    assert report["argv"] == ["topomark", *argv]
    assert report["topomark"]["version"] and report["python"]["version"] == sys.version and report["platform"]
    assert [entry["json"] for entry in report["inputs"]] == [json.loads(world_file.read_text())]
    assert report["run"]["algorithm"] == "basic"
    assert report["run"]["world"] == world_to_json(resolve_world(str(world_file)))
    assert "unavailable" not in json.dumps(report)


def test_a_disagreement_of_topomarks_own_checks_writes_a_report(capsys, reports, world_file):
    argv = ["explore", str(world_file), "--check-mode", "both", "--quiet"]
    with pytest.MonkeyPatch.context() as mp:
        seed_disagreement(mp)
        code = main(argv)
    err = capsys.readouterr().err
    assert code == 3 and "internal fault" in err and "not in your input" in err and "CITATION.cff" in err
    path = named_report(err)
    assert path.parent == reports and path.is_file() and path.name.startswith("topomark-fault-")
    report = json.loads(path.read_text())
    assert_complete(report, argv, world_file)
    check = report["failure"]["check"]
    assert check["name"] == "incremental and full I-1/I-2 agree" and "disagree" in check["message"]
    assert report["failure"]["type"] == "topomark.spec.errors.TopomarkFault"
    assert "Traceback" in report["failure"]["traceback"] and "check_state" in report["failure"]["traceback"]
    trace = report["run"]["trace"]
    full = the_trace(world_file)
    records = trace["records"]
    assert records[0]["event"] == "header" and records[-1]["event"] == "iteration"
    assert records == full[:len(records)] and len(records) < len(full)  # the trace up to the fault, not past it
    assert trace["made"] == len(records) and trace["cut"] is False


def test_under_json_the_error_names_the_report(capsys, reports, world_file):
    with pytest.MonkeyPatch.context() as mp:
        seed_disagreement(mp)
        code = main(["explore", str(world_file), "--check-mode", "both", "--json"])
    out, err = capsys.readouterr()
    error = json.loads(out)
    assert code == 3 and error["exit"] == 3 and error["error"].startswith("internal fault")
    assert Path(error["report"]).is_absolute() and Path(error["report"]).parent == reports
    assert json.loads(Path(error["report"]).read_text())["failure"]["check"] is not None
    assert Path(error["report"]).name in err


def test_the_report_is_written_in_a_subprocess_too(tmp_path, world_file):
    """The command as a user runs it: a process of its own, the report in the current directory by default."""
    env = {k: v for k, v in os.environ.items() if k not in ("TOPOMARK_FAULT_DIR", "TOPOMARK_DEBUG")}
    here = tmp_path / "here"
    here.mkdir()
    code = f"import sys\n{SEED_DISAGREEMENT}\nfrom topomark.reference.cli.main import main\nsys.exit(main(sys.argv[1:]))"
    argv = ["explore", str(world_file), "--check-mode", "both", "--quiet"]
    proc = subprocess.run([sys.executable, "-c", code, *argv], cwd=here, env={**env, "PYTHONPATH": str(ROOT)},
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 3 and "Traceback" not in proc.stderr, proc.stderr
    shown = shown_report(proc.stderr)
    assert shown.startswith("./topomark-fault-") and len(proc.stderr.strip().splitlines()) == 2
    written = list(here.glob("topomark-fault-*.json"))
    assert [p.name for p in written] == [Path(shown).name]
    report = json.loads(written[0].read_text())
    assert_complete(report, argv, world_file)
    assert report["topomark"]["location"] == str(ROOT) and report["cwd"] == str(here)


def test_an_unexpected_exception_is_reported_with_its_traceback(capsys, reports, world_file):
    with pytest.MonkeyPatch.context() as mp:
        seed_exception(mp)
        code = main(["explore", str(world_file), "--quiet"])
    err = capsys.readouterr().err
    assert code == 3 and "unexpected ZeroDivisionError: seeded division by zero" in err and "Traceback" not in err
    report = json.loads(named_report(err).read_text())
    failure = report["failure"]
    assert failure["type"] == "builtins.ZeroDivisionError" and failure["check"] is None
    assert "ZeroDivisionError: seeded division by zero" in failure["traceback"]
    assert report["run"]["trace"]["records"][0]["event"] == "header"


def test_a_generated_world_is_in_the_report_though_no_file_names_it(capsys, reports):
    with pytest.MonkeyPatch.context() as mp:
        seed_disagreement(mp)
        assert main(["explore", WORLD, "--check-mode", "both", "--quiet"]) == 3
    report = json.loads(named_report(capsys.readouterr().err).read_text())
    assert report["inputs"] == [] and report["run"]["world"] == world_to_json(resolve_world(WORLD))


def test_a_check_failure_behind_a_fault_is_named_with_its_violation(capsys, reports, monkeypatch):
    def step(self):
        try:
            raise CheckFailure(Violation("I-2", "vertex 7", "an open dart", "none", "seeded"))
        except CheckFailure as exc:
            raise TopomarkFault("the witness fails its re-verification") from exc

    from topomark.reference.explorers.algorithm31 import LighthouseExplorer
    monkeypatch.setattr(LighthouseExplorer, "step", step)
    assert main(["explore", "cycle:n=5", "--quiet"]) == 3
    check = json.loads(named_report(capsys.readouterr().err).read_text())["failure"]["check"]
    assert check == {"name": "I-2", "message": "I-2 violated at vertex 7: expected an open dart, found none (seeded)",
                     "where": "vertex 7", "expected": "an open dart", "found": "none", "detail": "seeded"}


def test_a_long_run_keeps_the_last_records_and_says_it_cut(capsys, reports, world_file, monkeypatch):
    """The trace is capped (FLIGHT_RECORDS, 10,000): here at 5, to see the cut on a small world."""
    monkeypatch.setattr(explore_module, "FlightRecorder", lambda world, name: FlightRecorder(world, name, limit=5))
    seed_disagreement(monkeypatch)
    assert main(["explore", str(world_file), "--check-mode", "both", "--quiet"]) == 3
    trace = json.loads(named_report(capsys.readouterr().err).read_text())["run"]["trace"]
    full = the_trace(world_file)
    assert trace["cut"] is True and len(trace["records"]) == 5 and trace["made"] > 5
    assert trace["records"] == full[trace["made"] - 5:trace["made"]] and "last 5 of the" in trace["note"]


def test_old_iteration_records_keep_their_counts_not_their_hypotheses():
    from topomark.spec.world import World
    flight = FlightRecorder(World({"a": ("b",), "b": ("a",)}), "basic", limit=10, full_iterations=2)
    made = [{"event": "iteration", "iteration": i, "hypotheses": [{"dart": [i, 0]}] * i} for i in range(4)]
    for record in made:
        flight.emit(record)
    kept = flight.to_json()["trace"]
    assert [r.get("hypotheses_left_out") for r in kept["records"]] == [0, 1, None, None]
    assert kept["records"][2:] == made[2:] and all("hypotheses" in r for r in made)  # the caller's stay whole
    assert "hypotheses_left_out" in kept["note"]


def test_an_unwritable_place_falls_back_to_the_temporary_directory(capsys, tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    temp = tmp_path / "temp"
    temp.mkdir()
    monkeypatch.setenv("TOPOMARK_FAULT_DIR", str(blocker / "reports"))  # under a file: no one can write there
    monkeypatch.setattr(tempfile, "tempdir", str(temp))
    seed_disagreement(monkeypatch)
    assert main(["explore", WORLD, "--check-mode", "both", "--quiet"]) == 3
    path = named_report(capsys.readouterr().err)
    assert path.parent == temp and json.loads(path.read_text())["format"] == FORMAT


def test_no_place_to_write_still_exits_3_and_says_why(capsys, tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    monkeypatch.setenv("TOPOMARK_FAULT_DIR", str(blocker / "reports"))
    monkeypatch.setattr(tempfile, "tempdir", str(blocker / "temp"))
    seed_disagreement(monkeypatch)
    assert main(["explore", WORLD, "--check-mode", "both", "--json"]) == 3
    out, err = capsys.readouterr()
    error = json.loads(out)
    assert error["exit"] == 3 and error["report"] is None and str(blocker / "reports") in error["report_not_written"]
    assert "No report could be written" in err and str(blocker / "temp") in err and "Traceback" not in err
    assert "the command line and the input that caused it" in err


def test_a_report_that_cannot_be_made_still_exits_3(capsys, reports, monkeypatch):
    monkeypatch.setattr(fault_report, "build_report", lambda argv, exc: 1 / 0)
    seed_exception(monkeypatch)
    assert main(["explore", WORLD, "--quiet"]) == 3
    err = capsys.readouterr().err
    assert "No report could be written (the report could not be made: ZeroDivisionError" in err
    assert not list(reports.iterdir())


def test_ctrl_c_while_the_report_is_written_still_reports_the_fault(capsys, reports, monkeypatch):
    def interrupted(argv, exc):
        raise KeyboardInterrupt
    monkeypatch.setattr(fault_report, "write_report", interrupted)
    seed_exception(monkeypatch)
    assert main(["explore", WORLD, "--quiet"]) == 3
    err = capsys.readouterr().err
    assert "internal fault: unexpected ZeroDivisionError" in err and "interrupted while it was being written" in err


def test_a_part_that_cannot_be_gathered_says_why_and_the_rest_is_written(reports, monkeypatch):
    import platform

    def broken():
        raise OSError("no uname here")
    monkeypatch.setattr(platform, "platform", broken)
    path, why = write_report(["explore"], RuntimeError("boom"))
    report = json.loads(Path(path).read_text())
    assert why == "" and report["platform"] == {"unavailable": "OSError: no uname here"}
    assert report["failure"]["message"] == "boom" and report["run"] is None


def test_two_faults_in_one_second_make_two_reports(reports):
    now = datetime.datetime(2026, 1, 5, 14, 15, 2)
    first, _ = write_report(["explore"], RuntimeError("one"), now)
    second, _ = write_report(["explore"], RuntimeError("two"), now)
    assert [first.name, second.name] == ["topomark-fault-20260105-141502.json", "topomark-fault-20260105-141502-2.json"]
    assert json.loads(first.read_text())["failure"]["message"] == "one"


def test_the_inputs_are_world_files_inlined_and_broken_json_as_text(tmp_path, world_file):
    broken, script = tmp_path / "broken.json", tmp_path / "client.py"
    broken.write_text('{"format": "topomark/world@1", "rotation": {')
    script.write_text("print('hello')\n")
    trace = tmp_path / "t.jsonl"
    trace.write_text('{"event": "header"}\n')
    report = build_report(["check-map", str(world_file), f"--map={broken}", str(script), str(trace), "x" * 5000],
                          RuntimeError("boom"))
    assert report["inputs"] == [{"path": str(world_file), "json": json.loads(world_file.read_text())},
                                {"path": str(broken), "text": broken.read_text(), "note": "not JSON"}]


@pytest.mark.parametrize("argv, code", [
    (["explore", "cycle:n=5", "--quiet"], 0),
    (["iso", "{a}", "{b}"], 1),
    (["explore", "no-such-generator"], 2),
    (["explore", "cycle:n=5", "--check-mode", "sideways"], 2),
])
def test_exits_0_1_and_2_write_no_report(capsys, reports, tmp_path, argv, code):
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    a.write_text(dumps_world(resolve_world("cycle:n=5")))
    b.write_text(dumps_world(resolve_world("cycle:n=6")))
    assert main([arg.format(a=a, b=b) for arg in argv]) == code
    assert "report" not in capsys.readouterr().err
    assert not list(reports.iterdir()) and not list(Path.cwd().iterdir())


def test_a_check_failure_escaping_a_command_is_exit_1_and_writes_no_report(capsys, reports, monkeypatch):
    """A violated check is a verdict on what was judged (exit 1), not topomark's fault: no report."""
    from topomark.reference.cli import cmd_explore

    def judged(args):
        raise CheckFailure(Violation("I-1", "vertex 3", "a", "b"))
    monkeypatch.setattr(cmd_explore, "explore_command", judged)
    assert main(["explore", "cycle:n=5"]) == 1
    assert "check failed: I-1 violated" in capsys.readouterr().err
    assert not list(reports.iterdir()) and not list(Path.cwd().iterdir())


def test_the_api_caller_finds_the_run_on_the_exception(monkeypatch):
    seed_disagreement(monkeypatch)
    world = resolve_world(WORLD)
    with pytest.raises(TopomarkFault) as caught:
        explore(world, "basic", check_mode="both")
    run = run_of(caught.value)
    assert caught.value.check == "incremental and full I-1/I-2 agree" and run is not None
    assert run["world"] == world_to_json(world) and run["trace"]["records"][0]["event"] == "header"

"""The exit code is the verdict's, however stdout and stderr are attached: closed before the start, closed by the
reader, unable to encode what topomark prints (reference/cli/pipes.py).  Failing to print never changes the
exit code, and never writes a fault report (exit 3 is for topomark's own faults).

Each command line runs in a fresh process (``python -m topomark``) under bash, as a user's shell would run it,
once plainly and once per attachment; the plain run's exit code is the one every other run must give."""

from __future__ import annotations

import io
import json
import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.cli.pipes import ClosedPipeSafe, closed_pipe_safe
from topomark.reference.oracle import conformance

ROOT = Path(__file__).resolve().parents[1]
CLIENT = [sys.executable, str(ROOT / "reference" / "oracle" / "examples" / "client.py")]

ATTACHED = {  # name: (shell redirection after the command, environment)
    "stdout closed": (">&-", {}),
    "stderr closed": ("2>&-", {}),
    "both closed": (">&- 2>&-", {}),
    "stdout a pipe closed early": ("| true; exit ${PIPESTATUS[0]}", {}),
    "ascii stdout": ("", {"PYTHONIOENCODING": "ascii"}),
    "latin-1 stdout": ("", {"PYTHONIOENCODING": "latin-1"}),
    "C locale, no UTF-8 mode": ("", {"LC_ALL": "C", "PYTHONUTF8": "0", "PYTHONIOENCODING": ""}),
}


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, str]:
    """A world and a map of another world (check-map: exit 1), and a one-case conformance suite."""
    root = tmp_path_factory.mktemp("inputs")
    assert main(["world", "cycle:n=4", "-o", str(root / "world.json")]) == 0
    assert main(["world", "cycle:n=5", "-o", str(root / "map.json")]) == 0
    conformance.export(root / "suite", [c for c in conformance.default_cases() if c[0] == "triangle"], algorithms=())
    return {"world": str(root / "world.json"), "map": str(root / "map.json"), "suite": str(root / "suite")}


COMMANDS = {  # name: (command line, with {world}/{map}/{suite}; its exit code)
    "explore passes": ("explore cycle:n=4", 0),
    "check-map of a wrong map fails": ("check-map {world} {map}", 1),
    "bad input": ("explore no-such-generator:n=4", 2),
    "claims (prints non-ASCII)": ("claims", 0),
    "algorithms (prints non-ASCII)": ("algorithms", 0),
    "conformance run passes": ("conformance run {suite} -k triangle {json} -- {client}", 0),
}


def _run(command: str, files: dict[str, str], as_json: bool, cwd: Path, redirect: str = "",
         env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    line = command.format(**files, client=shlex.join(CLIENT), json="--json" if as_json else "")
    if as_json and "{json}" not in command:
        line += " --json"
    shell = f"{shlex.quote(sys.executable)} -m topomark {line} {redirect}"
    environment = {**os.environ, "PYTHONPATH": str(ROOT), **(env or {})}
    return subprocess.run(["bash", "-c", shell], capture_output=True, timeout=300, cwd=cwd, env=environment)


@pytest.mark.slow
@pytest.mark.parametrize("as_json", [False, True], ids=["text", "json"])
@pytest.mark.parametrize("command", COMMANDS)
def test_the_exit_code_does_not_depend_on_the_streams(command, as_json, files, tmp_path):
    line, code = COMMANDS[command]
    plain = _run(line, files, as_json, tmp_path)
    assert plain.returncode == code, plain.stderr.decode()
    for name, (redirect, env) in ATTACHED.items():
        done = _run(line, files, as_json, tmp_path, redirect, env)
        assert done.returncode == code, (name, done.stderr.decode(errors="replace"))
        assert not list(tmp_path.glob("topomark-fault-*")), name  # no fault report for a print failure
        if "stderr closed" == name and as_json:  # stdout is still the one JSON object, no message in it
            data = json.loads(done.stdout)
            assert code != 2 or data["exit"] == 2, data
        if env:  # every character reached stdout, escaped where the encoding has none for it
            done.stdout.decode(env.get("PYTHONIOENCODING") or "ascii")
            if any(ord(c) > 0xFF for c in plain.stdout.decode()):
                assert b"\\u" in done.stdout, name


def test_an_unencodable_character_is_escaped_not_a_fault(capsys, monkeypatch):
    """``claims`` prints § and —; a stdout that has no such characters gets backslash escapes, exit 0."""
    raw = io.BytesIO()
    monkeypatch.setattr(sys, "stdout", io.TextIOWrapper(raw, encoding="ascii"))
    assert main(["claims"]) == 0
    sys.stdout.flush()
    text = raw.getvalue().decode("ascii")
    assert "\\xa7" in text and "\\u2014" in text


@pytest.mark.parametrize("error", [BrokenPipeError(32, "Broken pipe"), OSError(28, "No space left on device"),
                                   ValueError("I/O operation on closed file")])
def test_a_failed_write_drops_the_output_and_says_why_once(error):
    heard: list[str] = []

    class Failing(io.StringIO):
        def write(self, s):
            raise error

    out = ClosedPipeSafe(Failing(), on_error=heard.append)
    assert out.write("verdict\n") == 8 and out.broken and out.write("more") == 4
    out.flush()
    assert len(heard) == (0 if isinstance(error, BrokenPipeError) else 1)  # a gone reader is no news


def test_a_stream_closed_at_the_start_is_a_null_stream(monkeypatch):
    """Python sets ``sys.stdout`` to None when descriptor 1 was closed; a command still runs to its verdict
    and ``--json`` output goes nowhere (and never to stderr, nor stderr's messages to stdout)."""
    err = io.StringIO()
    monkeypatch.setattr(sys, "stdout", None)
    monkeypatch.setattr(sys, "stderr", err)
    with closed_pipe_safe():
        assert not sys.stdout.isatty()
        print("gone")
        print("kept", file=sys.stderr)
    assert sys.stdout is None and err.getvalue() == "kept\n"
    assert main(["explore", "no-such-generator:n=4", "--json"]) == 2
    assert "no-such-generator" in err.getvalue()

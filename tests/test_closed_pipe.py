"""A verdict's exit code survives a closed pipe: ``topomark … | head -1`` under ``pipefail`` sees 1 for a failure
and 0 for a success, wherever in the output the reader stops (reference/cli/pipes.py)."""

from __future__ import annotations

import io
import subprocess
import sys
from pathlib import Path

import pytest

from topomark.reference.cli.main import main

ROOT = Path(__file__).resolve().parents[1]
WRONG = str(Path(__file__).resolve().parent / "clients" / "wrong_client.py")
FAILS = ["explore", "cycle:n=6", "--lighthouse", "undirected-vertex", "--seed", "2"]  # outcome failed, exit 1
PASSES = ["explore", "cycle:n=6"]  # correct, exit 0


class ClosesAfter(io.StringIO):
    """A reader that takes ``limit`` characters, then closes its end of the pipe."""

    def __init__(self, limit: int):
        super().__init__()
        self.limit = limit

    def write(self, text: str) -> int:
        if self.tell() + len(text) > self.limit:
            super().write(text[:max(0, self.limit - self.tell())])
            raise BrokenPipeError(32, "Broken pipe")
        return super().write(text)


def _full_output(argv: list[str], capsys) -> str:
    main(argv)
    return capsys.readouterr().out


@pytest.mark.parametrize("argv, code", [(FAILS, 1), (PASSES, 0), ([*FAILS, "--json"], 1), ([*PASSES, "--json"], 0)])
def test_the_pipe_closed_at_every_point_of_the_output(argv, code, capsys, monkeypatch):
    full = _full_output(argv, capsys)
    assert len(full) > 200
    for limit in sorted({*range(0, len(full), max(1, len(full) // 40)), len(full) - 1}):
        monkeypatch.setattr(sys, "stdout", ClosesAfter(limit))
        assert main(argv) == code, limit
    monkeypatch.undo()


@pytest.mark.parametrize("argv, code", [(FAILS, 1), (PASSES, 0)])
def test_head_sees_the_verdict_in_a_real_pipe(argv, code):
    """A real process whose reader has gone before the first line (``true`` reads nothing); Python's own flush at
    exit must not fail (it would exit 120) and the verdict must not turn into 0."""
    shell = f"{sys.executable} -m topomark.reference.cli.main {' '.join(argv)} | true; echo ${{PIPESTATUS[0]}}"
    done = subprocess.run(["bash", "-c", shell], capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert done.stdout.strip() == str(code), done.stderr


@pytest.mark.slow
def test_conformance_run_piped_to_head_exits_1_for_a_failing_client(default_suite):
    """``conformance run … | head -1; echo ${PIPESTATUS[0]}`` prints 1 for a failing client; so does a reader that
    has gone before the first line."""
    suite = default_suite
    for reader in ("head -1 > /dev/null", "true"):
        shell = (f"{sys.executable} -m topomark.reference.cli.main conformance run {suite} -k cycle -- "
                 f"{sys.executable} {WRONG} bad-exit | {reader}; echo ${{PIPESTATUS[0]}}")
        done = subprocess.run(["bash", "-c", shell], capture_output=True, text=True, timeout=600, cwd=ROOT)
        assert done.stdout.strip() == "1", (reader, done.stderr)

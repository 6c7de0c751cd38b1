"""Misbehaving external programs (issue 15): whatever they fork, print or ignore, topomark ends the session.

Each hostile program is a small Python script that records the pids of
everything it starts in a file; after the verdict, none of them may still
run.  The commands are run as subprocesses of the test (the real CLI, its
signal handling and its exit code), with small timeouts.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.oracle.peer import TAIL_CHARS, TAIL_LINES, _Tail
from topomark.reference.oracle.protocol import ProtocolError, decode

SLACK = 12.0  # seconds beyond --timeout a verdict may take (a hang guard, not a speed claim)

PRELUDE = """\
import os, signal, sys, time
PIDS = sys.argv[1]

def record(pid):
    with open(PIDS, "a") as fh:
        fh.write(f"{pid}\\n")

def sleeper(setsid=False, ignore_term=False):
    pid = os.fork()
    if pid == 0:
        if setsid:
            os.setsid()
        if ignore_term:
            signal.signal(signal.SIGTERM, signal.SIG_IGN)
        record(os.getpid())
        time.sleep(1000)
        os._exit(0)
    return pid

record(os.getpid())
"""

HOSTILE = {
    # forks a sleeper (which keeps the pipes) and exits at once
    "fork-exit": "sleeper()\nos._exit(0)\n",
    # forks a sleeper and stays, silent
    "fork-silent": "sleeper()\ntime.sleep(1000)\n",
    # a child leaves the session with setsid(), forks a grandchild and exits: the grandchild is an orphan
    "setsid-orphan": textwrap.dedent("""\
        if os.fork() == 0:
            os.setsid()
            sleeper()
            os._exit(0)
        time.sleep(1000)
        """),
    # the same, and the program itself exits too
    "setsid-exit": textwrap.dedent("""\
        if os.fork() == 0:
            os.setsid()
            sleeper()
            os._exit(0)
        time.sleep(0.3)
        os._exit(0)
        """),
    # ignores SIGTERM, and so does its child
    "ignore-term": "signal.signal(signal.SIGTERM, signal.SIG_IGN)\nsleeper(ignore_term=True)\ntime.sleep(1000)\n",
    # 100,000 levels of nesting on one protocol line
    "deep": 'sys.stdout.write("[" * 100000 + "]" * 100000 + "\\n"); sys.stdout.flush(); time.sleep(1000)\n',
    # a 5,000-digit integer
    "bigint": ('sys.stdout.write(\'{"type": "move", "motion": \' + "9" * 5000 + "}\\n"); sys.stdout.flush()\n'
               "time.sleep(1000)\n"),
    # a line longer than MAX_LINE, never ended
    "long-line": 'sys.stdout.write("x" * 6_000_000); sys.stdout.flush(); time.sleep(1000)\n',
    # megabytes of stderr without a newline (size in MB from argv[2])
    "stderr-flood": textwrap.dedent("""\
        chunk = b"e" * (1 << 20)
        for _ in range(int(sys.argv[2])):
            os.write(2, chunk)
        time.sleep(1000)
        """),
}


def hostile(tmp_path: Path, kind: str, *extra: str) -> tuple[list[str], Path]:
    script = tmp_path / f"{kind}.py"
    script.write_text(PRELUDE + HOSTILE[kind])
    pids = tmp_path / f"{kind}.pids"
    return [sys.executable, str(script), str(pids), *extra], pids


def topomark(*args: str, timeout: float) -> tuple[subprocess.CompletedProcess, float]:
    started = time.monotonic()
    proc = subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", *args], capture_output=True, text=True,
                          timeout=timeout + 60)  # a hang guard far beyond the assertion below
    return proc, time.monotonic() - started


def alive(pid: int) -> bool:
    """True if ``pid`` runs (a zombie, or a pid reused by a process not started by the test, does not count)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            stat = fh.read()
        with open(f"/proc/{pid}/cmdline", "rb") as fh:
            cmdline = fh.read()
    except OSError:
        return False
    return stat[stat.rindex(b")") + 2:][:1] not in (b"Z", b"X") and b".py" in cmdline


def recorded(pids: Path, at_least: int) -> list[int]:
    found = [int(x) for x in pids.read_text().split()] if pids.exists() else []
    assert len(found) >= at_least, f"the hostile program recorded {found}"
    return found


def assert_all_gone(pids: list[int]) -> None:
    deadline = time.monotonic() + 3.0
    while any(alive(p) for p in pids) and time.monotonic() < deadline:
        time.sleep(0.05)
    left = [p for p in pids if alive(p)]
    for p in left:  # do not leave them behind even when the test fails
        os.kill(p, signal.SIGKILL)
    assert not left, f"still running after the verdict: {left}"


def assert_verdict(proc: subprocess.CompletedProcess, reasons: tuple[str, ...]) -> None:
    assert proc.returncode == 1, (proc.returncode, proc.stdout[-2000:], proc.stderr[-2000:])
    assert any(f"FAIL [{r}]" in proc.stdout for r in reasons), proc.stdout[-2000:]
    assert len(proc.stdout) < 10_000 and len(proc.stderr) < 10_000
    assert "Traceback" not in proc.stderr


# -- processes that outlive the verdict ----------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("kind, children", [("fork-exit", 2), ("fork-silent", 2), ("setsid-orphan", 2),
                                            ("setsid-exit", 2), ("ignore-term", 2)])
def test_run_external_kills_everything_the_program_started(tmp_path, kind, children):
    cmd, pids = hostile(tmp_path, kind)
    proc, took = topomark("run-external", "cycle:n=4", "--message-timeout", "2", "--timeout", "3", "--", *cmd,
                          timeout=3)
    assert_verdict(proc, ("timeout", "crash"))
    assert took < 3 + SLACK
    assert_all_gone(recorded(pids, children))


@pytest.mark.slow
def test_drive_kills_everything_the_provider_started(tmp_path):
    cmd, pids = hostile(tmp_path, "setsid-orphan")
    proc, took = topomark("drive", "--message-timeout", "2", "--timeout", "3", "--", *cmd, timeout=3)
    assert_verdict(proc, ("timeout", "crash"))
    assert took < 3 + SLACK
    assert_all_gone(recorded(pids, 2))


@pytest.mark.slow
@pytest.mark.parametrize("kind, reason", [("fork-exit", ("timeout", "crash")), ("deep", ("garbage",))])
def test_conformance_run_fails_the_case_and_kills_everything(default_suite, tmp_path, kind, reason):
    cmd, pids = hostile(tmp_path, kind)
    proc, took = topomark("conformance", "run", str(default_suite), "-k", "triangle", "--message-timeout", "2",
                          "--timeout", "3", "--", *cmd, timeout=3)
    assert proc.returncode == 1, (proc.stdout, proc.stderr)
    assert "0/" in proc.stdout and any(r in proc.stdout for r in reason), proc.stdout
    assert took < 3 + SLACK
    assert_all_gone(recorded(pids, 1))


# -- what the program prints ---------------------------------------------------------------
@pytest.mark.parametrize("kind, words", [("deep", "nested deeper than 64 levels"),
                                         ("bigint", "(5000 digits) is out of range"),
                                         ("long-line", "longer than 4000000 bytes")])
def test_unparseable_lines_are_garbage_with_a_bounded_message(tmp_path, kind, words):
    cmd, pids = hostile(tmp_path, kind)
    proc, took = topomark("run-external", "cycle:n=4", "--message-timeout", "5", "--timeout", "10", "--", *cmd,
                          timeout=10)
    assert_verdict(proc, ("garbage",))
    assert words in proc.stdout
    assert_all_gone(recorded(pids, 1))


def test_deep_nesting_and_huge_integers_decode_as_garbage():
    for line in ("[" * 100_000 + "]" * 100_000, '{"type": "move", "motion": ' + "9" * 5000 + "}"):
        with pytest.raises(ProtocolError) as exc:
            decode(line)
        assert exc.value.kind == "garbage" and len(str(exc.value)) < 1000


@pytest.mark.slow
def test_a_stderr_flood_without_newlines_costs_bounded_memory_and_gets_a_verdict(tmp_path):
    cmd, pids = hostile(tmp_path, "stderr-flood", "200")
    code = ("import resource, subprocess, sys\n"
            "p = subprocess.run(sys.argv[1:], capture_output=True, text=True)\n"
            "sys.stdout.write(p.stdout)\n"
            "print('RSS', resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
            "sys.exit(p.returncode)\n")
    started = time.monotonic()
    proc = subprocess.run([sys.executable, "-c", code, sys.executable, "-m", "topomark.reference.cli.main",
                           "run-external", "cycle:n=4", "--message-timeout", "5", "--timeout", "8", "--", *cmd],
                          capture_output=True, text=True, timeout=120)
    assert time.monotonic() - started < 8 + SLACK
    assert_verdict(proc, ("timeout",))
    rss_kb = int(proc.stdout.rsplit("RSS", 1)[1])
    assert rss_kb < 300_000, f"peak RSS {rss_kb} kB for 200 MB of stderr"
    assert "eeee" in proc.stdout and "bytes)" in proc.stdout  # the tail, clipped, with the line's length
    assert_all_gone(recorded(pids, 1))


def test_the_stderr_tail_is_bounded_in_lines_and_characters():
    tail = _Tail()
    tail.feed(b"first\n" + b"y" * 10_000)
    tail.feed(b"z" * 10_000 + b"\nlast")
    lines = tail.snapshot()
    assert lines[0] == "first" and lines[-1] == "last"
    assert lines[1].startswith("y" * TAIL_CHARS) and "20,000 bytes" in lines[1] and len(lines[1]) < TAIL_CHARS + 40
    tail.feed(b"".join(b"%d\n" % k for k in range(10_000)))
    assert tail.snapshot() == [str(k) for k in range(10_000 - TAIL_LINES, 10_000)]


# -- signals to topomark -----------------------------------------------------------------
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP])
def test_a_signal_to_topomark_kills_the_program_and_exits_128_plus_signum(tmp_path, signum):
    cmd, pids = hostile(tmp_path, "ignore-term")
    proc = subprocess.Popen([sys.executable, "-m", "topomark.reference.cli.main", "run-external", "cycle:n=4",
                             "--message-timeout", "100", "--timeout", "100", "--", *cmd],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 30
        while len(pids.read_text().split() if pids.exists() else []) < 2 and time.monotonic() < deadline:
            time.sleep(0.05)
        started = time.monotonic()
        proc.send_signal(signum)
        out, err = proc.communicate(timeout=SLACK)
    finally:
        proc.kill()
    assert proc.returncode == 128 + signum, (proc.returncode, err)
    assert time.monotonic() - started < SLACK
    assert err.count("\n") == 1 and signal.Signals(signum).name in err and "Traceback" not in err
    assert_all_gone(recorded(pids, 2))


# -- numeric options -----------------------------------------------------------------------
@pytest.mark.parametrize("value", ["nan", "inf", "-1", "0", "1e308", "abc", "604801"])
@pytest.mark.parametrize("command, option", [
    (["run-external", "cycle:n=4"], "--timeout"), (["run-external", "cycle:n=4"], "--message-timeout"),
    (["drive"], "--timeout"), (["drive"], "--message-timeout"),
    (["conformance", "run", "."], "--timeout"),
])
def test_a_time_limit_that_is_not_a_sane_number_of_seconds_is_bad_input(command, option, value, capsys):
    assert main([*command, option, value, "--", "true"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and option in err


@pytest.mark.parametrize("value", ["nan", "1e308", "-1"])
def test_search_timeout_is_checked_the_same_way(value, capsys):
    assert main(["search", "--marker", "none", "--max-vertices", "4", "--max-degree", "3", "--timeout", value]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--timeout must be positive" in err


@pytest.mark.parametrize("value", ["-1", str(10 ** 16), pytest.param("1" * 5000, id="5000-digits")])
@pytest.mark.parametrize("command", [["run-external", "cycle:n=4"], ["drive"]])
def test_max_traversals_out_of_range_is_bad_input(command, value, capsys):
    assert main([*command, "--max-traversals", value, "--", "true"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--max-traversals" in err


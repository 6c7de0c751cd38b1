"""Hostile input (issue 15): every command that reads a file, trace, suite or protocol line, fed garbage.

A corpus of malformed world/map texts and special paths (FIFO, ``/dev/zero``, a
directory, a missing file) goes through every file slot of every command, table
driven; malformed trace lines, conformance manifests, protocol lines, generator
arguments and option values follow; hypothesis generates malformed JSON and
protocol messages for the loaders in-process.  The assertion is always the one
of the README: exit 2 (or, for a program under test that says something
malformed, exit 1 with ``FAIL [garbage]``), one short message naming what is
wrong, no traceback, in bounded time and memory.  Exit 3 ("internal fault") on
hostile input is a bug and fails here.

How the CLI is run
------------------
Every invocation is a separate process with ``RLIMIT_AS`` = :data:`MEMORY_LIMIT`
(a memory blow-up becomes ``MemoryError`` -> exit 3 -> a failure, never a machine
hang), stdin from ``/dev/null``, its own session (killed as a group after
:data:`TIMEOUT` seconds: a hang is a failure, never a hung suite).

A fresh interpreter costs about a second here (networkx and z3 imports) and the
table has a few hundred rows, so by default each invocation is forked from a
*zygote*: a clean ``python3`` (not pytest) that has imported
``topomark.reference.cli.main`` once and, per request, forks a child that sets the
limit, redirects 0/1/2, and runs ``sys.exit(main(argv))`` -- exactly what the
``topomark`` entry point does after its imports, including normal interpreter
shutdown.  ``TOPOMARK_HOSTILE_FRESH=1`` runs every case in a fresh
``python3 -m topomark.reference.cli.main`` via ``subprocess`` + ``preexec_fn``
instead (slower, same assertions); :func:`test_zygote_agrees_with_a_fresh_interpreter`
checks a few rows both ways on every run.

A normal ``topomark explore`` of the 5x5 default world peaks at ~50 MB resident
and runs under ``RLIMIT_AS`` = 256 MiB (measured); 2 GiB leaves ample headroom
for the z3/numpy reservations while a read of ``/dev/zero`` or a 9-million
vertex world still fails fast.
"""

from __future__ import annotations

import json
import os
import resource
import select
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from topomark.spec.errors import CheckFailure, InvalidInput

REPO = Path(__file__).resolve().parent.parent
CLIENT = REPO / "reference" / "oracle" / "examples" / "client.py"
PROVIDER = REPO / "reference" / "oracle" / "examples" / "provider.py"

MEMORY_LIMIT = 2 << 30   # RLIMIT_AS per invocation (see the module docstring)
TIMEOUT = 60.0           # hang guard per invocation (generous: a healthy case takes well under 2 s)
PROMPT = 30.0            # hang guard where the brief says "promptly" (generator arguments)
MAX_STDERR_CHARS = 2000  # "one message": a 10 MB value must not be echoed
MAX_STDERR_LINES = 3
MAX_STDOUT_CHARS = 64_000

# ---------------------------------------------------------------------------------------------------------
# Running the CLI: zygote (default) or fresh interpreter, both with RLIMIT_AS and a hang guard
# ---------------------------------------------------------------------------------------------------------

_ZYGOTE_SRC = r"""
import json, os, resource, sys
req_fd, resp_fd = int(sys.argv[1]), int(sys.argv[2])
from topomark.reference.cli.main import build_parser, main
build_parser()  # imports every command module once, before any fork
resp = os.fdopen(resp_fd, "w", buffering=1)
req = os.fdopen(req_fd, "r")
resp.write("ready\n")
for line in req:
    r = json.loads(line)
    pid = os.fork()
    if pid == 0:
        os.setsid()
        resource.setrlimit(resource.RLIMIT_AS, (r["limit"], r["limit"]))
        os.chdir(r["cwd"])
        for fd, path, flags in ((0, os.devnull, os.O_RDONLY),
                                (1, r["out"], os.O_WRONLY | os.O_CREAT | os.O_TRUNC),
                                (2, r["err"], os.O_WRONLY | os.O_CREAT | os.O_TRUNC)):
            new = os.open(path, flags, 0o600)
            os.dup2(new, fd)
            os.close(new)
        os.close(req_fd)
        os.close(resp_fd)
        sys.argv = ["topomark", *r["argv"]]
        sys.exit(main(r["argv"]))
    resp.write(f"{pid}\n")
    _, status = os.waitpid(pid, 0)
    resp.write(f"{os.waitstatus_to_exitcode(status)}\n")
"""


@dataclass
class Run:
    argv: list[str]
    code: int | None     # None: killed by the hang guard
    out: str
    err: str
    seconds: float

    @property
    def timed_out(self) -> bool:
        return self.code is None

    def describe(self) -> str:
        return (f"topomark {' '.join(_short(a) for a in self.argv)}\n  exit {self.code} after {self.seconds:.2f} s"
                f"\n  stderr: {self.err[:600]!r}\n  stdout: {self.out[:300]!r}")


def _short(arg: str) -> str:
    return arg if len(arg) <= 60 else arg[:40] + f"...({len(arg)} chars)"


def _limit_memory() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


class _Zygote:
    def __init__(self) -> None:
        req_r, self._req_w = os.pipe()
        self._resp_r, resp_w = os.pipe()
        env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
        env.pop("TOPOMARK_DEBUG", None)
        self._log = tempfile.TemporaryFile()
        self.proc = subprocess.Popen([sys.executable, "-c", _ZYGOTE_SRC, str(req_r), str(resp_w)],
                                     pass_fds=(req_r, resp_w), stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=self._log, env=env, cwd=str(REPO))
        os.close(req_r)
        os.close(resp_w)
        self._buf = b""
        if self._line(120.0) != "ready":
            self._log.seek(0)
            raise RuntimeError("the zygote could not import topomark: "
                               + self._log.read().decode(errors="replace")[-2000:])

    def _line(self, timeout: float) -> str | None:
        end = time.monotonic() + timeout
        while b"\n" not in self._buf:
            left = end - time.monotonic()
            if left <= 0 or not select.select([self._resp_r], [], [], left)[0]:
                return None
            chunk = os.read(self._resp_r, 4096)
            if not chunk:
                raise RuntimeError("the zygote died")
            self._buf += chunk
        line, self._buf = self._buf.split(b"\n", 1)
        return line.decode()

    def run(self, argv: list[str], cwd: Path, out: Path, err: Path, timeout: float) -> int | None:
        req = {"argv": argv, "cwd": str(cwd), "out": str(out), "err": str(err), "limit": MEMORY_LIMIT}
        os.write(self._req_w, (json.dumps(req) + "\n").encode())
        pid = int(self._line(30.0))
        status = self._line(timeout)
        if status is None:  # hang guard: kill the whole session of the child
            try:
                os.killpg(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self._line(30.0)
            return None
        return int(status)

    def close(self) -> None:
        os.close(self._req_w)
        try:
            self.proc.wait(10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        os.close(self._resp_r)
        self._log.close()


def _run_fresh(argv: list[str], cwd: Path, out: Path, err: Path, timeout: float) -> int | None:
    env = {k: v for k, v in os.environ.items() if k != "TOPOMARK_DEBUG"}
    with open(out, "wb") as fo, open(err, "wb") as fe:
        proc = subprocess.Popen([sys.executable, "-m", "topomark.reference.cli.main", *argv], cwd=cwd,
                                stdin=subprocess.DEVNULL, stdout=fo, stderr=fe, env=env,
                                preexec_fn=_limit_memory, start_new_session=True)
        try:
            return proc.wait(timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            return None


def _source_stamp() -> float:
    """The newest modification time of topomark's own sources (the zygote is restarted when it changes)."""
    return max(p.stat().st_mtime for d in ("spec", "reference", "proofs") for p in (REPO / d).rglob("*.py"))


class Cli:
    """Runs ``topomark ARGV`` under the memory limit and the hang guard."""

    def __init__(self, workdir: Path, fresh: bool) -> None:
        self.workdir = workdir
        self.fresh = fresh
        self._zygote: _Zygote | None = None
        self._stamp = 0.0
        self._n = 0

    def _warm(self) -> _Zygote:
        stamp = _source_stamp()
        if self._zygote is None or stamp != self._stamp:  # never run stale code: re-import after an edit
            if self._zygote is not None:
                self._zygote.close()
            self._zygote, self._stamp = _Zygote(), stamp
        return self._zygote

    def _warm_or_none(self) -> "_Zygote | None":
        """The zygote, or None (run a fresh interpreter) if it cannot start: the zygote is a speed-up only."""
        try:
            return self._warm()
        except RuntimeError:
            self._zygote = None
            return None

    def __call__(self, *argv: str, timeout: float = TIMEOUT, cwd: Path | None = None, fresh: bool | None = None) -> Run:
        self._n += 1
        out, err = self.workdir / f"run{self._n}.out", self.workdir / f"run{self._n}.err"
        use_fresh = self.fresh if fresh is None else fresh
        zygote = None if use_fresh else self._warm_or_none()
        start = time.monotonic()
        if zygote is None:
            code = _run_fresh(list(argv), cwd or self.workdir, out, err, timeout)
        else:
            try:
                code = zygote.run(list(argv), cwd or self.workdir, out, err, timeout)
            except RuntimeError:  # the zygote itself died (not the command): run this one afresh
                self._zygote = None
                code = _run_fresh(list(argv), cwd or self.workdir, out, err, timeout)
        seconds = time.monotonic() - start
        text = [p.read_bytes()[:1 << 20].decode("utf-8", "replace") if p.exists() else "" for p in (out, err)]
        for p in (out, err):
            p.unlink(missing_ok=True)
        return Run(list(argv), code, text[0], text[1], seconds)

    def close(self) -> None:
        if self._zygote is not None:
            self._zygote.close()


# ---------------------------------------------------------------------------------------------------------
# The corpus
# ---------------------------------------------------------------------------------------------------------

def _unreadable_blocks_reads() -> bool:
    """Whether ``chmod 000`` stops this process from reading a file (it does not for root or CAP_DAC_OVERRIDE)."""
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "x"
        p.write_text("{}")
        p.chmod(0)
        try:
            p.read_bytes()
        except PermissionError:
            return True
        return False


# The world texts are built from a small valid world (a 4x4 lattice with a hole, plus a start so that
# `distinguish` accepts it); WORLD_TEXTS maps a name to a function of that world's compact JSON object.
def _with(obj: dict, **changes) -> bytes:
    return json.dumps({**obj, **changes}).encode()


def _first(obj: dict) -> tuple[str, str]:
    v = next(iter(obj["rotation"]))
    return v, obj["rotation"][v][0]


def _replace_neighbours(obj: dict, value) -> bytes:
    rot = {v: list(ns) for v, ns in obj["rotation"].items()}
    v = next(iter(rot))
    rot[v] = [value] + rot[v][1:]
    return _with(obj, rotation=rot)


DEEP = 100_000
HUGE_INT = b"7" * 5000       # over Python's 4300-digit int-string limit
BIG_INT = b"7" * 4000        # under it: json.loads accepts it
TEN_MB = 10 * 1024 * 1024

WORLD_TEXTS = {
    "empty": lambda o: b"",
    "null": lambda o: b"null",
    "array": lambda o: b"[]",
    "string": lambda o: b'"topomark/world@1"',
    "truncated": lambda o: json.dumps(o).encode()[: len(json.dumps(o)) // 2],
    "deep-open": lambda o: b"[" * DEEP,
    "deep-closed": lambda o: b"[" * DEEP + b"]" * DEEP,
    "deep-objects": lambda o: b'{"a":' * DEEP + b"1" + b"}" * DEEP,
    "deep-in-key": lambda o: b'{"format":"topomark/world@1","rotation":' + b"[" * DEEP,
    "deep-in-key-closed": lambda o: (b'{"format":"topomark/world@1","rotation":{"a":' + b"[" * DEEP + b"]" * DEEP
                                     + b"}}"),
    "huge-int-count": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": 0}]).replace(
        b'"count": 0', b'"count": ' + HUGE_INT),
    "big-int-count": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": 0}]).replace(
        b'"count": 0', b'"count": ' + BIG_INT),
    "nan-count": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": 0}]).replace(
        b'"count": 0', b'"count": NaN'),
    "infinity-count": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": 0}]).replace(
        b'"count": 0', b'"count": Infinity'),
    "non-utf8": lambda o: json.dumps(o).encode().replace(b'"rotation"', b'"rot\xff\xfeation"', 1),
    "non-utf8-name": lambda o: _replace_neighbours(o, "PLACEHOLDER").replace(b"PLACEHOLDER", b"\xc3\x28\xa0"),
    "bom": lambda o: b"\xef\xbb\xbf" + json.dumps(o).encode(),
    "duplicate-keys": lambda o: json.dumps(o).encode()[:-1] + b', "rotation": {}}',
    "huge-string-format": lambda o: _with(o, format="x" * TEN_MB),
    "huge-string-vertex": lambda o: _replace_neighbours(o, "v" * TEN_MB),
    "control-chars": lambda o: json.dumps(o).encode().replace(b"topomark/world@1", b"topomark/\x00\x07\x1b[2J@1"),
    "wrong-types-everywhere": lambda o: json.dumps({"format": 1, "rotation": [["a", "b"]], "markers": {"at": 0},
                                                   "start": [0, 1]}).encode(),
    "wrong-type-neighbour": lambda o: _replace_neighbours(o, 17),
}

# Each field of a valid world with a value of the wrong type: run in-process only (cheap), through the
# world loader; the CLI table above carries two of them.
WRONG_TYPE_FIELDS = {
    "format-int": lambda o: _with(o, format=1),
    "format-null": lambda o: _with(o, format=None),
    "rotation-list": lambda o: _with(o, rotation=list(o["rotation"].items())),
    "rotation-entry-string": lambda o: _with(o, rotation={v: ",".join(ns) for v, ns in o["rotation"].items()}),
    "rotation-entry-null": lambda o: _with(o, rotation={v: None for v in o["rotation"]}),
    "neighbour-int": lambda o: _replace_neighbours(o, 3),
    "neighbour-list": lambda o: _replace_neighbours(o, ["x"]),
    "neighbour-bool": lambda o: _replace_neighbours(o, True),
    "markers-object": lambda o: _with(o, markers={"kind": "vertex"}),
    "marker-string": lambda o: _with(o, markers=["vertex"]),
    "marker-kind-int": lambda o: _with(o, markers=[{"kind": 1, "at": _first(o)[0]}]),
    "marker-at-int": lambda o: _with(o, markers=[{"kind": "vertex", "at": 0}]),
    "marker-count-string": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": "1"}]),
    "marker-count-bool": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": True}]),
    "marker-count-float": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0], "count": 1.5}]),
    "marker-points-to-list": lambda o: _with(o, markers=[{"kind": "vertex", "at": _first(o)[0],
                                                          "points_to": [_first(o)[1]]}]),
    "marker-between-string": lambda o: _with(o, markers=[{"kind": "edge", "between": "ab"}]),
    "marker-between-ints": lambda o: _with(o, markers=[{"kind": "edge", "between": [1, 2]}]),
    "marker-head-int": lambda o: _with(o, markers=[{"kind": "edge", "between": list(_first(o)), "head": 0}]),
    "start-list": lambda o: _with(o, start=list(_first(o))),
    "start-null": lambda o: _with(o, start=None),
    "start-at-int": lambda o: _with(o, start={"at": 0, "facing": _first(o)[1]}),
    "start-facing-list": lambda o: _with(o, start={"at": _first(o)[0], "facing": [_first(o)[1]]}),
}

SPECIAL_PATHS = ["fifo", "dev-zero", "directory", "missing"]
if _unreadable_blocks_reads():
    SPECIAL_PATHS.append("unreadable")
# else: running as root (or with CAP_DAC_OVERRIDE), where chmod 000 does not stop a read, so an
# "unreadable" file is an ordinary readable one and the case would test nothing; it is left out.

WORLD_CORPUS = list(WORLD_TEXTS) + SPECIAL_PATHS

# Trace-specific lines: each replaces one line of a valid trace (the line of the named event).
# Malformed ones must give exit 2; "claims" are well-formed lines claiming something false (exit 1 or 2).
TRACE_LINES = {
    "move-huge-step": ("move", b'{"event":"move","motion":1,"perception":"[3,A,A]","purpose":"new","step":'
                       + HUGE_INT + b"}"),
    "move-nan-motion": ("move", b'{"event":"move","motion":NaN,"perception":"[3,A,A]","purpose":"new","step":1}'),
    "move-infinity-step": ("move", b'{"event":"move","motion":0,"perception":"[3,A,A]","purpose":"new",'
                           b'"step":-Infinity}'),
    "move-float-motion": ("move", b'{"event":"move","motion":1.0,"perception":"[3,A,A]","purpose":"new","step":1}'),
    "move-bool-motion": ("move", b'{"event":"move","motion":true,"perception":"[3,A,A]","purpose":"new","step":1}'),
    "move-deep-perception": ("move", b'{"event":"move","motion":0,"perception":' + b"[" * DEEP + b"]" * DEEP
                             + b',"purpose":"new","step":1}'),
    "move-huge-perception": ("move", b'{"event":"move","motion":0,"perception":"[' + b"9" * TEN_MB
                             + b',A,A]","purpose":"new","step":1}'),
    "second-header": ("move", b'{"algorithm":"basic","event":"header","format":"topomark/trace@1","m":18,"n":14,'
                      b'"policies":{"edge":"nearest","hypothesis":"fifo","path":"shortest"}}'),
    "unknown-event": ("move", b'{"event":"teleport","to":"elsewhere"}'),
    "header-huge-n": ("header", b'{"algorithm":"basic","event":"header","format":"topomark/trace@1","m":18,"n":'
                      + HUGE_INT + b',"policies":{"edge":"nearest","hypothesis":"fifo","path":"shortest"}}'),
    "iteration-deep-hypotheses": ("iteration", b'{"augmentation":"loop","by_marker":false,"edge":[0,0],'
                                  b'"event":"iteration","hypotheses":' + b"[" * DEEP + b"]" * DEEP
                                  + b',"iteration":1,"joined":[[0,0],[1,0]],"signature":"[3,A,A]"}'),
    "end-nan-cost": ("end", b'{"cost":NaN,"event":"end","verified":true,"violation":null}'),
}
TRACE_CLAIMS = {
    "move-huge-motion": ("move", b'{"event":"move","motion":999999999999999999,"perception":"[3,A,A]",'
                         b'"purpose":"new","step":1}'),
    "move-negative-motion": ("move", b'{"event":"move","motion":-1,"perception":"[3,A,A]","purpose":"new","step":1}'),
    "move-bad-perception": ("move", b'{"event":"move","motion":0,"perception":"[999999999999999999,A,A]",'
                            b'"purpose":"new","step":1}'),
    "move-garbage-perception": ("move", b'{"event":"move","motion":0,"perception":"]]]","purpose":"new","step":1}'),
    "end-huge-cost": ("end", b'{"cost":999999999999999999,"event":"end","verified":true,"violation":null}'),
    "iteration-far-dart": ("iteration", b'{"augmentation":"loop","by_marker":false,"edge":[999999999999999999,0],'
                           b'"event":"iteration","hypotheses":[],"iteration":1,'
                           b'"joined":[[999999999999999999,0],[-5,999999999999999999]],"signature":"[3,A,A]"}'),
    "iteration-bad-hypothesis": ("iteration", b'{"augmentation":"loop","by_marker":false,"edge":[0,0],'
                                 b'"event":"iteration","hypotheses":[{"dart":"x","motions":[1e400],"expected":7,'
                                 b'"outcome":"case 9","perceived":null}],"iteration":1,"joined":[[0,0],[1,0]],'
                                 b'"signature":"[3,A,A]"}'),
}

# Conformance manifests: each world corpus item as manifest.json, plus valid manifests whose first case points
# somewhere hostile.
MANIFEST_EDITS = {
    "case-world-dev-zero": lambda m, d: _edit_case(m, world="/dev/zero"),
    "case-world-fifo": lambda m, d: _edit_case(m, world=_make_fifo(d / "worlds" / "fifo.json")),
    "case-world-escapes": lambda m, d: _edit_case(m, world="../../../../../../../../etc/hostname"),
    "case-trace-dev-zero": lambda m, d: _edit_ref(m, trace="/dev/zero"),
    "case-map-fifo": lambda m, d: _edit_ref(m, map=_make_fifo(d / "reference" / "fifo.map.json")),
    "case-n-huge": lambda m, d: _edit_case(m, n=10 ** 30),
    "case-name-deep": lambda m, d: _edit_case(m, name=[[[[[[[[[[[]]]]]]]]]]]),
    "cases-object": lambda m, d: {**m, "cases": {"a": 1}},
    "cases-of-strings": lambda m, d: {**m, "cases": ["figure-3.6-wheel-a"]},
    "version-int": lambda m, d: {**m, "version": 10 ** 30},
    "policies-list": lambda m, d: {**m, "policies": ["default"]},
    "reference-list": lambda m, d: _edit_case(m, reference=["default"]),
}
MANIFEST_CORPUS = WORLD_CORPUS + list(MANIFEST_EDITS)


def _make_fifo(path: Path) -> str:
    os.mkfifo(path)
    return str(path.relative_to(path.parent.parent))


def _edit_case(manifest: dict, **changes) -> dict:
    cases = [dict(c) for c in manifest["cases"]]
    cases[0].update(changes)
    return {**manifest, "cases": cases}


def _edit_ref(manifest: dict, **changes) -> dict:
    cases = [dict(c) for c in manifest["cases"]]
    ref = {k: dict(v) for k, v in cases[0]["reference"].items()}
    ref["default"].update(changes)
    cases[0]["reference"] = ref
    return {**manifest, "cases": cases}


# Protocol lines a program under test prints instead of a message.
PROTOCOL_LINES = {
    "deep-object": b'{"type":"move","motion":' + b"[" * DEEP + b"]" * DEEP + b"}",
    "deep-array": b"[" * DEEP,
    "huge-int": b'{"type":"move","motion":' + HUGE_INT + b"}",
    "big-int": b'{"type":"move","motion":' + BIG_INT + b"}",
    "nan": b'{"type":"move","motion":NaN}',
    "infinity": b'{"type":"drop","direction":Infinity}',
    "non-utf8": b'{"type":"drop","direction":0,"\xff\xfe":1}',
    "non-utf8-type": b'{"type":"dr\xc3\x28op","direction":0}',
    "five-mb-line": b'{"type":"move","motion":1,"pad":"' + b"x" * (5 * 1024 * 1024) + b'"}',
    "five-mb-garbage": b"x" * (5 * 1024 * 1024),
    "unknown-type": b'{"type":"teleport","to":"v0"}',
    "missing-field": b'{"type":"move"}',
    "wrong-field-type": b'{"type":"move","motion":"1"}',
    "bool-field": b'{"type":"drop","direction":true}',
    "float-field": b'{"type":"move","motion":1.0}',
    "type-not-string": b'{"type":["move"],"motion":1}',
    "json-array": b'["move",1]',
    "json-string": b'"move"',
    "empty-line": b"",
    "control-chars": b'{"type":"move\x00\x1b[2J","motion":1}',
}
PROTOCOL_PROGRAM = r"""
import sys, time
{read_first}
sys.stdout.buffer.write(open(sys.argv[1], "rb").read() + b"\n")
sys.stdout.buffer.flush()
time.sleep(40)
"""


# ---------------------------------------------------------------------------------------------------------
# Fixtures
# ---------------------------------------------------------------------------------------------------------

@dataclass
class Corpus:
    root: Path
    valid: Path            # a valid world with a start
    valid_obj: dict
    trace: Path            # its valid trace
    map: Path              # its map
    suite: Path            # an exported conformance suite
    protocol_dir: Path

    def world_item(self, name: str) -> Path:
        """The path of world corpus item ``name``."""
        special = {"dev-zero": Path("/dev/zero")}
        return special.get(name, self.root / "worlds" / f"{name}.json")


@pytest.fixture(scope="module")
def cli(tmp_path_factory):
    runner = Cli(tmp_path_factory.mktemp("runs"), fresh=bool(os.environ.get("TOPOMARK_HOSTILE_FRESH")))
    yield runner
    runner.close()


@pytest.fixture(scope="module")
def corpus(tmp_path_factory, cli, default_suite) -> Corpus:
    root = tmp_path_factory.mktemp("hostile")
    gen = cli("world", "lattice-hole:rows=4,cols=4", "-o", str(root / "gen.json"))
    assert gen.code == 0, gen.describe()
    obj = json.loads((root / "gen.json").read_text())
    v, w = _first(obj)
    obj["start"] = {"at": v, "facing": w}
    valid = root / "valid.json"
    valid.write_text(json.dumps(obj))
    explored = cli("explore", str(valid), "--trace", str(root / "valid.trace.jsonl"), "--map",
                   str(root / "valid.map.json"), "--quiet")
    assert explored.code == 0, explored.describe()
    suite = default_suite  # read only: the tests that damage a suite damage a copy (_hostile_suite)

    worlds = root / "worlds"
    worlds.mkdir()
    for name, make in WORLD_TEXTS.items():
        (worlds / f"{name}.json").write_bytes(make(obj))
    os.mkfifo(worlds / "fifo.json")
    (worlds / "directory.json").mkdir()
    unreadable = worlds / "unreadable.json"
    unreadable.write_text(json.dumps(obj))
    unreadable.chmod(0)
    protocol_dir = root / "protocol"
    protocol_dir.mkdir()
    for name, line in PROTOCOL_LINES.items():
        (protocol_dir / f"{name}.line").write_bytes(line)
    (protocol_dir / "explorer.py").write_text(PROTOCOL_PROGRAM.format(read_first="sys.stdin.readline()"))
    (protocol_dir / "provider.py").write_text(PROTOCOL_PROGRAM.format(read_first=""))
    return Corpus(root, valid, obj, root / "valid.trace.jsonl", root / "valid.map.json", suite, protocol_dir)


def _assert_bad_input(run: Run, names: list[str]) -> None:
    """Exit 2, one short message on stderr naming one of ``names``, no traceback, within the hang guard."""
    assert not run.timed_out, f"hung (killed by the hang guard):\n{run.describe()}"
    assert run.code == 2, f"expected exit 2 (bad input):\n{run.describe()}"
    assert "Traceback" not in run.err and "Traceback" not in run.out, run.describe()
    err = run.err.strip()
    assert err, f"exit 2 without a message:\n{run.describe()}"
    assert len(err) <= MAX_STDERR_CHARS and len(err.splitlines()) <= MAX_STDERR_LINES, \
        f"not one short message ({len(err)} chars, {len(err.splitlines())} lines):\n{run.describe()}"
    assert len(run.out) <= MAX_STDOUT_CHARS, run.describe()
    assert any(n in err for n in names), f"the message names none of {names}:\n{run.describe()}"


def _names_of(path: Path) -> list[str]:
    return [str(path)] if str(path).startswith("/dev/") else [path.name]


# ---------------------------------------------------------------------------------------------------------
# 1-2. World/map corpus x every command slot that reads a world or map file
# ---------------------------------------------------------------------------------------------------------

def _slot_argv(slot: str, bad: Path, c: Corpus) -> list[str]:
    b, v = str(bad), str(c.valid)
    return {
        "explore": ["explore", b, "--quiet"],
        "world --show": ["world", "--show", b],
        "iso A": ["iso", b, v],
        "iso B": ["iso", v, b],
        "check-map WORLD": ["check-map", b, str(c.map)],
        "check-map MAP": ["check-map", v, b],
        "run-external WORLD": ["run-external", b, "--timeout", "20", "--message-timeout", "5", "--",
                               sys.executable, str(CLIENT)],
        "drive --check": ["drive", "--check", b, "--timeout", "20", "--message-timeout", "5", "--",
                          sys.executable, str(PROVIDER), v],
        "replay WORLD": ["replay", b, str(c.trace)],
        "replay TRACE": ["replay", v, b],
        "distinguish A": ["distinguish", b, v],
        "distinguish B": ["distinguish", v, b],
    }[slot]


WORLD_SLOTS = ["explore", "world --show", "iso A", "iso B", "check-map WORLD", "check-map MAP",
               "run-external WORLD", "drive --check", "replay WORLD", "replay TRACE", "distinguish A",
               "distinguish B"]


@pytest.mark.slow
@pytest.mark.parametrize("item", WORLD_CORPUS)
@pytest.mark.parametrize("slot", WORLD_SLOTS)
def test_malformed_file_in_every_slot(cli, corpus, slot, item):
    bad = corpus.world_item(item)
    _assert_bad_input(cli(*_slot_argv(slot, bad, corpus)), _names_of(bad))


# ---------------------------------------------------------------------------------------------------------
# Trace lines: a valid trace with one line replaced
# ---------------------------------------------------------------------------------------------------------

def _trace_with(corpus: Corpus, name: str, event: str, line: bytes) -> Path:
    lines = corpus.trace.read_bytes().split(b"\n")
    if lines[-1] == b"":
        lines.pop()
    k = next(i for i, raw in enumerate(lines) if json.loads(raw)["event"] == event)
    if event == "end":
        k = len(lines) - 1
    lines[k] = line
    path = corpus.root / f"trace-{name}.jsonl"
    path.write_bytes(b"\n".join(lines) + b"\n")
    return path


@pytest.mark.slow
@pytest.mark.parametrize("item", list(WORLD_TEXTS))
def test_trace_line_replaced_by_corpus_item(cli, corpus, item):
    line = WORLD_TEXTS[item](corpus.valid_obj).replace(b"\n", b" ")
    path = _trace_with(corpus, f"line-{item}", "move", line)
    _assert_bad_input(cli("replay", str(corpus.valid), str(path)), [path.name])


@pytest.mark.parametrize("item", list(TRACE_LINES))
def test_malformed_trace_line(cli, corpus, item):
    event, line = TRACE_LINES[item]
    path = _trace_with(corpus, item, event, line)
    _assert_bad_input(cli("replay", str(corpus.valid), str(path)), [path.name])


@pytest.mark.parametrize("item", list(TRACE_CLAIMS))
def test_false_trace_claim_is_a_verdict_or_bad_input(cli, corpus, item):
    """Well-formed lines that claim the impossible: a divergence (exit 1) or bad input (exit 2), never a crash."""
    event, line = TRACE_CLAIMS[item]
    path = _trace_with(corpus, item, event, line)
    run = cli("replay", str(corpus.valid), str(path))
    assert not run.timed_out, run.describe()
    assert run.code in (1, 2), f"expected a verdict (1) or bad input (2):\n{run.describe()}"
    assert "Traceback" not in run.err + run.out, run.describe()
    assert len(run.err) <= MAX_STDERR_CHARS and len(run.out) <= MAX_STDOUT_CHARS, run.describe()


# ---------------------------------------------------------------------------------------------------------
# Conformance suites with a hostile manifest
# ---------------------------------------------------------------------------------------------------------

def _hostile_suite(corpus: Corpus, item: str, tag: str) -> Path:
    d = corpus.root / f"suite-{tag}-{item}"
    shutil.copytree(corpus.suite, d)
    manifest = d / "manifest.json"
    if item in MANIFEST_EDITS:
        edited = MANIFEST_EDITS[item](json.loads(manifest.read_text()), d)
        manifest.write_text(json.dumps(edited, indent=1))
        return d
    manifest.unlink()
    if item in WORLD_TEXTS:
        manifest.write_bytes(WORLD_TEXTS[item](corpus.valid_obj))
    elif item == "fifo":
        os.mkfifo(manifest)
    elif item == "dev-zero":
        manifest.symlink_to("/dev/zero")
    elif item == "directory":
        manifest.mkdir()
    elif item == "unreadable":
        manifest.write_text("{}")
        manifest.chmod(0)
    else:
        assert item == "missing"
    return d


@pytest.mark.slow
@pytest.mark.parametrize("item", MANIFEST_CORPUS)
@pytest.mark.parametrize("action", ["lint", "run"])
def test_hostile_conformance_manifest(cli, corpus, action, item):
    suite = _hostile_suite(corpus, item, action)
    if action == "lint":
        argv = ["conformance", "lint", str(suite)]
    else:
        argv = ["conformance", "run", str(suite), "-k", "wheel-a", "--timeout", "20", "--message-timeout", "5",
                "--", sys.executable, str(CLIENT)]
    _assert_bad_input(cli(*argv), ["manifest.json", suite.name, "fifo", "/dev/zero", "etc/hostname"])


# ---------------------------------------------------------------------------------------------------------
# 3. Protocol lines from a program under test (explorer role) and from a provider (drive)
# ---------------------------------------------------------------------------------------------------------

def _assert_fail(run: Run, reasons: tuple[str, ...]) -> None:
    assert not run.timed_out, f"hung (killed by the hang guard):\n{run.describe()}"
    assert run.code == 1, f"expected exit 1 (FAIL):\n{run.describe()}"
    text = run.out + run.err
    assert "Traceback" not in text, run.describe()
    assert any(f"FAIL [{r}]" in text for r in reasons), f"expected FAIL [{'|'.join(reasons)}]:\n{run.describe()}"
    assert len(run.out) <= MAX_STDERR_CHARS and len(run.err) <= MAX_STDERR_CHARS, \
        f"not a short message ({len(run.out)} + {len(run.err)} chars):\n{run.describe()}"


@pytest.mark.slow
@pytest.mark.parametrize("item", list(PROTOCOL_LINES))
def test_hostile_protocol_line_from_explorer(cli, corpus, item):
    line = corpus.protocol_dir / f"{item}.line"
    run = cli("run-external", str(corpus.valid), "--message-timeout", "5", "--timeout", "20", "--",
              sys.executable, str(corpus.protocol_dir / "explorer.py"), str(line))
    # big-int is a well-formed move to an exit that does not exist: any FAIL reason is right for it
    _assert_fail(run, ("garbage", "protocol") if item != "big-int" else ("garbage", "protocol", "limit", "motion",
                                                                          "exit"))


DRIVE_LINES = ["deep-object", "deep-array", "huge-int", "nan", "non-utf8", "five-mb-line", "json-array",
               "empty-line", "unknown-type", "missing-field"]


@pytest.mark.parametrize("item", DRIVE_LINES)
def test_hostile_protocol_line_from_provider(cli, corpus, item):
    line = corpus.protocol_dir / f"{item}.line"
    run = cli("drive", "--message-timeout", "5", "--timeout", "20", "--",
              sys.executable, str(corpus.protocol_dir / "provider.py"), str(line))
    _assert_fail(run, ("garbage", "protocol"))


# ---------------------------------------------------------------------------------------------------------
# 5. Generator arguments
# ---------------------------------------------------------------------------------------------------------

GENERATOR_ARGS = {
    "rows-4400-digits": "lattice-hole:rows=" + "9" * 4400 + ",cols=4",
    "rows-1e38": "lattice-hole:rows=1" + "0" * 38 + ",cols=4",
    "complete-hole-2**63": f"complete-hole:n={2 ** 63}",
    "rows-negative": "lattice-hole:rows=-1,cols=4",
    "rows-abc": "lattice-hole:rows=abc,cols=4",
    "rows-float": "lattice-hole:rows=4.5,cols=4",
    "rows-3000x3000": "lattice-hole:rows=3000,cols=3000",
    "cycle-1e9": "cycle:n=1000000000",
    "complete-100000": "complete:n=100000",
    "fraction-nan": "lattice-hole:rows=4,cols=4,fraction=nan",
    "fraction-1e400": "lattice-hole:rows=4,cols=4,fraction=1e400",
    "p-nan": "small-world:n=10,k=4,p=nan",
    "seed-5000-digits": "random:n=6,seed=" + "7" * 5000,
    "unknown-parameter": "cycle:n=5,bogus=1",
}


@pytest.mark.slow
@pytest.mark.parametrize("command", ["explore", "world"])
@pytest.mark.parametrize("item", list(GENERATOR_ARGS))
def test_hostile_generator_argument(cli, command, item):
    spec = GENERATOR_ARGS[item]
    argv = ["explore", spec, "--quiet"] if command == "explore" else ["world", spec]
    run = cli(*argv, timeout=PROMPT)
    name, _, params = spec.partition(":")
    keys = [p.split("=")[0] for p in params.split(",")]
    _assert_bad_input(run, [name, *keys])


# ---------------------------------------------------------------------------------------------------------
# 6. Option values
# ---------------------------------------------------------------------------------------------------------

def _option_cases() -> list[tuple[str, str, str]]:
    cases = []
    for cmd in ("run-external", "drive", "conformance run"):
        for v in ("nan", "inf", "-1", "0", "1e308", "abc"):
            cases.append((cmd, "--timeout", v))
        for v in ("nan", "-1", "inf"):
            cases.append((cmd, "--message-timeout", v))
        for v in ("-5", "abc"):
            cases.append((cmd, "--max-traversals", v))
    for cmd in ("explore", "world", "run-external"):
        cases.append((cmd, "--seed", "1e400"))
        cases.append((cmd, "--seed", "7" * 5000))
    for v in ("nan", "-1", "inf"):
        cases.append(("search", "--timeout", v))
    for v in ("1" + "0" * 30, "-1", "0"):
        cases.append(("search", "--max-degree", v))
        cases.append(("search", "--max-vertices", v))
        cases.append(("census", "--max-vertices", v))
    for v in ("0", "-1"):
        cases.append(("bench", "--graphs", v))
    cases += [("census", "--jobs", "0"), ("census", "--jobs", "-1")]
    cases += [("bench", "--jobs", v) for v in ("0", "-1", "257")]  # default (no --jobs): one per CPU
    cases.append(("census", "--jobs", "257"))
    cases.append(("bench", "--sizes", "-5"))
    return cases


def _option_argv(cmd: str, option: str, value: str, c: Corpus, out: Path) -> list[str]:
    opt = [f"{option}={value}"]  # "=" so that a value like -1 is not read as an option
    v = str(c.valid)
    if cmd == "run-external":
        world = ["lattice-hole:rows=4,cols=4"] if option == "--seed" else [v]
        return ["run-external", *world, *opt, "--", sys.executable, str(CLIENT)]
    if cmd == "drive":
        return ["drive", "--check", v, *opt, "--", sys.executable, str(PROVIDER), v]
    if cmd == "conformance run":
        return ["conformance", "run", str(c.suite), "-k", "wheel-a", *opt, "--", sys.executable, str(CLIENT)]
    if cmd == "explore":
        return ["explore", "lattice-hole:rows=4,cols=4", "--quiet", *opt]
    if cmd == "world":
        return ["world", "lattice-hole:rows=4,cols=4", *opt]
    if cmd == "search":
        base = {"--marker": "directional-vertex", "--max-vertices": "2", "--max-degree": "2", "--timeout": "20"}
        base[option] = value
        return ["search", *[f"{k}={x}" for k, x in base.items()]]
    if cmd == "census":
        base = {"--marker": "directional-vertex", "--max-vertices": "2", "--max-degree": "2"}
        base[option] = value
        return ["census", *[f"{k}={x}" for k, x in base.items()]]
    assert cmd == "bench"
    base = {"--sizes": "4", "--graphs": "1", "--out": str(out)}
    base[option] = value
    return ["bench", "lattice", "--no-plots", "--quiet", *[f"{k}={x}" for k, x in base.items()]]


@pytest.mark.slow
@pytest.mark.parametrize("cmd,option,value", _option_cases(),
                         ids=[f"{c}-{o}={v if len(v) < 12 else v[:6] + '...'}" for c, o, v in _option_cases()])
def test_hostile_option_value(cli, corpus, tmp_path, cmd, option, value):
    run = cli(*_option_argv(cmd, option, value, corpus, tmp_path / "bench-out"))
    _assert_bad_input(run, [option])


# ---------------------------------------------------------------------------------------------------------
# In-process: the loaders on the whole text corpus (cheap) and on hypothesis-generated garbage
# ---------------------------------------------------------------------------------------------------------

def _assert_refused(exc: BaseException, source: str) -> None:
    text = str(exc)
    assert source in text, f"the message does not name {source!r}: {text[:300]!r}"
    assert len(text) <= MAX_STDERR_CHARS, f"a {len(text)}-character message: {text[:300]!r}..."


@pytest.mark.parametrize("item", list(WORLD_TEXTS) + [f"wrong-type:{k}" for k in WRONG_TYPE_FIELDS])
def test_world_loader_refuses_corpus_item(corpus, tmp_path, item):
    from topomark.spec.worldfile import load_world
    make = WRONG_TYPE_FIELDS[item.split(":", 1)[1]] if item.startswith("wrong-type:") else WORLD_TEXTS[item]
    path = tmp_path / "bad-world.json"
    path.write_bytes(make(corpus.valid_obj))
    with pytest.raises(InvalidInput) as info:
        load_world(path)
    _assert_refused(info.value, "bad-world.json")


def _mutations(base: bytes):
    """Byte flips, truncations, deletions, and insertions of brackets, huge digit runs and odd tokens."""
    op = st.one_of(
        st.tuples(st.just("flip"), st.floats(0, 1), st.integers(0, 255)),
        st.tuples(st.just("truncate"), st.floats(0, 1), st.just(0)),
        st.tuples(st.just("delete"), st.floats(0, 1), st.integers(1, 20)),
        st.tuples(st.just("brackets"), st.floats(0, 1), st.sampled_from([10, 100, 1000, 5000, DEEP])),
        st.tuples(st.just("objects"), st.floats(0, 1), st.sampled_from([10, 100, 1000, DEEP])),
        st.tuples(st.just("digits"), st.floats(0, 1), st.sampled_from([18, 19, 100, 4300, 4301, 20_000])),
        st.tuples(st.just("token"), st.floats(0, 1), st.integers(0, 14)),
    )
    tokens = [b"NaN", b"Infinity", b"-Infinity", b"null", b"true", b'""', b",", b":", b"\x00", b"\xff",
              b"1e400", b"-0", b"[]", b"{}", b"\xef\xbb\xbf"]

    def apply(ops) -> bytes:
        data = bytearray(base)
        for kind, where, arg in ops:
            pos = int(where * len(data))
            if kind == "flip" and data:
                data[min(pos, len(data) - 1)] = arg
            elif kind == "truncate":
                del data[pos:]
            elif kind == "delete":
                del data[pos:pos + arg]
            elif kind == "brackets":
                data[pos:pos] = b"[" * arg
            elif kind == "objects":
                data[pos:pos] = b'{"a":' * arg
            elif kind == "digits":
                data[pos:pos] = b"9" * arg
            elif kind == "token":
                data[pos:pos] = tokens[arg]
        return bytes(data)

    return st.lists(op, min_size=1, max_size=4).map(apply)


_json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=20),
    lambda inner: st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=10), inner, max_size=5),
    max_leaves=30)
_json_texts = _json_values.map(lambda v: json.dumps(v).encode())  # allow_nan: floats give NaN/Infinity too

FUZZ = settings(max_examples=200, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.function_scoped_fixture])


@pytest.mark.slow
@FUZZ
@given(data=st.data())
def test_fuzz_world_loader(corpus, data):
    """loads_world (text) and load_world (bytes in a file): a World, or InvalidInput naming the source."""
    from topomark.spec.world import World
    from topomark.spec.worldfile import load_world, loads_world
    raw = data.draw(st.one_of(_json_texts, _mutations(corpus.valid.read_bytes())), label="world bytes")
    text = raw.decode("utf-8", "replace")
    try:
        assert isinstance(loads_world(text, "fuzz.json"), World)
    except InvalidInput as exc:
        _assert_refused(exc, "fuzz.json")
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "fuzz.json"
        path.write_bytes(raw)
        try:
            assert isinstance(load_world(path), World)
        except InvalidInput as exc:
            _assert_refused(exc, "fuzz.json")


@FUZZ
@given(data=st.data())
def test_fuzz_trace_parser_and_replay(corpus, data):
    """parse_trace then replay, with one line replaced: a result, InvalidInput (2) or CheckFailure (1) only."""
    from topomark.reference.replay.replay import parse_trace, replay
    from topomark.spec.worldfile import load_world
    lines = corpus.trace.read_bytes().splitlines()
    k = data.draw(st.integers(0, len(lines) - 1), label="line index")
    line = data.draw(st.one_of(_json_texts, _mutations(lines[k])), label="line")
    lines[k] = line.replace(b"\n", b" ")
    text = b"\n".join(lines).decode("utf-8", "replace") + "\n"
    try:
        records = parse_trace(text, "fuzz.jsonl")
    except InvalidInput as exc:
        _assert_refused(exc, "fuzz.jsonl")
        return
    try:
        replay(load_world(corpus.valid), records, "fuzz.jsonl")
    except (InvalidInput, CheckFailure) as exc:
        assert len(str(exc)) <= MAX_STDERR_CHARS, str(exc)[:300]


_VALID_MESSAGES = [b'{"type":"move","motion":1}', b'{"type":"drop","direction":0}',
                   b'{"type":"snapshot","S":{},"U":[]}', b'{"type":"map","world":{"format":"topomark/world@1"}}',
                   b'{"type":"signature","value":"[2,A,A]","step":3}', b'{"type":"error","message":"x"}',
                   b'{"type":"bye"}']


@FUZZ
@given(line=st.one_of(_json_texts, st.sampled_from(_VALID_MESSAGES).flatmap(_mutations),
                      st.text(max_size=200)))
def test_fuzz_protocol_decode(line):
    """decode: a message dict, or ProtocolError; nothing else, and a short message."""
    from topomark.reference.oracle.protocol import ProtocolError, decode
    text = line.decode("utf-8", "replace") if isinstance(line, bytes) else line
    try:
        assert isinstance(decode(text), dict)
    except ProtocolError as exc:
        assert exc.kind in ("garbage", "protocol"), exc.kind
        assert len(str(exc)) <= MAX_STDERR_CHARS, str(exc)[:300]


@pytest.mark.parametrize("item", list(PROTOCOL_LINES))
def test_protocol_decode_refuses_corpus_line(item):
    from topomark.reference.oracle.protocol import ProtocolError, decode
    text = PROTOCOL_LINES[item].decode("utf-8", "replace")
    if item == "big-int":  # well-formed (a move to a far exit): decode may accept it; the game refuses it
        try:
            decode(text)
        except ProtocolError:
            pass
        return
    with pytest.raises(ProtocolError) as info:
        decode(text)
    assert len(str(info.value)) <= MAX_STDERR_CHARS


# ---------------------------------------------------------------------------------------------------------
# The harness itself: zygote and fresh interpreter agree; a normal run fits the limits
# ---------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("item", ["valid", "deep-open", "fifo", "huge-string-format"])
def test_zygote_agrees_with_a_fresh_interpreter(cli, corpus, item):
    path = corpus.valid if item == "valid" else corpus.world_item(item)
    zygote = cli("world", "--show", str(path), fresh=False)
    fresh = cli("world", "--show", str(path), fresh=True)
    assert (zygote.code, zygote.out, zygote.err) == (fresh.code, fresh.out, fresh.err), \
        f"zygote:\n{zygote.describe()}\nfresh:\n{fresh.describe()}"
    if item == "valid":
        assert zygote.code == 0, zygote.describe()


def test_normal_runs_fit_the_memory_limit_and_the_hang_guard(cli, corpus):
    """The limits are not what fails the table: ordinary runs of each command pass under them."""
    for argv in (["explore", "lattice-hole:rows=4,cols=4", "--quiet"],
                 ["run-external", str(corpus.valid), "--", sys.executable, str(CLIENT)],
                 ["drive", "--check", str(corpus.valid), "--", sys.executable, str(PROVIDER), str(corpus.valid)],
                 ["replay", str(corpus.valid), str(corpus.trace)],
                 ["conformance", "run", str(corpus.suite), "-k", "wheel-a", "--", sys.executable, str(CLIENT)]):
        run = cli(*argv)
        assert run.code == 0, run.describe()

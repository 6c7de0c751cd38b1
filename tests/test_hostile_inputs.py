"""Hostile input files and values (issue 15 items 1, 2, 9, 10, 12): exit 2 with one message, never a traceback.

Every case runs the real CLI in a subprocess (a hang guard of 60 s, never a
speed assertion) and checks: exit code 2, one line on stderr starting with
``topomark: error:``, no traceback, and the words that name the file, field
or limit.  A hypothesis test feeds mutated world files to the loader.
"""

from __future__ import annotations

import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.reference.oracle import conformance
from topomark.reference.worlds import generators as g
from topomark.spec.errors import InvalidInput, InvalidWorld
from topomark.spec.signature import Signature
from topomark.spec.world import MAX_DEGREE, MAX_EDGES, MAX_VERTICES, World, check_size
from topomark.spec.worldfile import dumps_world, load_world, loads_world

ROOT = Path(__file__).resolve().parents[1]
CLIENT = [sys.executable, str(ROOT / "reference" / "oracle" / "examples" / "client.py")]
TIMEOUT = 60  # a hang guard only
DIGITS_4400 = "9" * 4400
VALID = dumps_world(g.cycle(4))


def cli(*argv, cwd=None, prelude: str = "") -> subprocess.CompletedProcess:
    code = f"import sys\n{prelude}\nfrom topomark.reference.cli.main import main\nsys.exit(main(sys.argv[1:]))"
    return subprocess.run([sys.executable, "-c", code, *map(str, argv)], cwd=cwd, capture_output=True,
                          text=True, timeout=TIMEOUT)


def assert_refused(proc: subprocess.CompletedProcess, *words: str, code: int = 2) -> None:
    err = proc.stderr
    assert proc.returncode == code, (proc.returncode, err[-2000:])
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err[-2000:]
    prefix = "topomark: error: " if code == 2 else "topomark: "
    assert lines[0].startswith(prefix), lines[0]
    for w in words:
        assert w in lines[0], (w, lines[0][:500])


# -- world files (items 1, 2, 9) ----------------------------------------------------------
def _with_count(count_text: str) -> str:
    return ('{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": ["a"]}, '
            f'"markers": [{{"kind": "vertex", "at": "a", "count": {count_text}}}]}}')


def _write(text: str | bytes):
    def make(tmp: Path) -> Path:
        path = tmp / "w.json"
        (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)
        return path
    return make


def _fifo(tmp: Path) -> Path:
    os.mkfifo(tmp / "fifo.json")
    return tmp / "fifo.json"


def _too_many_vertices(tmp: Path) -> Path:
    names = [f"v{k}" for k in range(MAX_VERTICES + 1)]
    rot = {v: [names[k - 1], names[(k + 1) % len(names)]] for k, v in enumerate(names)}
    return _write(json.dumps({"format": "topomark/world@1", "rotation": rot}))(tmp)


WORLD_FILES = {
    "deep nesting": (_write('{"format": "topomark/world@1", "rotation": ' + "[" * 100_000 + "]" * 100_000 + "}"),
                     ["w.json", "nested deeper than 64"]),
    "huge integer": (_write(_with_count("9" * 5000)), ["w.json", "5000 digits", "out of range"]),
    "NaN": (_write(_with_count("NaN")), ["w.json", "NaN"]),
    "Infinity": (_write(_with_count("-Infinity")), ["w.json", "Infinity"]),
    "non-UTF-8": (_write(VALID.encode()[:20] + b"\xff\xfe" + VALID.encode()[20:]), ["w.json", "UTF-8"]),
    "directory": (lambda tmp: tmp, ["not a regular file"]),
    "FIFO": (_fifo, ["fifo.json", "not a regular file"]),
    "/dev/zero": (lambda tmp: Path("/dev/zero"), ["/dev/zero", "not a regular file"]),
    "too many vertices": (_too_many_vertices, ["w.json", f"{MAX_VERTICES + 1:,} vertices", "MAX_VERTICES"]),
}


@pytest.mark.slow
@pytest.mark.parametrize("case", WORLD_FILES)
def test_a_hostile_world_file_is_refused(case, tmp_path):
    make, words = WORLD_FILES[case]
    path = make(tmp_path)
    assert_refused(cli("world", "--show", path, cwd=tmp_path), *words)


@pytest.mark.parametrize("case", ["FIFO", "/dev/zero", "deep nesting"])
def test_explore_refuses_a_hostile_world_file_too(case, tmp_path):
    make, words = WORLD_FILES[case]
    assert_refused(cli("explore", make(tmp_path), cwd=tmp_path), *words)


# -- generator arguments (item 2) ---------------------------------------------------------
GENERATOR_ARGS = {
    "4,400 digits": (f"lattice-hole:rows={DIGITS_4400}", ["rows", "at most 18 digits"]),
    "10^38": ("lattice-hole:rows=100000000000000000000000000000000000000", ["rows", "out of range"]),
    "2^63": ("complete-hole:n=9223372036854775808", ["parameter n", "out of range"]),
    "3000x3000 lattice": ("lattice-hole:rows=3000,cols=3000", ["9,000,000 vertices", "MAX_VERTICES"]),
    "huge lattice within digits": ("lattice:rows=100000000000000000,cols=2", ["MAX_VERTICES"]),
    "K_2000": ("complete:n=2000", ["1,999,000 edges", "MAX_EDGES"]),
    "K_n before removal": ("complete-hole:n=922337203685477580", ["MAX_VERTICES"]),
    "dense random": ("random:n=100000,fraction=0.5", ["MAX_EDGES"]),
    "large small-world": ("small-world:n=300000,k=4,p=0.1", ["300,000 vertices", "MAX_VERTICES"]),
    "wide small-world": ("small-world:n=200000,k=6,p=0.1", ["1,200,000 edges", "MAX_EDGES"]),
    "long cycle": ("cycle:n=250001", ["MAX_VERTICES"]),
    "long chain": ("chain:n=250001", ["MAX_VERTICES"]),
    "superscript digit": ("cycle:n=²", ["parameter n must be int", "'²'"]),
    "Arabic-Indic digit": ("cycle:n=٣", ["parameter n must be int"]),
    "underscore": ("lattice:rows=1_0,cols=2", ["parameter rows must be int"]),
    "nan": ("random:n=10,fraction=nan", ["fraction must be float"]),
    "infinite float": ("random:n=10,fraction=1e999", ["fraction must be a finite number"]),
    "huge seed": (f"random:n=10,fraction=0.5,seed={DIGITS_4400}", ["seed", "at most 18 digits"]),
}


@pytest.mark.slow
@pytest.mark.parametrize("case", GENERATOR_ARGS)
def test_a_hostile_generator_argument_is_refused(case, tmp_path):
    spec, words = GENERATOR_ARGS[case]
    assert_refused(cli("world", spec, cwd=tmp_path), *words)


@pytest.mark.parametrize("spec", [f"lattice-hole:rows={DIGITS_4400}", f"x{DIGITS_4400}", f"{DIGITS_4400}.json",
                                  "lattice-hole:rows=3000,cols=3000"])
def test_explore_never_treats_an_impossible_path_as_a_fault(spec, tmp_path):
    proc = cli("explore", spec, cwd=tmp_path)
    assert_refused(proc)
    assert len(proc.stderr) < 6000  # the 4,400-digit value is not echoed in full... except as a file name


def test_the_size_limits_are_inclusive():
    check_size(MAX_VERTICES, MAX_EDGES, "a world at the limits")
    for n, m, word in ((MAX_VERTICES + 1, 1, "MAX_VERTICES"), (2, MAX_EDGES + 1, "MAX_EDGES")):
        with pytest.raises(InvalidWorld, match=word):
            check_size(n, m, "x")
    assert MAX_DEGREE == MAX_VERTICES - 1


def test_generators_refuse_before_building():
    """Sizes far beyond memory are refused at once: nothing proportional to them is built."""
    for build in (lambda: g.lattice(10**17, 10**17), lambda: g.lattice_hole(10**9, 3),
                  lambda: g.complete_hole(10**12), lambda: g.random_graph(10**12, 0.5),
                  lambda: g.small_world(10**15, 4, 0.0), lambda: g.generate("cycle", n=10**17)):
        with pytest.raises(InvalidInput, match="MAX_"):
            build()
    for build in (lambda: g.lattice(10**5000, 2), lambda: g.complete_hole(7, 0.1, -10**5000)):
        with pytest.raises(InvalidInput, match="out of range"):
            build()


def test_random_graph_draws_from_the_same_pairs_without_listing_them():
    """The lazy pair sequence equals the list it replaces, so random_graph's worlds are unchanged."""
    rng = random.Random(7)
    for n in range(2, 30):
        pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
        taken = set(rng.sample(pairs, rng.randrange(len(pairs) + 1)))
        lazy = g.OtherPairs(n, taken)
        listed = [p for p in pairs if p not in taken]
        assert len(lazy) == len(listed) and list(lazy) == listed
        k = rng.randrange(len(listed) + 1)
        assert random.Random(n).sample(lazy, k) == random.Random(n).sample(listed, k)
    big = g.OtherPairs(MAX_VERTICES, [])
    for k in (0, 1, len(big) // 3, len(big) - 1):
        i, j = big[k]
        assert 0 <= i < j < MAX_VERTICES and big._rank(i, j) == k


# -- signatures (item 10) -----------------------------------------------------------------
BAD_SIGNATURES = {
    "superscript degree": ("[²,A,A]", "not of the form"),
    "fullwidth degree": ("[３,A,A]", "not of the form"),
    "huge degree": ("[100000000,A,A]", "degree must be 1..249999"),
    "degree above MAX_DEGREE": (f"[{MAX_DEGREE + 1},A,A]", "MAX_DEGREE"),
    "degree of 5000 digits": ("[" + "9" * 5000 + ",A,A]", "5000 digits"),
    "non-ASCII direction": ("[3,V-٣,A]", "cannot read vertex part"),
    "huge marker count": ("[3,V" + "9" * 30 + ",A]", "30 digits"),
    "huge edge count": ("[3,A,E" + "9" * 30 + "-1]", "30 digits"),
    "huge edge exit": ("[3,A,E-" + "9" * 5000 + "]", "5000 digits"),
    "non-ASCII edge exit": ("[3,A,E-١]", "cannot read edge part"),
    "not a string": (3, "must be a string"),
}


@pytest.mark.parametrize("case", BAD_SIGNATURES)
def test_signature_parse_refuses(case):
    text, words = BAD_SIGNATURES[case]
    with pytest.raises(InvalidInput, match=words) as info:
        Signature.parse(text)
    assert len(str(info.value)) < 300  # a megabyte-long value is not echoed back


def test_the_largest_degree_still_parses():
    assert Signature.parse(f"[{MAX_DEGREE},V-{MAX_DEGREE - 1},A]").degree == MAX_DEGREE


@pytest.mark.parametrize("signature, words", [("[100000000,A,A]", "MAX_DEGREE"), ("[²,A,A]", "not of the form")])
def test_replay_refuses_a_hostile_signature(signature, words, tmp_path):
    (tmp_path / "c4.json").write_text(VALID)
    assert cli("explore", "c4.json", "--trace", "t.jsonl", cwd=tmp_path).returncode == 0
    lines = (tmp_path / "t.jsonl").read_text().splitlines()
    k = next(i for i, line in enumerate(lines) if '"perception"' in line)
    record = json.loads(lines[k])
    record["perception"] = signature
    lines[k] = json.dumps(record)
    (tmp_path / "bad.jsonl").write_text("\n".join(lines) + "\n")
    assert_refused(cli("replay", "c4.json", "bad.jsonl", cwd=tmp_path), "bad.jsonl", words)


# -- tampered conformance suites (item 12) ------------------------------------------------
@pytest.fixture(scope="module")
def small_suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("hostile-suite") / "suite"
    conformance.export(root, conformance.default_cases()[2:4], algorithms=())  # the triangle and C4: cheap
    return root


def _manifest_edit(change):
    def tamper(root: Path) -> None:
        path = root / "manifest.json"
        manifest = json.loads(path.read_text())
        change(manifest)
        path.write_text(json.dumps(manifest))
    return tamper


def _ref(manifest: dict) -> dict:
    return manifest["cases"][0]["reference"]["default"]


def _bytes(rel: str, data: bytes):
    return lambda root: (root / rel).write_bytes(data)


def _replace_by_fifo(rel: str):
    def tamper(root: Path) -> None:
        (root / rel).unlink()
        os.mkfifo(root / rel)
    return tamper


TAMPERED = {
    "cost 0": (_manifest_edit(lambda m: _ref(m).update(cost=0)), ["manifest.json",
                                                                    "reference.default.cost", "got 0"]),
    "cost missing": (_manifest_edit(lambda m: _ref(m).pop("cost")), ["reference.default.cost", "got null"]),
    "cost 'abc'": (_manifest_edit(lambda m: _ref(m).update(cost="abc")), ["reference.default.cost", '"abc"']),
    "cost true": (_manifest_edit(lambda m: _ref(m).update(cost=True)), ["reference.default.cost"]),
    "reference entry 'x'": (_manifest_edit(lambda m: m["cases"][0]["reference"].update(default="x")),
                            ["cases[0] (triangle).reference.default must be an object"]),
    "reference not an object": (_manifest_edit(lambda m: m["cases"][0].update(reference=[])),
                                ["reference must have one entry per named policy"]),
    "case not an object": (_manifest_edit(lambda m: m["cases"].insert(0, 5)), ["cases[0] must be an object"]),
    "n 'abc'": (_manifest_edit(lambda m: m["cases"][0].update(n="abc")), ["cases[0] (triangle).n"]),
    "world path escapes": (_manifest_edit(lambda m: m["cases"][0].update(world="../../etc/passwd")),
                           ["cases[0] (triangle).world", "relative path inside the suite"]),
    "absolute world path": (_manifest_edit(lambda m: m["cases"][0].update(world="/dev/zero")),
                            ["cases[0] (triangle).world"]),
    "trace path not a string": (_manifest_edit(lambda m: _ref(m).update(trace=7)), ["reference.default.trace"]),
    "version not a string": (_manifest_edit(lambda m: m.update(version=1)), ["version must be a version string"]),
    "no policies": (_manifest_edit(lambda m: m.update(policies={})), ["policies must be a non-empty object"]),
    "manifest not an object": (lambda root: (root / "manifest.json").write_text("[]"), ["must be a JSON object"]),
    "manifest non-UTF-8": (_bytes("manifest.json", b'{"format": "\xff"}'), ["manifest.json", "UTF-8"]),
    "manifest nested deeply": (_bytes("manifest.json", b"[" * 100_000 + b"]" * 100_000),
                               ["manifest.json", "nested deeper"]),
    "manifest huge integer": (_bytes("manifest.json", b'{"format": ' + b"9" * 5000 + b"}"),
                              ["manifest.json", "out of range"]),
    "manifest is a FIFO": (_replace_by_fifo("manifest.json"), ["manifest.json", "not a regular file"]),
}

TAMPERED_FILES = {
    "world non-UTF-8": (_bytes("worlds/triangle.json", b'{"format": "topomark/world@1\xff"}'),
                        ["worlds/triangle.json", "UTF-8"]),
    "world nested deeply": (_bytes("worlds/triangle.json", b"[" * 100_000 + b"]" * 100_000),
                            ["worlds/triangle.json", "nested deeper"]),
    "map huge integer": (_bytes("reference/triangle/default.map.json", b'{"format": ' + b"9" * 5000 + b"}"),
                         ["default.map.json", "out of range"]),
    "world is a FIFO": (_replace_by_fifo("worlds/triangle.json"), ["worlds/triangle.json", "not a regular file"]),
    "trace is a FIFO": (_replace_by_fifo("reference/triangle/default.trace.jsonl"),
                        ["default.trace.jsonl", "not a regular file"]),
    "trace non-UTF-8": (_bytes("reference/triangle/default.trace.jsonl", b'{"event": "\xff"}\n'),
                        ["default.trace.jsonl"]),
    "schema tampered": (_bytes("schema/world.schema.json", b"{}"), ["not the published schema"]),
    "schema non-UTF-8": (_bytes("schema/world.schema.json", b"\xff"), ["world.schema.json", "UTF-8"]),
}


@pytest.fixture
def suite_copy(small_suite, tmp_path) -> Path:
    dest = tmp_path / "suite"
    shutil.copytree(small_suite, dest)
    return dest


@pytest.mark.slow
@pytest.mark.parametrize("case", TAMPERED)
def test_conformance_run_refuses_a_tampered_manifest(case, suite_copy):
    tamper, words = TAMPERED[case]
    tamper(suite_copy)
    assert_refused(cli("conformance", "run", suite_copy, "--", *CLIENT), *words)


@pytest.mark.slow
@pytest.mark.parametrize("case", list(TAMPERED_FILES) + ["cost 0", "world path escapes", "manifest non-UTF-8"])
def test_conformance_lint_refuses_a_tampered_suite(case, suite_copy):
    tamper, words = {**TAMPERED, **TAMPERED_FILES}[case]
    tamper(suite_copy)
    assert_refused(cli("conformance", "lint", suite_copy), *words)


def test_lint_without_jsonschema_is_a_fault_not_a_pass(small_suite):
    proc = cli("conformance", "lint", small_suite, prelude="sys.modules['jsonschema'] = None")
    assert proc.returncode == 3 and "Traceback" not in proc.stderr
    assert "jsonschema" in proc.stderr


def test_the_untampered_small_suite_still_lints(small_suite):
    proc = cli("conformance", "lint", small_suite)
    assert proc.returncode == 0, proc.stderr


# -- random garbage fed to the loader -----------------------------------------------------
_JUNK = st.sampled_from(['[', ']', '{', '}', '"', ',', ':', '0', '-1', 'NaN', 'Infinity', '1e999', 'null',
                         'true', '"a"', '9' * 30, '[' * 200, '\\', '\x00', '\udcff', 'é', '²'])


@st.composite
def mutated_world_texts(draw) -> str:
    text = VALID
    for _ in range(draw(st.integers(1, 4))):
        where = draw(st.integers(0, len(text)))
        action = draw(st.sampled_from(["truncate", "flip", "insert", "delete"]))
        if action == "truncate":
            text = text[:where]
        elif action == "flip":
            text = text[:where] + draw(st.characters()) + text[where + 1:]
        elif action == "insert":
            text = text[:where] + draw(_JUNK) * draw(st.integers(1, 3)) + text[where:]
        else:
            text = text[:where] + text[where + draw(st.integers(1, 20)):]
    return text


@settings(max_examples=300, deadline=None)
@given(mutated_world_texts())
def test_garbled_world_texts_load_or_raise_invalid_world(text):
    try:
        world = loads_world(text, "garbled.json")
    except InvalidWorld as exc:
        assert str(exc).startswith("garbled.json")
    else:
        assert isinstance(world, World)


@settings(max_examples=100, deadline=None)
@given(mutated_world_texts(), st.binary(max_size=8), st.integers(0, 400))
def test_garbled_world_files_load_or_raise_invalid_world(text, junk, where):
    data = text.encode("utf-8", "surrogatepass")
    data = data[:where] + junk + data[where:]
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "garbled.json"
        path.write_bytes(data)
        try:
            world = load_world(path)
        except InvalidWorld as exc:
            assert str(path) in str(exc)
        else:
            assert isinstance(world, World)

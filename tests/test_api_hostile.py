"""Hostile arguments to every function of ``topomark.__all__``: each is refused before any work with one
:class:`~topomark.spec.errors.InvalidInput` (or its subclass InvalidKeyword) naming the parameter, fast and in
bounded memory — never a deep AttributeError or TypeError, a MemoryError, a hang, or a result with no rows.

Each case runs under ``signal.alarm``: the cases that used to hang (a worst case past the exhaustive sizes, a
search of 300,000 vertices, an algorithm option of None meaning "no limit") fail the test instead of hanging it.
"""

from __future__ import annotations

import inspect
import json
import itertools
import signal
from typing import Any, Callable

import pytest

import topomark as T
from topomark.reference.explorers.policies import Policies
from topomark.spec.errors import InvalidInput, InvalidKeyword

NAN, INF = float("nan"), float("inf")
W = "cycle:n=4"
SECONDS = 20
"""Each refusal must come well within this (they take milliseconds); the alarm turns a hang into a failure."""


class _Hang(BaseException):
    pass


@pytest.fixture
def alarm():
    def ring(*_: Any) -> None:
        raise _Hang(f"no answer within {SECONDS} s")

    previous = signal.signal(signal.SIGALRM, ring)
    signal.alarm(SECONDS)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, previous)


def _endless() -> Any:
    while True:
        yield {"event": "x"}


def _small(**kw: Any) -> Any:
    return T.adversarial_search("basic", **{"n": 5, "max_degree": 3, "evaluations": 2, **kw})


CASES: list[tuple[str, Callable[[], Any], type[Exception], str]] = [
    # load_world, save_world
    ("load_world None", lambda: T.load_world(None), InvalidInput, "path must be a path"),
    ("load_world int", lambda: T.load_world(3), InvalidInput, "not int"),
    ("load_world empty", lambda: T.load_world(""), InvalidInput, "path: the path is empty"),
    ("load_world NUL", lambda: T.load_world("a\0b"), InvalidInput, "NUL byte"),
    ("load_world misspelt", lambda: T.load_world(pth="w.json"), InvalidKeyword, "'pth'; did you mean 'path'"),
    ("save_world text", lambda: T.save_world(W, "w.json"), InvalidInput, "writes a World"),
    ("save_world None", lambda: T.save_world(None, "w.json"), InvalidInput, "not NoneType"),
    ("save_world path None", lambda: T.save_world(T.generate(W), None), InvalidInput, "path must be a path"),
    ("save_world NUL", lambda: T.save_world(T.generate(W), "a\0b"), InvalidInput, "NUL byte"),
    # generate
    ("generate n str", lambda: T.generate("cycle", n="4"), InvalidInput, "parameter n must be int, not str"),
    ("generate n None", lambda: T.generate("cycle", n=None), InvalidInput, "parameter n must be int"),
    ("generate n NaN", lambda: T.generate("cycle", n=NAN), InvalidInput, "not float (nan)"),
    ("generate n bool", lambda: T.generate("cycle", n=True), InvalidInput, "not bool"),
    ("generate n huge", lambda: T.generate("cycle", n=10 ** 100), InvalidInput, "out of range"),
    ("generate n -1", lambda: T.generate("cycle", n=-1), InvalidInput, "n must be >= 3"),
    ("generate seed str", lambda: T.generate("lattice-hole", seed="x"), InvalidInput, "seed must be int"),
    ("generate marker int", lambda: T.generate("wheel-a", marker=3), InvalidInput, "marker must be str"),
    ("generate misspelt", lambda: T.generate("cycle", nn=4), InvalidKeyword, "did you mean 'n'"),
    ("generate dict", lambda: T.generate({"a": ["b"]}), InvalidInput, "not dict"),
    # explore
    ("explore None", lambda: T.explore(None), InvalidInput, "a world must be"),
    ("explore generator", lambda: T.explore(_endless()), InvalidInput, "not generator"),
    ("explore list", lambda: T.explore([1, 2]), InvalidInput, "not list"),
    ("explore algorithm list", lambda: T.explore(W, algorithm=["basic"]), InvalidInput, "algorithm must be"),
    ("explore algorithm None", lambda: T.explore(W, algorithm=None), InvalidInput, "not NoneType"),
    ("explore lighthouse int", lambda: T.explore(W, lighthouse=3), InvalidInput, "lighthouse must be"),
    ("explore policy None", lambda: T.explore(W, policies={"edge": None}), InvalidInput, "the edge policy must"),
    ("explore policy kind", lambda: T.explore(W, policies={3: "lifo"}), InvalidInput, "unknown policy kind 3"),
    ("explore check str", lambda: T.explore(W, check="no"), InvalidInput, "check must be True or False"),
    ("explore check None", lambda: T.explore(W, check=None), InvalidInput, "check must be True or False"),
    ("explore record str", lambda: T.explore(W, record="no"), InvalidInput, "record must be True or False"),
    ("explore trace int", lambda: T.explore(W, trace=3), InvalidInput, "trace must be a path"),
    ("explore option None", lambda: T.explore(W, algorithm="model-tree", max_steps=None), InvalidInput,
     "max_steps must be an integer"),
    ("explore option str", lambda: T.explore(W, algorithm="model-tree", max_steps="10"), InvalidInput,
     "not str ('10')"),
    ("explore option NaN", lambda: T.explore(W, algorithm="model-tree", max_steps=NAN), InvalidInput, "max_steps"),
    ("explore option bool", lambda: T.explore(W, algorithm="model-tree", max_steps=True), InvalidInput, "not bool"),
    ("explore misspelt", lambda: T.explore(W, algoritm="basic"), InvalidKeyword, "did you mean 'algorithm'"),
    # explore: options checked deep in the registry, named as keywords (topomark.spec.spelling)
    ("explore option too small", lambda: T.explore(W, algorithm="model-tree", max_models=0), InvalidInput,
     "max_models must be an integer >= 1, got 0"),
    ("explore option too large", lambda: T.explore(W, algorithm="model-tree", max_models=10 ** 9), InvalidInput,
     "max_models must be at most 100,000"),
    ("explore option choice", lambda: T.explore(W, algorithm="model-tree", prior="nope"), InvalidInput,
     "prior must be one of none, single-leaf"),
    ("explore false cue", lambda: T.explore(W, algorithm="model-tree", cue_diameter=5), InvalidInput,
     "cue_diameter=5 is false for this world"),
    ("explore false cue n", lambda: T.explore(W, algorithm="model-tree", cue_n=7), InvalidInput,
     "cue_n=7 is false for this world"),
    ("explore false prior", lambda: T.explore(W, algorithm="model-tree", prior="single-leaf"), InvalidInput,
     "prior='single-leaf' is false for this world"),
    # check_map, isomorphic, distinguish
    ("check_map None", lambda: T.check_map(W, None), InvalidInput, "a world must be"),
    ("check_map misspelt", lambda: T.check_map(W, map=W), InvalidKeyword, "did you mean 'map_'"),
    ("isomorphic markers str", lambda: T.isomorphic(W, W, markers="no"), InvalidInput, "markers must be True"),
    ("isomorphic markers None", lambda: T.isomorphic(W, W, markers=None), InvalidInput, "markers must be True"),
    ("isomorphic misspelt", lambda: T.isomorphic(W, W, marker=False), InvalidKeyword, "did you mean 'markers'"),
    ("distinguish int", lambda: T.distinguish(1, 2), InvalidInput, "not int"),
    # replay
    ("replay None", lambda: T.replay(W, None), InvalidInput, "trace must be a trace file or an iterable"),
    ("replay int", lambda: T.replay(W, 3), InvalidInput, "not int"),
    ("replay dict", lambda: T.replay(W, {"event": "header"}), InvalidInput, "not dict"),
    ("replay bytes", lambda: T.replay(W, b"{}"), InvalidInput, "not bytes"),
    ("replay endless", lambda: T.replay(W, _endless()), InvalidInput, "line 1: expected a trace event"),
    ("replay a set", lambda: T.replay(W, [{"event": {1}}]), InvalidInput, "line 1: not a JSON object"),
    ("replay NaN", lambda: T.replay(W, [{"cost": NAN}]), InvalidInput, "NaN is not a JSON number"),
    ("replay empty path", lambda: T.replay(W, ""), InvalidInput, "trace: the path is empty"),
    # search, prove
    ("search marker None", lambda: T.search(None, 3, 2), InvalidInput, "marker must be a marker class"),
    ("search max_vertices str", lambda: T.search("none", "3", 2), InvalidInput, "max_vertices must be an integer"),
    ("search max_vertices bool", lambda: T.search("none", True, 2), InvalidInput, "not bool"),
    ("search max_vertices huge", lambda: T.search("none", 10 ** 100, 2), InvalidInput, "integer of 101 digits"),
    ("search max_degree huge", lambda: T.search("none", 3, 10 ** 100), InvalidInput, "max_degree must be"),
    ("search max_degree float", lambda: T.search("none", 3, 2.5), InvalidInput, "not float (2.5)"),
    ("search timeout NaN", lambda: T.search("none", 3, 2, timeout=NAN), InvalidInput, "timeout must be positive"),
    ("search timeout inf", lambda: T.search("none", 3, 2, timeout=INF), InvalidInput, "got inf"),
    ("search timeout 0", lambda: T.search("none", 3, 2, timeout=0), InvalidInput, "timeout must be positive"),
    ("search timeout -1", lambda: T.search("none", 3, 2, timeout=-1), InvalidInput, "timeout must be positive"),
    ("search timeout str", lambda: T.search("none", 3, 2, timeout="1"), InvalidInput, "not str"),
    ("search timeout huge int", lambda: T.search("none", 3, 2, timeout=10 ** 400), InvalidInput, "401 digits"),
    ("search planar str", lambda: T.search("none", 3, 2, planar="no"), InvalidInput, "planar must be True"),
    ("search misspelt", lambda: T.search("none", 3, 2, timout=1), InvalidKeyword, "did you mean 'timeout'"),
    ("prove timeout NaN", lambda: T.prove("none", 3, 2, timeout=NAN), InvalidInput, "timeout must be positive"),
    ("prove max_vertices NaN", lambda: T.prove("none", NAN, 2), InvalidInput, "max_vertices must be"),
    # census
    ("census max_vertices str", lambda: T.census("none", "3", 2), InvalidInput, "max_vertices must be an integer"),
    ("census max_vertices None", lambda: T.census("none", None, 2), InvalidInput, "not NoneType"),
    ("census max_degree NaN", lambda: T.census("none", 3, NAN), InvalidInput, "max_degree must be"),
    ("census max_degree huge", lambda: T.census("none", 3, 10 ** 100), InvalidInput, "max_degree must be"),
    ("census too many worlds", lambda: T.census("none", 8, 7), InvalidInput,
     "max_degree=7 with max_vertices=8 enumerates more than"),
    ("census jobs float", lambda: T.census("none", 3, 2, jobs=1.5), InvalidInput, "jobs must be an integer"),
    ("census jobs str", lambda: T.census("none", 3, 2, jobs="2"), InvalidInput, "not str"),
    ("census shards int", lambda: T.census("none", 3, 2, shards=3), InvalidInput, "shards must be a path"),
    ("census scheduler int", lambda: T.census("none", 3, 2, scheduler=3), InvalidInput, "scheduler must be"),
    ("census progress int", lambda: T.census("none", 3, 2, progress=3), InvalidInput, "progress must be a function"),
    ("census misspelt", lambda: T.census("none", 3, 2, job=2), InvalidKeyword, "did you mean 'jobs'"),
    # algorithms
    ("algorithms misspelt", lambda: T.algorithms(verbose=True), InvalidKeyword, "algorithms() takes no keywords"),
    # worst_case
    ("worst_case algorithm None", lambda: T.worst_case(None, 3, 2), InvalidInput, "algorithm must be"),
    ("worst_case unknown lighthouse", lambda: T.worst_case("basic", 3, 2, lighthouse="nope"), InvalidInput,
     "unknown lighthouse 'nope'"),
    ("worst_case lighthouse for a kit", lambda: T.worst_case("footprints", 3, 2, lighthouse="directional-vertex"),
     InvalidInput, "takes no lighthouse"),
    ("worst_case unknown policy", lambda: T.worst_case("basic", 3, 2, policies={"edge": "x"}), InvalidInput,
     "unknown edge policy 'x'"),
    ("worst_case max_vertices 0", lambda: T.worst_case("basic", 0, 2), InvalidInput, "max_vertices must be an integer"),
    ("worst_case max_vertices 1", lambda: T.worst_case("basic", 1, 2), InvalidInput, "from 2 to 8"),
    ("worst_case max_vertices 9", lambda: T.worst_case("basic", 9, 4), InvalidInput, "from 2 to 8"),
    ("worst_case max_vertices None", lambda: T.worst_case("basic", None, 2), InvalidInput, "not NoneType"),
    ("worst_case max_vertices float", lambda: T.worst_case("basic", 3.0, 2), InvalidInput, "not float (3.0)"),
    ("worst_case max_vertices bool", lambda: T.worst_case("basic", True, 2), InvalidInput, "not bool"),
    ("worst_case too many worlds", lambda: T.worst_case("basic", 7, 6), InvalidInput,
     "max_degree=6 with max_vertices=7 enumerates more than"),
    ("worst_case max_degree 0", lambda: T.worst_case("basic", 3, 0), InvalidInput, "max_degree must be"),
    ("worst_case max_degree NaN", lambda: T.worst_case("basic", 3, NAN), InvalidInput, "max_degree must be"),
    ("worst_case max_degree huge", lambda: T.worst_case("basic", 3, 10 ** 100), InvalidInput, "101 digits"),
    ("worst_case jobs huge", lambda: T.worst_case("basic", 3, 2, jobs=10 ** 6), InvalidInput, "from 1 to 256"),
    ("worst_case sample NaN", lambda: T.worst_case("basic", 3, 2, sample=NAN), InvalidInput, "sample must be a number"),
    ("worst_case sample 2", lambda: T.worst_case("basic", 3, 2, sample=2), InvalidInput, "from 0 to 1, not int (2)"),
    ("worst_case sample inf", lambda: T.worst_case("basic", 3, 2, sample=INF), InvalidInput, "not float (inf)"),
    ("worst_case sample str", lambda: T.worst_case("basic", 3, 2, sample="0.1"), InvalidInput, "not str"),
    ("worst_case seed NaN", lambda: T.worst_case("basic", 3, 2, seed=NAN), InvalidInput, "seed must be an integer"),
    ("worst_case seed huge", lambda: T.worst_case("basic", 3, 2, seed=10 ** 100), InvalidInput, "seed must be"),
    ("worst_case shards int", lambda: T.worst_case("basic", 3, 2, shards=3), InvalidInput, "shards must be a path"),
    ("worst_case misspelt", lambda: T.worst_case("basic", 3, 2, lighthose="x"), InvalidKeyword,
     "did you mean 'lighthouse'"),
    # adversarial_search
    ("adversarial_search policies str", lambda: _small(policies="lifo"), InvalidInput, "policies must be a Policies"),
    ("adversarial_search policy unknown", lambda: _small(policies={"edge": "x"}), InvalidInput, "unknown edge policy 'x'"),
    ("adversarial_search n 300000", lambda: _small(n=300_000), InvalidInput, "n must be an integer from 3 to 500"),
    ("adversarial_search n huge", lambda: _small(n=10 ** 9), InvalidInput, "from 3 to 500"),
    ("adversarial_search n NaN", lambda: _small(n=NAN), InvalidInput, "not float (nan)"),
    ("adversarial_search evaluations huge", lambda: _small(evaluations=10 ** 12), InvalidInput,
     "evaluations must be an integer from 1 to 100,000"),
    ("adversarial_search evaluations x n", lambda: _small(n=400, evaluations=10_000), InvalidInput, "at most 2,000,000"),
    ("adversarial_search max_degree huge", lambda: _small(max_degree=10 ** 12), InvalidInput, "max_degree must be"),
    ("adversarial_search objective None", lambda: _small(objective=None), InvalidInput, "objective must be"),
    ("adversarial_search family list", lambda: _small(family=[]), InvalidInput, "family must be"),
    ("adversarial_search lighthouse int", lambda: _small(lighthouse=3), InvalidInput, "lighthouse must be"),
    ("adversarial_search progress int", lambda: _small(progress=3), InvalidInput, "progress must be a function"),
    ("adversarial_search baseline str", lambda: _small(baseline="no"), InvalidInput, "baseline must be True or False"),
    ("adversarial_search misspelt", lambda: _small(evalutions=3), InvalidKeyword, "did you mean 'evaluations'"),
]


@pytest.mark.parametrize("call, error, fragment", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_a_hostile_argument_is_one_precise_refusal(alarm, call, error, fragment, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a case that wrongly wrote a file would write it here
    with pytest.raises(error) as caught:
        call()
    message = str(caught.value)
    assert fragment in message and "\n" not in message
    assert isinstance(caught.value, InvalidInput)
    assert "--" not in message  # a Python caller is told the keyword argument, never a command-line flag


def test_every_public_function_has_a_case():
    functions = {name for name in T.__all__ if callable(getattr(T, name)) and not isinstance(getattr(T, name), type)
                 and name[0].islower()}
    covered = {name.split()[0] for name, *_ in CASES}
    assert functions == covered


def test_a_misspelt_keyword_is_also_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'lighthose'"):
        T.worst_case("basic", 3, 2, lighthose="x")


def test_replay_reads_records_one_at_a_time(alarm):
    run = T.explore(W)
    pulled = []

    def records() -> Any:
        for k, rec in enumerate(itertools.chain(run.trace[:2], [{"event": "header"}], run.trace[2:]), 1):
            pulled.append(k)
            yield rec

    with pytest.raises(InvalidInput, match="line 3"):
        T.replay(W, records())
    assert max(pulled) == 3  # refused when reached; the old code read the whole stream first


def test_adversarial_search_takes_the_policies_explore_takes():
    by_mapping = T.adversarial_search("basic", n=6, max_degree=3, evaluations=4, seed=1, policies={"edge": "lifo"})
    by_object = T.adversarial_search("basic", n=6, max_degree=3, evaluations=4, seed=1, policies=Policies("lifo"))
    assert by_mapping.best is not None and by_mapping.to_json() == by_object.to_json()


def test_worst_case_takes_policies_and_still_answers():
    rows = T.worst_case("basic", 3, 2, policies={"edge": "lifo"})
    assert [r["n"] for r in rows] == [2, 3] and all(r["runs"] > 0 for r in rows)


@pytest.mark.parametrize("name", [n for n in T.__all__ if inspect.isfunction(getattr(T, n))])
def test_a_call_the_signature_cannot_take_is_bad_input_naming_the_function(name):
    """Too many positional arguments, or a required one missing: bad input, as a misspelt keyword is, and still
    the TypeError Python raises for such a call."""
    function = getattr(T, name)
    with pytest.raises(InvalidKeyword, match=rf"^{name}\(\) cannot be called so: too many positional arguments"):
        function(*([None] * 12))
    required = [p for p in inspect.signature(function).parameters.values()
                if p.default is p.empty and p.kind == p.POSITIONAL_OR_KEYWORD]
    if required:
        with pytest.raises(TypeError, match=rf"^{name}\(\) cannot be called so: missing a required argument"):
            function()


def _endless_valid(pulled: list[int]) -> Any:
    """A valid trace that never ends: the robot family's header, then moves around a 4-cycle for ever."""
    from topomark.spec.kit import Kit

    yield {"event": "header", "format": "topomark/trace@2", "family": "robot", "algorithm": "chapter-6-sketch",
           "policies": {}, "lighthouse": None, "kit": Kit(vertex=1, movable=True).to_json(), "n": 4, "m": 4}
    for step in itertools.count(1):
        pulled.append(step)
        yield {"event": "move", "step": step, "motion": 0, "perception": "[2,A,A]", "purpose": "other"}


def test_an_endless_valid_generator_is_refused_at_the_record_cap(alarm, monkeypatch):
    """The cap the command's trace files have (MAX_TRACE_RECORDS, lowered here so the test is quick) ends an
    endless generator of valid records: one InvalidInput naming the record, read one at a time up to it."""
    from topomark.reference.trace import reader

    monkeypatch.setattr(reader, "MAX_TRACE_RECORDS", 2000)
    pulled: list[int] = []
    with pytest.raises(InvalidInput, match=r"^<records> line 2001: the trace goes on past 2,000 records") as caught:
        T.replay(W, _endless_valid(pulled))
    assert len(pulled) == 2000 and "\n" not in str(caught.value) and "--" not in str(caught.value)


def test_a_trace_file_past_the_record_cap_is_exit_2(tmp_path, monkeypatch, capsys):
    from topomark.reference.cli.main import main
    from topomark.reference.trace import reader

    monkeypatch.setattr(reader, "MAX_TRACE_RECORDS", 50)
    T.save_world(T.generate(W), tmp_path / "w.json")
    records = _endless_valid([])
    (tmp_path / "t.jsonl").write_text("".join(json.dumps(next(records)) + "\n" for _ in range(60)))
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "t.jsonl line 51: the trace goes on past 50 records" in err


def test_a_run_stopped_by_a_limit_through_the_api_replays_from_the_command_line(tmp_path, capsys):
    """A run's reason is part of the run (recorded in the trace's end, compared by replay's re-run), so it keeps
    one spelling whoever started it: a trace the API records replays from the command line, and the reverse."""
    from topomark.reference.cli.main import main

    world = T.generate("lattice:rows=3,cols=3")
    T.save_world(world, tmp_path / "w.json")
    run = T.explore(world, algorithm="model-tree", max_steps=1, trace=tmp_path / "api.jsonl")
    assert run.outcome == "limit" and "max-steps 1 reached" in run.reason
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "api.jsonl")]) == 0
    assert main(["explore", str(tmp_path / "w.json"), "--algorithm", "model-tree", "--max-steps", "1",
                 "--trace", str(tmp_path / "cli.jsonl")]) in (0, 1)
    capsys.readouterr()
    assert T.replay(world, tmp_path / "cli.jsonl").ok


@pytest.mark.parametrize("argv, flag", [
    (["explore", W, "--algorithm", "model-tree", "--max-models", "0"], "--max-models must be an integer >= 1"),
    (["explore", W, "--algorithm", "model-tree", "--cue-diameter", "5"], "--cue-diameter 5 is false"),
    (["worst-case", "--max-vertices", "7", "--max-degree", "6"], "--max-degree 6 with --max-vertices 7"),
    (["census", "--marker", "none", "--max-vertices", "9", "--max-degree", "4"], "--max-degree 4 with --max-vertices 9"),
    (["world", "cycle:n=4", "--seed", "3"], "--seed has no effect"),
])
def test_the_command_line_still_names_its_flags(argv, flag, capsys):
    from topomark.reference.cli.main import main

    assert main(argv) == 2
    assert flag in capsys.readouterr().err


def test_the_api_writers_refuse_a_file_already_there_unless_forced(tmp_path):
    """One rule for output paths (reference/files/overwrite.py): ``explore(trace=...)`` and ``save_world`` refuse a
    file that is there, before any work, naming the keywords; ``force=True`` overwrites it."""
    trace, world_file = tmp_path / "t.jsonl", tmp_path / "w.json"
    trace.write_text("keep\n")
    world_file.write_text("keep\n")
    with pytest.raises(InvalidInput, match=r"^trace='.*t\.jsonl': the file exists; give force=True to overwrite it$"):
        T.explore(W, trace=trace)
    with pytest.raises(InvalidInput, match=r"^path='.*w\.json': the file exists; give force=True to overwrite it$"):
        T.save_world(T.generate(W), world_file)
    assert trace.read_text() == world_file.read_text() == "keep\n"  # nothing written
    T.explore(W, trace=trace, force=True)
    T.save_world(T.generate(W), world_file, force=True)
    assert T.replay(W, trace).ok and T.load_world(world_file).n == T.generate(W).n
    with pytest.raises(InvalidInput, match="force must be True or False"):
        T.explore(W, trace=tmp_path / "new.jsonl", force="yes")
    assert not (tmp_path / "new.jsonl").exists()

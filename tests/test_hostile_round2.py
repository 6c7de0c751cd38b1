"""Hostile input, second round: option values that size work or memory, kit counts, generated worlds, and the
text of ``explore`` (exit 2 with one message naming the option and the value, never a traceback or a hang).

Each case runs the CLI in this process (``main``) and reads stderr; none asserts a speed.
"""

from __future__ import annotations

import pytest

from topomark.reference.algorithms.registrations.model_tree import MAX_MODELS, MAX_STEPS
from topomark.proofs.census_exec import worker_count
from topomark.reference.cli.args import MAX_JOBS
from topomark.reference.cli.main import main
from topomark.reference.explorers.lighthouses import (LIGHTHOUSES, MAX_NEIGHBOURHOOD, MAX_THRESHOLD,
                                                      MAX_WALK_LIMIT)
from topomark.spec.errors import InvalidInput
from topomark.spec.kit import Kit

DIGITS_5000 = "9" * 5000


def refused(capsys, argv: list[str], *words: str) -> str:
    """Run ``topomark argv``; it must exit 2 with one ``topomark: error:`` line holding every word."""
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert "Traceback" not in err and len(err.splitlines()) == 1, err[-2000:]
    assert err.startswith("topomark: error: "), err
    for w in words:
        assert w in err, (w, err)
    assert len(err) < 600, err
    return err


# -- 1: options that size work or memory have caps ---------------------------------------------------------
@pytest.mark.parametrize("light, option, value, words", [
    ("undirected-vertex", "--walk-limit", DIGITS_5000, ("--walk-limit", f"{MAX_WALK_LIMIT:,}", "99999")),
    ("undirected-vertex", "--neighbourhood", DIGITS_5000, ("--neighbourhood", f"{MAX_NEIGHBOURHOOD}", "99999")),
    ("undirected-vertex", "--walk-limit", "-" + DIGITS_5000, ("--walk-limit", "at least 1")),
    ("local-pair", "--walk-limit", "100000000", ("--walk-limit", f"{MAX_WALK_LIMIT:,}", "100000000")),
    ("local-degree-list", "--walk-limit", "100000000", ("--walk-limit", "100000000")),
    ("undirected-vertex", "--neighbourhood", "100", ("--neighbourhood", "at most 8", "got 100")),
    ("local-degree-list", "--neighbourhood", "1000000000", ("--neighbourhood", "1000000000")),
    ("local-pair", "--threshold", str(MAX_THRESHOLD + 1), ("--threshold", f"{MAX_THRESHOLD:,}")),
    ("local-pair", "--threshold", DIGITS_5000, ("--threshold", "characters")),
])
def test_lighthouse_option_caps(capsys, light, option, value, words):
    refused(capsys, ["explore", "lattice:rows=4,cols=4", "--lighthouse", light, option, value, "--quiet"], *words)


def test_lighthouse_caps_accept_their_own_value():
    light = LIGHTHOUSES["local-degree-list"].with_options(walk_limit=MAX_WALK_LIMIT, neighbourhood=MAX_NEIGHBOURHOOD,
                                                          threshold=MAX_THRESHOLD)
    assert (light.walk_limit, light.neighbourhood, light.threshold) == (MAX_WALK_LIMIT, MAX_NEIGHBOURHOOD,
                                                                        MAX_THRESHOLD)
    with pytest.raises(InvalidInput, match="--walk-limit must be at most"):
        light.with_options(walk_limit=MAX_WALK_LIMIT + 1)


@pytest.mark.parametrize("option, value, words", [
    ("--max-models", str(MAX_MODELS + 1), ("--max-models", f"{MAX_MODELS:,}", str(MAX_MODELS + 1))),
    ("--max-models", "1000000000000000000", ("--max-models", f"{MAX_MODELS:,}")),
    ("--max-steps", str(10 ** 18 - 1), ("--max-steps", f"{MAX_STEPS:,}", str(10 ** 18 - 1))),
    ("--max-steps", DIGITS_5000, ("--max-steps", f"{MAX_STEPS:,}", "characters")),
])
def test_model_tree_caps(capsys, option, value, words):
    refused(capsys, ["explore", "cycle:n=4", "--algorithm", "model-tree", option, value, "--quiet"], *words)


def test_help_states_the_caps(capsys):
    with pytest.raises(SystemExit):
        main(["explore", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for cap in (f"at most {MAX_WALK_LIMIT:,}", f"at most {MAX_NEIGHBOURHOOD}", f"at most {MAX_THRESHOLD:,}",
                f"at most {MAX_MODELS:,}", f"at most {MAX_STEPS:,}"):
        assert cap in text, cap


# -- 2: --kit counts are integers, not booleans; a key named twice is refused ------------------------------
@pytest.mark.parametrize("kit, words", [
    ('{"thread": true}', ("--kit", "thread length must be a non-negative integer", "True")),
    ('{"thread": false}', ("--kit", "thread length", "False")),
    ('{"undirected-edge": true}', ("--kit", "edge markers must be a non-negative integer", "True")),
    ('{"directional-vertex": true}', ("--kit", "vertex markers", "True")),
    ('{"undirected-either": true, "undirected-edge": 1}', ("--kit", "either markers", "True")),
    ('{"undirected-edge": 1, "undirected-edge": 3}', ("--kit", "duplicate key 'undirected-edge'")),
    ('{"thread": 0, "thread": 0}', ("--kit", "duplicate key 'thread'")),
    ('{"directional-edge": 1, "movable": true, "movable": false}', ("--kit", "duplicate key 'movable'")),
    ('{"' + "k" * 5000 + '": 1}', ("--kit", "unknown key", "characters")),
])
def test_kit_refusals(capsys, kit, words):
    refused(capsys, ["run-external", "cycle:n=4", "--kit", kit, "--", "true"], *words)


@pytest.mark.parametrize("obj", [{"thread": True}, {"undirected-vertex": False}, {"undirected-either": True}])
def test_kit_from_json_refuses_booleans_for_every_kind(obj):
    """The same parser reads a provider's hello.kit (protocol@2) and a trace header's kit."""
    with pytest.raises(InvalidInput, match="must be a non-negative integer"):
        Kit.from_json(obj)


def test_world_files_still_refuse_duplicate_keys(tmp_path, capsys):
    path = tmp_path / "w.json"
    path.write_text('{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": ["a"]}, '
                    '"rotation": {"a": ["b"], "b": ["a"]}}')
    refused(capsys, ["explore", str(path), "--quiet"], str(path), "duplicate key 'rotation'")


# -- 3: the wheel worlds: Figure 3.4's undirected marker, Figure 3.6's directional one -------------------------
def test_a_written_figure_3_6_wheel_is_explored(tmp_path, capsys):
    """``wheel-a:marker=directional`` carries the marker Algorithm 3.1 drops (Figure 3.6): written or as
    generator text, ``explore`` maps it with its default lighthouse."""
    for marker in ("directional", "none"):
        path = tmp_path / f"{marker}.json"
        assert main(["world", f"wheel-a:marker={marker}", "-o", str(path)]) == 0
        assert main(["explore", str(path), "--quiet", "--json"]) == 0
        assert main(["explore", f"wheel-b:marker={marker}", "--quiet", "--json"]) == 0
    capsys.readouterr()


def test_figure_3_4_wheel_says_what_to_do(tmp_path, capsys):
    """The wheels are written bare by default (every command takes them, see test_every_generator_everywhere);
    Figure 3.4's undirected centre marker, asked for, is refused by a lighthouse algorithm alike from the file
    and from the generator text, with the way out in the message."""
    path = tmp_path / "w.json"
    assert main(["world", "wheel-a:marker=undirected", "-o", str(path)]) == 0
    capsys.readouterr()
    texts = [refused(capsys, ["explore", where, "--quiet"], "only a directional vertex marker",
                     "wheel-a:marker=directional", "marker=none", "--lighthouse")
             for where in (str(path), "wheel-a:marker=undirected")]
    assert texts[0] == texts[1]
    refused(capsys, ["world", "wheel-a:marker=sideways"], "marker must be one of undirected, directional, none")


# -- 4, 5: the text report's bound and hypothesis rows say what they count ------------------------------------
def test_an_asymptotic_bound_is_not_reported_as_none(capsys):
    """case-3b states O(m) (``topomark algorithms``): no constant, so no run is held to it — not "none stated"."""
    assert main(["explore", "lattice:rows=3,cols=3", "--algorithm", "case-3b", "--quiet"]) == 0
    row = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("cost bound"))
    assert "O(m)" in row and "asymptotic" in row and "none stated" not in row
    assert main(["explore", "cycle:n=4", "--algorithm", "model-tree", "--max-steps", "12", "--quiet"]) in (0, 1)
    row = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("cost bound"))
    assert "none stated in the thesis" in row


def test_the_hypothesis_counts_add_up(capsys):
    """Rejected + confirmed + untested (never walked: a confirmation ends the test of H) = all hypotheses."""
    assert main(["explore", "lattice:rows=5,cols=5", "--quiet"]) == 0
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith("hypotheses"))
    assert "(rejected / confirmed / untested)" in row
    total, rest = row.split(")", 1)[1].split("(", 1)
    rejected, confirmed, untested = (int(x) for x in rest.split(";")[0].split(" / "))
    assert int(total) == rejected + confirmed + untested and untested > 0
    assert main(["explore", "lattice:rows=5,cols=5", "--quiet", "--json"]) == 0
    data = __import__("json").loads(capsys.readouterr().out)
    assert (data["hypotheses"], data["hypotheses_rejected"], data["hypotheses_confirmed"]) == (
        int(total), rejected, confirmed)


@pytest.mark.parametrize("command", [["explore", "cycle:n=4"], ["world", "random"]])
def test_a_huge_seed_is_refused_with_its_value_clipped(capsys, command):
    refused(capsys, [*command, "--seed", DIGITS_5000], "--seed", "at most 18 digits", "(5,000 characters)")


# -- --jobs: one check for every command, a cap, and never more workers than tasks ------------------------------
@pytest.mark.parametrize("command", [
    ["bench", "random-20", "--sizes", "15", "--graphs", "1", "--no-plots", "--quiet"],
    ["census", "--marker", "directional-vertex", "--max-vertices", "2", "--max-degree", "2"],
])
@pytest.mark.parametrize("value", ["0", "-1", str(MAX_JOBS + 1)])
def test_jobs_is_refused_the_same_way_everywhere(capsys, tmp_path, command, value):
    err = refused(capsys, [*command, "--out" if command[0] == "bench" else "--shards", str(tmp_path / "o"),
                           f"--jobs={value}"], "--jobs", f"at most {MAX_JOBS}", f"got {value}")
    assert err == f"topomark: error: --jobs must be at least 1 and at most {MAX_JOBS}; got {value}"


def test_worker_count_never_exceeds_the_tasks():
    assert [worker_count(j, t) for j, t in ((48, 12), (2, 12), (4, 0), (1, 5), (256, 256))] == [12, 2, 1, 1, 256]


def test_bench_starts_no_more_workers_than_runs(monkeypatch, tmp_path, capsys):
    import multiprocessing

    started = []

    class FakePool:
        def __init__(self, n, **_):  # initializer: the workers' own set-up (they ignore Ctrl-C, die with the leader)
            started.append(n)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            return False

        def imap_unordered(self, f, items, chunksize=1):
            return map(f, items)

    class FakeContext:
        Pool = FakePool

    monkeypatch.setattr(multiprocessing, "get_context", lambda *a: FakeContext())
    assert main(["bench", "random-20", "--sizes", "15", "20", "--graphs", "1", "--no-plots", "--quiet", "--jobs", "48",
                 "--out", str(tmp_path), "--json"]) == 0
    ran = __import__("json").loads(capsys.readouterr().out)["ran"]
    assert ran >= 2 and started == [min(48, ran)]


def test_census_starts_no_more_workers_than_tasks(monkeypatch, tmp_path):
    from topomark.proofs import census_exec, census_run

    started = []
    real = census_exec.multiprocessing.get_context

    class Recording:
        def __init__(self, ctx):
            self.ctx = ctx

        def Pool(self, processes, **kw):
            started.append(processes)
            return self.ctx.Pool(processes, **kw)

    monkeypatch.setattr(census_exec.multiprocessing, "get_context", lambda *a: Recording(real(*a)))
    census_run.sharded_census("directional-vertex", 4, 3, tmp_path, jobs=48, task_worlds=20, shards=3)
    tasks = len(__import__("json").loads((tmp_path / "manifest.json").read_text())["tasks"])
    assert tasks < 48 and started == [max(tasks, 3)]  # the map tasks or the 3 reduce tasks, not 48


def test_census_progress_never_shows_an_estimate_below_the_count():
    from topomark.proofs.census_exec import Progress

    bar = Progress(2367, None)
    bar.done(2000, 2539)
    line = bar.line()
    assert "2,539 worlds (more than the ~2,367 estimated)" in line and "/~2,367" not in line
    bar = Progress(2367, None)
    bar.done(1000, 1200)
    assert "1,200/~2,367 worlds" in bar.line()


# -- --policy: only the kinds the algorithm's registry entry declares ----------------------------------------
@pytest.mark.parametrize("algorithm, policy, kind", [
    ("case-4", "hypothesis=lifo", "hypothesis"), ("case-4", "lifo", "edge"), ("dudek", "hypothesis=lifo", "hypothesis"),
    ("thread-explore", "hypothesis=lifo", "hypothesis"), ("thread-explore", "edge=fifo", "edge"),
    ("case-3b", "path=dfs", "path"), ("model-tree", "lifo", "edge"),
])
def test_a_policy_the_algorithm_does_not_take_is_refused(capsys, algorithm, policy, kind):
    refused(capsys, ["explore", "cycle:n=5", "--algorithm", algorithm, "--policy", policy, "--quiet"],
            f"--policy {policy}", f"the algorithm {algorithm} takes no {kind} policy")


@pytest.mark.parametrize("algorithm, policy", [("basic", "hypothesis=lifo"), ("case-3b", "lifo"),
                                               ("dudek", "edge=fifo"), ("case-1a", "edge=lifo")])
def test_a_declared_policy_is_accepted_and_recorded(capsys, algorithm, policy):
    assert main(["explore", "cycle:n=5", "--algorithm", algorithm, "--policy", policy, "--quiet", "--json"]) == 0
    kind, _, name = policy.rpartition("=")
    assert __import__("json").loads(capsys.readouterr().out)["policies"][kind or "edge"] == name


def test_the_declared_policy_kinds_are_the_ones_each_explorer_consults():
    """Every registered algorithm declares exactly the policy kinds its explorer asks for on a small world
    (model-tree and its listing, whose model search grows fast with cycles, on a 4-vertex chain; an algorithm for a class of worlds
    on the first of the lattice, a chain and a world with one leaf that it accepts)."""
    from topomark.reference.algorithms.registry import REGISTRY
    from topomark.reference.explorers.policies import Policies
    from topomark.reference.run.explore import explore
    from topomark.reference.worlds.argument import resolve_world

    class Spy(Policies):
        def choose_edge(self, S, dist):
            self.used.add("edge")
            return super().choose_edge(S, dist)

        def order_hypotheses(self, hypotheses, lengths):
            self.used.add("hypothesis")
            return super().order_hypotheses(hypotheses, lengths)

        def __getattribute__(self, name):
            if name == "path":
                object.__getattribute__(self, "used").add("path")
            return object.__getattribute__(self, name)

    from topomark.reference.run.explore import check_run
    from topomark.spec.errors import InvalidInput

    def world_for(spec):  # the lattice, unless the algorithm is for a class of worlds it is not in (a tree walk)
        if spec.name in ("model-tree", "model-tree-listing"):
            return resolve_world("chain:n=4")
        for text in ("lattice:rows=3,cols=3", "chain:n=6"):  # then a world with one leaf (single-leaf, §5.3)
            try:
                check_run(resolve_world(text), spec)
            except InvalidInput:
                continue
            return resolve_world(text)
        return resolve_world("random:n=6,fraction=0.4,seed=3")

    specs = REGISTRY.values() if isinstance(REGISTRY, dict) else REGISTRY
    for spec in specs:
        spy = Spy()
        spy.used = set()
        explore(world_for(spec), spec, spy, check=False, record=False)
        assert sorted(spy.used) == sorted(spec.policy_kinds), spec.name

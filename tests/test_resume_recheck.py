"""A resumed census trusts no kept record by its seal: records edited and resealed are found by recomputation.

A checksum finds damage, not an edit resealed by hand.  A resume so computes again a seeded sample of what it
kept and every kept record the census's verdict rests on (:mod:`topomark.proofs.census_recheck`); one that its
recomputation does not reproduce is exit 2 naming the file.  Each forgery below changes the census's answer
when the re-check is switched off (the seeded fault), and is refused with it on.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from topomark.proofs import census_recheck, census_run
from topomark.proofs.census_recheck import recheck_sample, task_of
from topomark.proofs.census_run import sharded_census
from topomark.proofs.census_shards import RECORD, digest, seal
from topomark.reference.cli.main import main
from topomark.spec.errors import InvalidInput

CENSUS = ("none", 5, 3)  # the C3/C4 counterexample at n = 4
ARGV = ["census", "--marker", "none", "--max-vertices", "5", "--max-degree", "3"]


def run(root: Path, notes: list[str] | None = None, seed: int | None = None):
    return sharded_census(*CENSUS, root, task_worlds=8, shards=3, note=(notes if notes is not None else []).append,
                          recheck_seed=seed)


@pytest.fixture(scope="module")
def baseline(tmp_path_factory):
    root = tmp_path_factory.mktemp("census") / "s"
    result = run(root)
    return root, result


@pytest.fixture
def copy(baseline, tmp_path):
    root = tmp_path / "s"
    shutil.copytree(baseline[0], root)
    return root


def _reseal(path: Path, change) -> None:
    record = {k: v for k, v in json.loads(path.read_text()).items() if k != "checksum"}
    change(record)
    path.write_text(json.dumps(seal(record)))


def _manifest(root: Path) -> dict:
    return json.loads((root / "manifest.json").read_text())


def _pair_shard(root: Path) -> int:
    return next(s for s in range(3) if json.loads((root / f"reduce-{s}.json").read_text())["pair"] is not None)


def _seed_drawing(kept: int, which: int, offset: int = 0) -> int:
    """A seed whose sample of ``range(kept)`` (drawn as the census draws it, seed + offset) holds ``which``."""
    return next(s for s in range(10_000) if which in recheck_sample(range(kept), s + offset))


def _seed_missing(kept: int, which: int, offset: int = 0) -> int:
    return next(s for s in range(10_000) if which not in recheck_sample(range(kept), s + offset))


def _unchecked(monkeypatch) -> None:
    """The seeded fault: the resume's re-check switched off."""
    monkeypatch.setattr(census_run, "recheck_resumed", lambda *a, **k: None)


def _forge_map(root: Path, task: int) -> None:
    """Rewrite map task ``task``'s data without its first record (its class loses a member) and reseal its record
    to match: every check of census_integrity holds afterwards."""
    data = np.fromfile(root / f"map-{task}.bin", RECORD)
    record = json.loads((root / f"map-{task}.done.json").read_text())
    shard = next(s for s in range(3) if record["offsets"][s + 1] > record["offsets"][s])
    keep = np.ones(len(data), bool)
    keep[record["offsets"][shard]] = False
    forged = data[keep].tobytes()
    (root / f"map-{task}.bin").write_bytes(forged)

    def change(r):
        r["offsets"] = [o - (i > shard) for i, o in enumerate(r["offsets"])]
        r.update(records=r["records"] - 1, bytes=len(forged), data=digest(forged))
    _reseal(root / f"map-{task}.done.json", change)
    for p in root.glob("reduce-*.json"):
        p.unlink()


def _hide_pair(r: dict) -> None:
    r["pair"] = None
    r["ambiguous_upto"] = [0] * len(r["ambiguous_upto"])


def test_an_untouched_resume_recomputes_a_sample_and_answers_the_same(baseline, copy):
    notes: list[str] = []
    assert run(copy, notes) == baseline[1]
    assert any("computing again map task(s)" in n and "seed" in n for n in notes), notes


def test_a_resealed_reduce_record_hiding_the_counterexample_is_refused_when_drawn(baseline, copy, monkeypatch):
    shard = _pair_shard(copy)
    _reseal(copy / f"reduce-{shard}.json", _hide_pair)
    with monkeypatch.context() as m:
        _unchecked(m)
        assert run(copy).smallest_counterexample is None  # the forgery flips the verdict without the re-check
    with pytest.raises(InvalidInput, match=rf"reduce-{shard}\.json: shard {shard} computed again .*edited and resealed"):
        run(copy, seed=_seed_drawing(3, shard, offset=1))


def test_a_sample_that_misses_the_forged_shard_does_not_see_it(copy):
    """What the sample does not draw it does not check: the rule is a sample, not a proof (documented)."""
    shard = _pair_shard(copy)
    _reseal(copy / f"reduce-{shard}.json", _hide_pair)
    assert run(copy, seed=_seed_missing(3, shard, offset=1)).smallest_counterexample is None


def test_the_shard_of_the_reported_pair_is_recomputed_even_when_not_drawn(baseline, copy, monkeypatch):
    shard = _pair_shard(copy)
    _reseal(copy / f"reduce-{shard}.json", lambda r: r.__setitem__("languages", [x + 1 for x in r["languages"]]))
    with monkeypatch.context() as m:
        _unchecked(m)
        assert run(copy).rows != baseline[1].rows
    with pytest.raises(InvalidInput, match=rf"reduce-{shard}\.json: shard {shard} computed again .*languages"):
        run(copy, seed=_seed_missing(3, shard, offset=1))


def test_a_resealed_task_record_with_other_sizes_is_refused_when_drawn(baseline, copy, monkeypatch):
    tasks = len(_manifest(copy)["tasks"])
    _reseal(copy / "map-1.done.json", lambda r: r["sizes"].__setitem__(next(iter(r["sizes"])), [10 ** 6, 10 ** 7]))
    with monkeypatch.context() as m:
        _unchecked(m)
        assert run(copy).rows != baseline[1].rows
    with pytest.raises(InvalidInput, match=r"map-1\.done\.json: map task 1 computed again .*sizes"):
        run(copy, seed=_seed_drawing(tasks, 1))


def test_forged_data_of_a_task_holding_the_counterexample_is_refused_even_when_not_drawn(copy):
    manifest = _manifest(copy)
    pair = json.loads((copy / f"reduce-{_pair_shard(copy)}.json").read_text())["pair"]
    for member in pair:
        root = copy.parent / f"forged-{member[0]}"
        shutil.copytree(copy, root, dirs_exist_ok=True)
        task = task_of(manifest, member)
        _forge_map(root, task)
        with pytest.raises(InvalidInput, match=rf"map-{task}\.done\.json: map task {task} computed again .*data"):
            run(root, seed=_seed_missing(len(manifest["tasks"]), task))


def test_forged_map_data_changes_the_answer_without_the_recheck(baseline, copy, monkeypatch):
    """The seeded fault of the map re-check: every task forged in turn; at least one forgery changes the answer
    when nothing is re-checked, and each is refused when its task is drawn."""
    tasks = len(_manifest(copy)["tasks"])
    changed = 0
    for task in range(tasks):
        root = copy.parent / f"forged-{task}"
        shutil.copytree(copy, root)
        _forge_map(root, task)
        with monkeypatch.context() as m:
            _unchecked(m)
            changed += run(root) != baseline[1]
        with pytest.raises(InvalidInput, match=rf"map-{task}\.done\.json"):
            run(root, seed=_seed_drawing(tasks, task))
    assert changed >= 1


def test_the_command_refuses_a_forged_directory_with_exit_2_naming_the_file(baseline, copy, capsys):
    shard = _pair_shard(copy)
    _reseal(copy / f"reduce-{shard}.json", lambda r: r.__setitem__("languages_upto", [0] * len(r["languages_upto"])))
    assert main([*ARGV, "--shards", str(copy)]) == 2
    err = capsys.readouterr().err
    lines = [x for x in err.splitlines() if not x.startswith("census:")]
    assert len(lines) == 1 and f"reduce-{shard}.json" in lines[0] and "Traceback" not in err


def test_what_ran_now_is_not_recomputed(copy, monkeypatch):
    for p in copy.glob("*.json"):
        if p.name != "manifest.json":
            p.unlink()
    calls: list = []
    monkeypatch.setattr(census_recheck, "recheck_map", lambda *a: calls.append(a))
    notes: list[str] = []
    run(copy, notes)
    assert calls == [] and not any("computing again" in n for n in notes)


# -- every record is read back as a regular file of bounded size ---------------------------------------------
def test_an_oversized_task_record_is_read_no_further_than_the_cap_and_mapped_again(baseline, copy):
    from topomark.proofs.census_integrity import MAX_RECORD_BYTES
    with open(copy / "map-0.done.json", "r+b") as f:  # sparse: as large as the cap allows plus one byte
        f.truncate(MAX_RECORD_BYTES + 1)
    notes: list[str] = []
    assert run(copy, notes) == baseline[1]
    assert any("map-0.done.json" in n and "more than" in n and "mapping task 0 again" in n for n in notes), notes


@pytest.mark.parametrize("text", [b"[" * 100_000 + b"]" * 100_000, None], ids=["nested", "oversized"])
def test_a_manifest_too_deep_or_too_large_is_exit_2_naming_it(copy, capsys, text):
    from topomark.proofs.census_integrity import MAX_RECORD_BYTES
    manifest = copy / "manifest.json"
    if text is None:
        with open(manifest, "r+b") as f:
            f.truncate(MAX_RECORD_BYTES + 1)
    else:
        manifest.write_bytes(text)
    assert main([*ARGV, "--shards", str(copy)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "manifest.json: not a census manifest" in err and "Traceback" not in err


# -- the worst case's resume: the same rule ----------------------------------------------------------------
def _worst(root: Path, seed: int | None = None):
    from topomark.reference.worstcase.exhaustive import Setup
    from topomark.reference.worstcase.resumable import worst_case
    found = worst_case(Setup("basic", sample=0), 5, 3, root, task_worlds=4, recheck_seed=seed)
    return {n: (t.max_cost, t.runs, t.argmax_cost) for n, t in found["tallies"].items()}


@pytest.fixture(scope="module")
def worst_dir(tmp_path_factory):
    root = tmp_path_factory.mktemp("worst") / "w"
    return root, _worst(root)


@pytest.fixture
def worst_copy(worst_dir, tmp_path):
    root = tmp_path / "w"
    shutil.copytree(worst_dir[0], root)
    return root


def _worst_unchecked(monkeypatch) -> None:
    from topomark.reference.worstcase import resumable
    monkeypatch.setattr(resumable, "_recheck_kept", lambda *a, **k: None)


def _holding(root: Path, n: int, cost: int) -> int:
    return next(t for t in range(len(_manifest(root)["tasks"]))
                if any(x["n"] == n and x["max_cost"] == cost for x in
                       json.loads((root / f"task-{t}.json").read_text())["tallies"]))


def test_a_resealed_task_file_hiding_the_worst_run_is_refused_whatever_the_seed(worst_dir, worst_copy, monkeypatch):
    """The task holding the largest cost at n = 5 forges it away, consistently (every check of task_record
    holds): the other tasks' largest cost would become the answer, and its re-run argmax would agree."""
    top = worst_dir[1][5][0]
    task = _holding(worst_copy, 5, top)

    def hide(r):
        t = next(x for x in r["tallies"] if x["n"] == 5)
        gone = sum(p[2] for p in t["pairs"] if p[1] >= 20)
        t["pairs"] = [p for p in t["pairs"] if p[1] < 20]
        t.update(runs=t["runs"] - gone, max_cost=max(p[1] for p in t["pairs"]))
        t["outcomes"]["correct"] -= gone
        best = max(t["pairs"], key=lambda p: p[1] / p[0])
        t["cost_m"] = [best[1], best[0]]
    _reseal(worst_copy / f"task-{task}.json", hide)
    with monkeypatch.context() as m:
        _worst_unchecked(m)
        assert _worst(worst_copy)[5][0] < top  # the forgery changes the answer without the re-check
    tasks = len(_manifest(worst_copy)["tasks"])
    with pytest.raises(InvalidInput, match=rf"task-{task}\.json: task {task} run again does not give what the file"):
        _worst(worst_copy, seed=_seed_missing(tasks, task))


def test_a_resealed_task_file_with_other_counts_is_refused_when_drawn(worst_dir, worst_copy, monkeypatch):
    task = _holding(worst_copy, 4, 10)  # not the task of any maximum: only the sample finds it

    def more(r):
        t = next(x for x in r["tallies"] if x["n"] == 4)
        t["pairs"][0][2] += 1
        t["runs"] += 1
        t["outcomes"]["correct"] += 1
    _reseal(worst_copy / f"task-{task}.json", more)
    with monkeypatch.context() as m:
        _worst_unchecked(m)
        assert _worst(worst_copy)[4][1] == worst_dir[1][4][1] + 1
    tasks = len(_manifest(worst_copy)["tasks"])
    assert _worst(worst_copy, seed=_seed_missing(tasks, task))[4][1] == worst_dir[1][4][1] + 1  # a sample
    with pytest.raises(InvalidInput, match=rf"task-{task}\.json: task {task} run again"):
        _worst(worst_copy, seed=_seed_drawing(tasks, task))


def test_an_untouched_worst_case_resume_answers_the_same(worst_dir, worst_copy):
    assert _worst(worst_copy) == worst_dir[1]


def test_worst_case_code_version_hashes_every_module_that_decides_a_cost():
    """A resumed worst-case run refuses tasks of other code; every module of proofs/ that the exhaustive runs
    import either is hashed (it decides which worlds and starts run) or is named as infrastructure (scheduling,
    sealing).  Seeded fault: a new proofs/ import in exhaustive.py that is in neither list fails here."""
    import ast
    from pathlib import Path

    from topomark.reference.worstcase import exhaustive, resumable
    imported = set()
    for module in (exhaustive, resumable):
        tree = ast.parse(Path(module.__file__).read_text())
        imported |= {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom) and node.module
                     and node.module.startswith("topomark.proofs.")}
    assert imported, "the exhaustive runs import proofs/"
    assert imported <= set(resumable.CODE_MODULES) | set(resumable.INFRASTRUCTURE), \
        imported - set(resumable.CODE_MODULES) - set(resumable.INFRASTRUCTURE)

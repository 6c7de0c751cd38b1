"""The equality comparisons stored in ``docs/equality-runs/`` (thesis §3.3): the figures the architecture page quotes
are what their sealed task files add up to.

Each directory is one comparison's ``--shards`` directory: a manifest, one sealed file per finished task and, once
every task has finished, the comparison's ``report.json``.  Whatever code wrote them, every file must pass its
seal and belong to its manifest, a finished comparison's tasks must add up to its report, and no comparison may
hold a disagreement.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from topomark.proofs.census_integrity import Damaged, read_record_text
from topomark.reference.engine.equality_store import EqualityStore

RUNS = Path(__file__).resolve().parents[1] / "docs" / "equality-runs"


def _raise(message: str) -> None:
    raise Damaged(message)


def _tally(root: Path) -> tuple[dict, dict[str, int], int, int]:
    """The manifest, the counts summed over the task files, their number and their disagreements; a task file
    that fails its seal or names another comparison is :class:`Damaged`.  The files are read by the store's own
    check (:meth:`EqualityStore.finished`), without its code-digest check: they may be another code's."""
    store = object.__new__(EqualityStore)
    store.root, store.manifest = root, read_record_text((root / "manifest.json").read_text(encoding="utf-8"))
    files = [int(p.stem.split("-")[1]) for p in root.glob("task-*.json")]
    results = store.finished(max(files, default=-1) + 1, _raise)
    counts: dict[str, int] = {}
    for result in results.values():
        for group, count in result["counts"].items():
            counts[group] = counts.get(group, 0) + count
    return store.manifest, counts, len(results), sum(r["disagreement_count"] for r in results.values())


def _name(params: dict) -> str:
    """The directory name a comparison is kept under: ``ALG-nN-dD``, and ``-LIGHTHOUSE`` unless it is the default
    ``directional-vertex`` (the footprint searches, which have none, record the default)."""
    (algorithm,) = params["algorithms"]
    name = f"{algorithm}-n{params['max_vertices']}-d{params['max_degree']}"
    return name if params["lighthouse"] == "directional-vertex" else f"{name}-{params['lighthouse']}"


def _check(root: Path) -> None:
    manifest, counts, tasks, disagreements = _tally(root)
    assert disagreements == 0, f"{root.name}: {disagreements} disagreeing run pairs"
    assert root.name == _name(manifest["params"]), f"{root.name} holds the comparison {_name(manifest['params'])}"
    report = root / "report.json"
    if report.exists():
        data = json.loads(report.read_text(encoding="utf-8"))
        assert data["disagreement_count"] == 0 and data["tasks"] == tasks, root.name
        assert data["by_group"] == counts and data["compared"] == sum(counts.values()), root.name


def test_every_stored_comparison_adds_up_and_has_no_disagreement():
    roots = sorted(p for p in RUNS.iterdir() if p.is_dir())
    assert any((p / "report.json").exists() for p in roots)
    for root in roots:
        _check(root)


@pytest.fixture
def finished(tmp_path):
    source = next(p for p in sorted(RUNS.iterdir()) if (p / "report.json").exists())
    return Path(shutil.copytree(source, tmp_path / source.name))


def test_seeded_fault_an_edited_count_breaks_its_seal(finished):
    path = finished / "task-0.json"
    record = json.loads(path.read_text(encoding="utf-8"))
    group = next(iter(record["result"]["counts"]))
    record["result"]["counts"][group] += 1
    path.write_text(json.dumps(record), encoding="utf-8")
    with pytest.raises(Damaged):
        _check(finished)


def test_seeded_fault_a_missing_task_no_longer_adds_up_to_the_report(finished):
    (finished / "task-0.json").unlink()
    with pytest.raises(AssertionError):
        _check(finished)


def test_seeded_fault_a_resealed_disagreement_is_caught(finished):
    from topomark.proofs.census_shards import seal
    path = finished / "task-0.json"
    record = json.loads(path.read_text(encoding="utf-8"))
    record["result"]["disagreement_count"] = 1
    del record["checksum"]
    path.write_text(json.dumps(seal(record)), encoding="utf-8")
    with pytest.raises(AssertionError, match="disagreeing"):
        _check(finished)


def test_seeded_fault_a_comparison_kept_under_another_lighthouse_name_is_caught(finished):
    renamed = finished.rename(finished.parent / f"{finished.name}-thread")
    with pytest.raises(AssertionError, match="holds the comparison"):
        _check(renamed)

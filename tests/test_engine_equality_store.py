"""The equality comparison resumes from ``--shards DIR``: finished tasks are kept, damaged or foreign task files
run again, and a directory of other options or other code is refused (thesis §3.3)."""

from __future__ import annotations

import json

from topomark.proofs.census_shards import seal, write_json
from topomark.reference.engine import equality_store
from topomark.reference.engine.equality import main as equality_main
from topomark.reference.engine.equality_store import EqualityStore

ARGS = ["--max-vertices", "5", "--max-degree", "3", "--random", "2", "--random-max-vertices", "12", "--json"]


def _run(capsys, root, *extra) -> tuple[int, dict, str]:
    code = equality_main([*ARGS, "--shards", str(root), *extra])
    out, err = capsys.readouterr()
    return code, (json.loads(out) if out else {}), err


def test_a_resumed_comparison_runs_only_what_is_missing_and_counts_the_same(tmp_path, capsys):
    root = tmp_path / "eq"
    code, first, _ = _run(capsys, root)
    assert code == 0 and first["resumed"] == 0 and first["tasks"] == 3 and first["compared"] > 0
    assert _run(capsys, root)[1]["resumed"] == 3  # all kept
    (root / "task-0.json").unlink()  # killed before it ended
    (root / "task-1.json").write_text("{\"truncated", encoding="utf-8")  # killed while writing
    code, again, err = _run(capsys, root)
    assert code == 0 and again["resumed"] == 1 and "task-1.json" in err and "running task 1 again" in err
    for key in ("compared", "by_group", "by_algorithm", "worlds", "disagreement_count"):
        assert again[key] == first[key], key


def test_a_task_file_of_another_comparison_runs_again(tmp_path, capsys):
    root = tmp_path / "eq"
    _run(capsys, root)
    forged = {"comparison": "another", "task": 2, "result": {"counts": {"5": 10**9}, "worlds": 1,
                                                               "disagreement_count": 0, "disagreements": [],
                                                               "disagreement_text": []}}
    write_json(root / "task-2.json", seal(forged))
    code, report, err = _run(capsys, root)
    assert code == 0 and report["resumed"] == 2 and "another comparison or task" in err
    assert report["by_group"]["5"] < 10**9


def test_a_directory_of_other_options_or_other_code_is_bad_input(tmp_path, capsys, monkeypatch):
    root = tmp_path / "eq"
    _run(capsys, root)
    code, _, err = _run(capsys, root, "--seed", "1")
    assert code == 2 and "holds another comparison" in err and "Traceback" not in err
    params = json.loads((root / "manifest.json").read_text())["params"]
    EqualityStore(root, params)  # the same options and code: resumed
    monkeypatch.setattr(equality_store, "CODE_PACKAGES", equality_store.CODE_PACKAGES[:-1])  # other code
    code, _, err = _run(capsys, root)
    assert code == 2 and "holds another comparison" in err
    (tmp_path / "file").write_text("x")
    assert equality_main([*ARGS, "--shards", str(tmp_path / "file" / "eq")]) == 2
    assert "cannot be made" in capsys.readouterr().err

"""The conformance suite the tests share (``default_suite`` in ``conftest.py``): exported whole, and guarded.

The suite is exported once per run and read by several tests; its digest, taken when it was exported, is
compared at the end of each worker's session, so a test that writes into the shared copy fails the run.
"""

from __future__ import annotations

import json

from conftest import tree_digest


def test_the_shared_suite_is_the_whole_default_export(default_suite):
    manifest = json.loads((default_suite / "manifest.json").read_text())
    assert manifest["format"].startswith("topomark/conformance@")
    assert len(manifest["suites"]) >= 2 and (default_suite / "worlds").is_dir()


def test_the_digest_sees_a_changed_byte_an_added_file_and_a_renamed_one(tmp_path):
    """Seeded fault for the teardown guard: each way a test could write into the suite changes its digest."""
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "x.json").write_text("{}")
    before = tree_digest(tmp_path)
    assert tree_digest(tmp_path) == before
    (tmp_path / "a" / "x.json").write_text("{ }")
    changed = tree_digest(tmp_path)
    (tmp_path / "a" / "y.json").write_text("")
    added = tree_digest(tmp_path)
    (tmp_path / "a" / "y.json").rename(tmp_path / "a" / "z.json")
    assert len({before, changed, added, tree_digest(tmp_path)}) == 4

"""The worked example of docs/port-model.md runs as written and prints what the page shows (the harness of
tests/test_doc_blocks.py, with the checkout's ``tests`` folder linked beside ``reference``, since the page reads
the contest maps copied into tests/data/icfpc2025/)."""

from __future__ import annotations

import pytest

import test_doc_blocks
from test_doc_blocks import ROOT, check_page


@pytest.mark.slow
def test_every_block_of_the_port_model_page_runs_as_written(tmp_path, monkeypatch):
    monkeypatch.setattr(test_doc_blocks, "CHECKOUT_LINKS", (*test_doc_blocks.CHECKOUT_LINKS, "tests"))
    check_page(ROOT / "docs" / "port-model.md", tmp_path)


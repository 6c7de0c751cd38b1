"""The thesis is cited by its structure, never by line numbers of a text rendering.

A reader who has the thesis has its sections (§3.3), Cases (§6.2.1 Case 1a), algorithms and their
numbered lines (Algorithm 3.1 line 5), figures, tables, equations ((3.1)) and footnotes — not the line
numbers of some plain-text copy.  These tests fail, naming file and line, when a citation such as
``L`` followed by a line number (or a range of them) appears in any tracked text file of the repository,
or in the JSON the CLI prints for ``claims`` and ``algorithms``.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest

from topomark.reference.claims import ledger
from topomark.reference.cli.main import main

ROOT = Path(__file__).resolve().parents[1]
ROOTS = ("README.md", "CHANGELOG.md", "docs", "spec", "reference", "proofs", "topomark", "tests")
"""Where prose, docstrings, messages and data live (``topomark/spec`` and the like are links, read once)."""
LINE_CITATION = re.compile(r"(?<![\w$\\])L\d{2,4}(?:\s*[–-]\s*L?\d{2,4})?(?!\w)")
"""A thesis line-number citation: ``L`` and a line number of 2–4 digits, maybe a range of two (dash or en dash)."""


def tracked_files(root: Path = ROOT) -> list[Path]:
    """The tracked regular files under :data:`ROOTS` (``git ls-files``; a walk where there is no git)."""
    try:
        names = subprocess.run(["git", "ls-files", "-z", "--", *ROOTS], cwd=root, capture_output=True,
                               check=True).stdout.decode().split("\0")
        paths = [root / n for n in names if n]
    except (OSError, subprocess.CalledProcessError):
        paths = [p for r in ROOTS for p in ([root / r] if (root / r).is_file() else (root / r).rglob("*"))]
    return [p for p in paths if p.is_file() and not p.is_symlink() and "__pycache__" not in p.parts]


def line_citations(path: Path, root: Path = ROOT) -> list[str]:
    """Every line of a text file that cites the thesis by line number, as ``file:line: text``."""
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:  # an image or other binary file
        return []
    return [f"{path.relative_to(root)}:{k}: {line.strip()}" for k, line in enumerate(text.splitlines(), 1)
            if LINE_CITATION.search(line)]


def test_no_tracked_file_cites_the_thesis_by_line_number():
    files = tracked_files()
    assert len(files) > 300 and any(p.name == "claims.toml" for p in files), "the tracked files were not found"
    found = [hit for p in files for hit in line_citations(p)]
    assert not found, ("cite the thesis by section, Case, algorithm line, figure, table, equation or footnote, "
                       "not by line number:\n" + "\n".join(found))


@pytest.mark.parametrize("text", ["(L" + "1506)", "§6.2.1, L" + "1497–L" + "1506", "L" + "220-" + "227, L" + "230",
                                  "as L" + "1663 prints it", "lines = \"L" + "148–L" + "150\""])
def test_a_line_citation_is_found_and_named_by_file_and_line(tmp_path, text):
    page = tmp_path / "docs" / "page.md"
    page.parent.mkdir()
    page.write_text("# A page\n\nSome prose " + text + " and more.\n", encoding="utf-8")
    assert line_citations(page, tmp_path) == [f"docs/page.md:3: Some prose {text} and more."]


@pytest.mark.parametrize("text", ["an L1 norm", "PROTOCOL2", "SUMMARY_64", r"$L_{12}$", "§6.2.1 Case 1a, line 12",
                                  "Algorithm 3.1 line 5", "CL120X", "equation (3.1)"])
def test_what_is_not_a_line_citation_is_not_flagged(tmp_path, text):
    page = tmp_path / "page.md"
    page.write_text(text + "\n", encoding="utf-8")
    assert line_citations(page, tmp_path) == []


def test_a_binary_file_is_skipped(tmp_path):
    image = tmp_path / "plot.png"
    image.write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe L" + b"1506")
    assert line_citations(image, tmp_path) == []


def test_claims_json_cites_by_structure_with_no_lines_field(capsys):
    assert main(["claims", "--json"]) == 0
    out = capsys.readouterr().out
    claims = json.loads(out)["claims"]
    assert claims and all("lines" not in c for c in claims)
    assert all(c["where"] and all(ledger.REFERENCE.fullmatch(w) for w in c["where"]) for c in claims)
    assert not LINE_CITATION.search(out), LINE_CITATION.search(out)


def test_algorithms_json_cites_by_structure(capsys):
    assert main(["algorithms", "--json"]) == 0
    out = capsys.readouterr().out
    assert json.loads(out) and not LINE_CITATION.search(out), LINE_CITATION.search(out)

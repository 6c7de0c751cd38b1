"""Every count the hand-written pages state in prose is the count the code gives.

A number of policies, worlds, marker classes or tests written into a sentence goes stale the day the code
grows one more.  Each such sentence is listed in :data:`COUNTS` with how to compute its number; the test
finds the sentence, reads the number (digits, or a word up to twenty) and compares.  The numbers of the
generated pages (``docs/cli.md``, ``docs/api.md``, ``docs/claims.md``) and of the tutorial's and README's
outputs (``tests/test_doc_blocks.py``) are kept true where they are made.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import SMALL_WORLDS
from topomark.reference.oracle.conformance.cases import POLICIES
from topomark.spec.markerclass import MARKER_CLASSES

ROOT = Path(__file__).resolve().parent.parent
WORDS = ("zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
         "seventeen eighteen nineteen twenty").split()
NUMBER = r"(\d[\d,]*|" + "|".join(WORDS) + ")"


def number(text: str) -> int:
    """``"eight"`` or ``"1,204"`` as an int."""
    return WORDS.index(text.lower()) if text.lower() in WORDS else int(text.replace(",", ""))


def collected(test_file: str) -> int:
    """How many tests pytest collects from ``test_file``."""
    out = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-n", "0", "-p", "no:cacheprovider",
                          test_file], cwd=ROOT, capture_output=True, text=True, timeout=300).stdout
    return int(re.search(r"^(\d+) tests? collected", out, re.MULTILINE).group(1))


def census_classes_without_counterexample(page: str = "") -> int:
    """The classes whose row of largest N in docs/census.md's results table has no counterexample."""
    page = page or (ROOT / "docs" / "census.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| `([\w-]+)` \| (\d+) \|.*?\| ([^|]+) \| [^|]+ \| [^|]+ \| [^|]+ \|$", page, re.MULTILINE)
    largest = {name: found for name, _, found in sorted(rows, key=lambda r: int(r[1]))}
    return sum(found.strip() == "none" for found in largest.values())


COUNTS = [  # (page, the sentence with its number as NUMBER, what the number counts)
    ("docs/implementers.md", rf"cost under {NUMBER} named policies", lambda: len(POLICIES)),
    ("docs/adding-an-algorithm.md", rf"algorithm on the {NUMBER} small worlds of `SMALL_WORLDS`", lambda: len(SMALL_WORLDS)),
    ("docs/census.md", rf"The table stops at n ≤ 9 for all {NUMBER} classes", lambda: len(MARKER_CLASSES)),
    ("docs/census.md", rf"for the {NUMBER} classes should take", lambda: len(MARKER_CLASSES)),
    ("docs/census.md", rf"the {NUMBER} classes with none have none", census_classes_without_counterexample),
    ("docs/checks.md", rf"The file has {NUMBER} tests", lambda: collected("tests/test_every_check_can_fail.py")),
]


@pytest.mark.parametrize("page, sentence, count", COUNTS, ids=lambda x: x if isinstance(x, str) else "")
def test_each_count_in_prose_is_the_code_s(page, sentence, count):
    text = re.sub(r"\s+", " ", (ROOT / page).read_text(encoding="utf-8"))
    m = re.search(sentence, text)
    assert m, f"{page}: no sentence matches {sentence!r}: update COUNTS with the page"
    assert number(m.group(1)) == count(), f"{page}: {m.group(0)!r}, but the code counts {count()}"


def test_a_stale_count_is_found_and_numbers_read_as_words_or_digits():
    assert (number("eight"), number("1,204"), number("Six")) == (8, 1204, 6)
    table = ("| `a` | 8 | 1 | 1 | 1 | 1 | 0 | none | 1 s | 1 s | 1 MB |\n| `a` | 9 | 1 | 1 | 1 | 1 | 2 | (3, 3) vs (4, 4) "
             "| 1 s | 1 s | 1 MB |\n| `b` | 9 | 1 | 1 | 1 | 1 | 0 | none | 1 s | 1 s | 1 MB |\n")
    assert census_classes_without_counterexample(table) == 1  # a's largest N has one, b's none
    m = re.search(COUNTS[0][1], "each with topomark's map, trace and cost under five named policies.")
    assert m and number(m.group(1)) != COUNTS[0][2]()

"""The claims ledger cites only published evidence: each figure and heading it quotes is on the page it names.

A row of ``reference/claims/claims.toml`` (and so of ``docs/claims.md``) cites a page by its path,
``docs/results/table-6.1.md``, and quotes from it in single quotes (``'The claims, and whether they held'``).
The rules, checked on every row:

* **A quote is on its page.**  Each quoted text occurs, word for word, in the last page named before it in
  the same field (:func:`citations`).
* **A figure is on a cited page.**  Each figure of a measured row's evidence and source, and of any text that
  follows a page named in another row, occurs in a page the row names (:func:`figures`: a number, with its
  ``%``; thesis references — ``§6.2``, ``Figure 6.17``, ``Table 4.1``, ``(3.3)``, ``Algorithm 3.1 line 5`` — and
  ``commands`` are not figures).
* **An unpublished sweep says so.**  A measured row that names no page says ``not published`` and gives the
  command that reproduces it, and quotes no figure: there is no page to check one against.  A row that
  speaks of a sweep names the page that publishes it, or says it is not published.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from topomark.reference.claims import ledger

ROOT = Path(__file__).resolve().parents[1]
PAGE = re.compile(r"docs/[\w./-]+\.md")
QUOTE = re.compile(r"(?<![\w])'([^']+)'(?![\w])")
REFERENCE = re.compile(r"`[^`]*`|§[\d.]+|\bline \d+\b|\((?:\d+\.\d+)\)|"
                       r"\b(?:Figures?|Tables?|Algorithms?|Case|Cases|Chapter|Enhancements?|Version|Lemma|Rows?)"
                       r"[ -](?:\d+(?:\.\d+)*)(?:\s*(?:[–-]|…|,|and)\s*\d+(?:\.\d+)*)*|"
                       r"\b[a-z]+\d*(?:[-+][a-z0-9]+)+|\b[a-zA-Z]\s*[=≥≤<>]\s*\d+(?:,\s*\d+)*")
"""What is not a figure: code, thesis references (§6.2, Algorithm 3.1 line 5, (3.3), Figure 6.17, Tables 4.1–4.8), names
(``case-1a``, ``enh3+4``) and parameters (``d = 2``, ``K = 4, 6, 10``)."""
FIGURE = re.compile(r"(?<![\w.,+])[−-]?\d[\d,]*(?:\.\d+)?%?(?!\w)")
UNPUBLISHED = "not published"


def normal(text: str) -> str:
    """Text as compared: one kind of minus, one space for any run of white space."""
    return re.sub(r"\s+", " ", text.replace("−", "-"))


def page_text(path: str) -> str:
    file = ROOT / path
    return normal(file.read_text(encoding="utf-8")) if file.is_file() else ""


def citations(text: str) -> list[tuple[str, str]]:
    """Each quote of ``text`` with the page named last before it (``""`` if none)."""
    found, page = [], ""
    for m in re.finditer(f"{PAGE.pattern}|{QUOTE.pattern}", text):
        if m.group(0).startswith("docs/"):
            page = m.group(0)
        else:
            found.append((page, m.group(1)))
    return found


def figures(text: str) -> list[str]:
    """The figures ``text`` quotes: its numbers once page paths, quotes and thesis references are taken out."""
    bare = QUOTE.sub(" ", REFERENCE.sub(" ", PAGE.sub(" ", normal(text))))
    return [f.rstrip(",") for f in FIGURE.findall(bare)]


def on_page(figure: str, page: str) -> bool:
    return re.search(rf"(?<![\d.,]){re.escape(figure)}(?![\d])", page) is not None


def problems(c: ledger.Claim) -> list[str]:
    """Every way row ``c`` cites what no published page holds."""
    found = []
    texts = {"evidence": c.evidence, "source": c.source}
    pages = sorted({p for t in texts.values() for p in PAGE.findall(t)})
    for name in pages:
        if not (ROOT / name).is_file():
            found.append(f"{c.id}: cites {name}, which does not exist")
    for field, text in texts.items():
        for page, quote in citations(text):
            if not page:
                found.append(f"{c.id}: {field} quotes {quote!r} from no page")
            elif normal(quote) not in page_text(page):
                found.append(f"{c.id}: {field} quotes {quote!r}, which {page} does not hold")
    checked = " ".join(texts.values()) if c.backing == "measured" else " ".join(
        t[t.index(m.group(0)):] for t in texts.values() for m in [PAGE.search(t)] if m)
    published = " ".join(page_text(p) for p in pages)
    says_unpublished = UNPUBLISHED in c.source or UNPUBLISHED in c.evidence
    for figure in figures(" ".join(texts.values()) if says_unpublished else checked):
        if says_unpublished:
            found.append(f"{c.id}: quotes the figure {figure} of evidence it says is not published")
        elif not pages or not on_page(figure.replace("−", "-"), published):
            found.append(f"{c.id}: the figure {figure} is on no page it cites ({', '.join(pages) or 'none'})")
    if c.backing == "measured" and not pages and not says_unpublished:
        found.append(f"{c.id}: a measurement that names no published page and does not say it is not published")
    if says_unpublished and "`topomark " not in c.source + c.evidence:
        found.append(f"{c.id}: says its evidence is not published but gives no command that reproduces it")
    if "sweep" in " ".join(texts.values()) and not pages and not says_unpublished:
        found.append(f"{c.id}: speaks of a sweep but names no page that publishes it")
    return found


def test_every_quote_and_figure_the_ledger_cites_is_on_its_page():
    found = [p for c in ledger.load() for p in problems(c)]
    assert not found, f"{len(found)} citations of reference/claims/claims.toml hold nothing published:\n" + \
        "\n".join(found)


def claim(**fields) -> ledger.Claim:
    row = {"id": "x", "section": "§4.1", "where": ("§4.1",), "claim": "c", "backing": "measured", "verdict": "held",
           "experiments": ("table-4.1",), "command": "topomark bench table-4.1"} | fields
    return ledger.Claim(**row)


@pytest.mark.parametrize("row, problem", [
    (claim(evidence="ok", source="docs/results/tables.md, 'No such heading'"), "does not hold"),
    (claim(evidence="ok", source="docs/results/no-such-page.md"), "does not exist"),
    (claim(evidence="Reductions 99.9% and 12.3%.", source="docs/results/tables.md, 'enh1'"), "figure 99.9%"),
    (claim(evidence="A reduction of 50.0%.", source="the full sweep"), "figure 50.0%"),
    (claim(evidence="Held.", source="the full sweep of `topomark bench tables`"), "does not say"),
    (claim(evidence="Held.", source="not published"), "no command"),
    (claim(evidence="Reductions of 50.0%.", source="not published; reproduce with `topomark bench tables`"),
     "figure 50.0% of evidence it says is not published"),
    (claim(backing="tested", evidence="The sweep found none.", source=""), "speaks of a sweep"),
    (claim(backing="proved", evidence="Up to n = 9 (docs/census.md, 'Results past n = 7', 123,456 worlds)"),
     "figure 123,456"),
])
def test_each_rule_finds_its_fault(row, problem):
    assert any(problem in p for p in problems(row)), problems(row)


def test_a_row_that_cites_what_its_page_holds_passes_and_references_are_not_figures():
    text = page_text("docs/census.md")
    worlds = re.search(r"\| `none` \| 9 \| ([\d,]+) \|", text).group(1)  # a figure the page holds
    good = claim(backing="proved", evidence=f"Up to n = 9 (docs/census.md, 'Results past n = 7': {worlds} worlds)")
    assert problems(good) == []
    assert problems(claim(evidence="Held.", source=f"{UNPUBLISHED}; reproduce with `topomark bench tables`")) == []
    assert figures("§6.2.1, Figure 6.17, Tables 4.1–4.8, (3.3), Algorithm 3.1 line 5, `bench table-6.1`, case-1a, enh3+4, d = 2, "
                   "K = 4, 6, 10, 3m: 1.026 / 0.957 and 85–98%, −1,487%") == ["1.026", "0.957", "85", "98%", "-1,487%"]

"""How the bench reports write numbers, verdicts and Markdown tables.

Part of the report kit (:mod:`~topomark.reference.bench.reports.kit`): one way to
write a count of moves (``12,345``), a mean with its standard deviation
(``12,345 ± 678``), a percentage, a yes/no verdict, and a table.

Examples
--------
>>> fmt(12345.6), fmt_pm(1500, 707.1), pct(67.54), pct(None)
('12,346', '1,500 ± 707', '67.5%', '')
>>> yes(True), yes(False), yes(None)
('yes', '**no**', '—')
>>> table("| size | cost |", "|---:|---:|", [row(72, fmt(3178))])
['| size | cost |', '|---:|---:|', '| 72 | 3,178 |', '']
"""

from __future__ import annotations

__all__ = ["fmt", "fmt_pm", "pct", "yes", "row", "table"]


def fmt(x: float) -> str:
    """A number of moves (or markers), rounded, with thousands separators."""
    return f"{x:,.0f}"


def fmt_pm(mean: float, sd: float) -> str:
    """A mean ± standard deviation, both as :func:`fmt`."""
    return f"{fmt(mean)} ± {fmt(sd)}"


def pct(x: float | None) -> str:
    """A percentage to one decimal ("" for none)."""
    return "" if x is None else f"{x:.1f}%"


def yes(ok: bool | None) -> str:
    """A verdict cell: yes, a bold no, or a dash where there is nothing to judge."""
    return "—" if ok is None else "yes" if ok else "**no**"


def row(*cells: object) -> str:
    """A Markdown table row of these cells."""
    return "| " + " | ".join(map(str, cells)) + " |"


def table(head: str, align: str, rows: list[str]) -> list[str]:
    """A Markdown table: its header row, its alignment row, its rows and the blank line that ends it."""
    return [head, align, *rows, ""]

"""The claims ledger: every theorem, lemma, stated bound and experimental statement of the thesis
(§2.3.1 and Chapters 3–6), each with its section and lines, and how topomark backs it.

The rows are data, in ``claims.toml`` beside this module; this module reads them into
:class:`Claim` records, one per claim, and counts them (:func:`summary`).  A claim is backed
in one of six ways (:data:`BACKINGS`):

* ``proved`` — by the census or Z3 (``topomark census``/``search``), up to the n the row states;
* ``checked`` — in every checked run, by the named checks of
  :data:`topomark.reference.algorithms.algorithm_spec.CHECKS`;
* ``tested`` — by the named tests (``tests/FILE.py::FUNCTION``);
* ``measured`` — by a bench experiment (``topomark bench EXPERIMENT``), with the verdict its report
  gives: ``held``, ``not held``, or ``partly held`` where it held on one world family and not on the
  other (the thesis states it for both).  Its ``source`` names the published page (``docs/results/...``)
  and quotes its headings and figures, or says ``not published`` and gives the command that reproduces
  it (``tests/test_claims_evidence.py`` checks every quote and figure against its page);
* ``assumed`` — taken as given (a result the thesis cites from the literature), with why;
* ``unbacked`` — nothing in topomark backs it, and the row says why.

A ``proved`` or ``tested`` row whose evidence contradicts the thesis as printed (a stated count one
short, say) carries ``verdict = "not held"``; the row's ``evidence`` says what holds instead.
Every row carries the command that reproduces its evidence (``assumed`` and ``unbacked`` rows none).

Examples
--------
>>> claims = load()
>>> len({c.id for c in claims}) == len(claims)
True
>>> next(c for c in claims if c.id == "3.4-lemma-1").backing
'checked'
>>> Claim.from_row({"id": "x", "section": "§9", "lines": "L1", "claim": "c", "backing": "hoped"})
Traceback (most recent call last):
...
topomark.spec.errors.TopomarkFault: claims.toml: claim 'x': backing 'hoped' is not one of proved, checked, tested, measured, assumed, unbacked
"""

from __future__ import annotations

import tomllib
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from topomark.spec.errors import TopomarkFault

__all__ = ["Claim", "BACKINGS", "VERDICTS", "DATA", "load", "summary", "chapter_of"]

BACKINGS = ("proved", "checked", "tested", "measured", "assumed", "unbacked")
"""The ways a claim is backed, strongest first."""

VERDICTS = ("held", "partly held", "not held")
"""What a measurement (or a test that contradicts the thesis) says of the claim."""

DATA = Path(__file__).with_name("claims.toml")
"""The ledger's rows."""

_FIELDS = ("id", "section", "lines", "claim", "backing", "evidence", "command", "verdict", "source", "checks",
           "tests", "experiments")


def chapter_of(section: str) -> int:
    """The chapter a section lies in: ``chapter_of("§6.2.1") == 6``; a table or figure counts by its number."""
    digits = section.lstrip("§").replace("Table ", "").replace("Figure ", "").split(".")[0]
    return int(digits)


@dataclass(frozen=True)
class Claim:
    """One claim of the thesis and its backing."""

    id: str
    section: str
    lines: str
    claim: str
    backing: str
    evidence: str = ""
    command: str = ""
    verdict: str = ""
    source: str = ""
    checks: tuple[str, ...] = field(default_factory=tuple)
    tests: tuple[str, ...] = field(default_factory=tuple)
    experiments: tuple[str, ...] = field(default_factory=tuple)

    @property
    def chapter(self) -> int:
        return chapter_of(self.section)

    @classmethod
    def from_row(cls, row: dict) -> "Claim":
        """A row of ``claims.toml``, its fields checked: a malformed ledger is a fault of topomark."""
        name = row.get("id", "?")
        unknown = sorted(set(row) - set(_FIELDS))
        if unknown:
            raise TopomarkFault(f"claims.toml: claim {name!r}: unknown fields {unknown}")
        if row.get("backing") not in BACKINGS:
            raise TopomarkFault(f"claims.toml: claim {name!r}: backing {row.get('backing')!r} is not one of "
                                + ", ".join(BACKINGS))
        fields: dict[str, Any] = {k: tuple(v) if isinstance(v, list) else v for k, v in row.items()}
        claim = cls(**fields)
        claim._validate()
        return claim

    def _validate(self) -> None:
        need = {"proved": self.command, "checked": self.checks and self.command, "tested": self.tests,
                "measured": self.experiments and self.verdict and self.source and self.command,
                "assumed": self.evidence, "unbacked": self.evidence}[self.backing]
        if not need:
            raise TopomarkFault(f"claims.toml: claim {self.id!r}: a {self.backing} claim needs its evidence "
                                "(checks and a command, tests, experiments with a verdict, source and command, "
                                "or the reason)")
        if self.verdict and self.verdict not in VERDICTS:
            raise TopomarkFault(f"claims.toml: claim {self.id!r}: verdict {self.verdict!r} is not one of "
                                + ", ".join(VERDICTS))

    def reproduce(self) -> str:
        """The command that reproduces the evidence: the row's, else the tests it names."""
        if self.command:
            return self.command
        return "python -m pytest -q " + " ".join(self.tests) if self.tests else ""

    def to_json(self) -> dict:
        return {"id": self.id, "chapter": self.chapter, "section": self.section, "lines": self.lines,
                "claim": self.claim, "backing": self.backing, "evidence": self.evidence,
                "verdict": self.verdict or None, "source": self.source or None, "checks": list(self.checks),
                "tests": list(self.tests), "experiments": list(self.experiments), "reproduce": self.reproduce()}


def load(path: Path = DATA) -> list[Claim]:
    """Every claim of the ledger, in the thesis's order; ids are unique."""
    rows = tomllib.loads(path.read_text(encoding="utf-8")).get("claim", [])
    claims = [Claim.from_row(row) for row in rows]
    repeated = sorted(k for k, v in Counter(c.id for c in claims).items() if v > 1)
    if repeated:
        raise TopomarkFault(f"claims.toml: claim ids used twice: {repeated}")
    return claims


def summary(claims: list[Claim]) -> dict[int, dict[str, int]]:
    """Per chapter, how many claims are backed each way, and the measured ones by verdict.

    >>> s = summary([Claim("a", "§3.1", "L1", "c", "measured", verdict="held"),
    ...              Claim("b", "§3.2", "L2", "c", "assumed")])
    >>> s[3]["measured"], s[3]["measured held"], s[3]["assumed"], s[3]["total"]
    (1, 1, 1, 2)
    """
    out: dict[int, dict[str, int]] = {}
    for c in claims:
        row = out.setdefault(c.chapter, {"total": 0, **{b: 0 for b in BACKINGS},
                                         **{f"measured {v}": 0 for v in VERDICTS}, "contradicted": 0})
        row["total"] += 1
        row[c.backing] += 1
        if c.backing == "measured":
            row[f"measured {c.verdict}"] += 1
        elif c.verdict == "not held":
            row["contradicted"] += 1
    return dict(sorted(out.items()))

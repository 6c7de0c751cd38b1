"""The claims ledger: every theorem, lemma, stated bound and experimental statement of the thesis
(§2.3.1 and Chapters 3–6), each with its section, where in the thesis it is stated, and how topomark
backs it.

The rows are data, in ``claims.toml`` beside this module; this module reads them into
:class:`Claim` records, one per claim, and counts them (:func:`summary`).  A claim's ``where`` lists
the places of the thesis that state it, each a reference a reader can look up (:data:`REFERENCE`):
a section (``"§3.5.2"``), a Case of §6.2.1 (``"§6.2.1 Case 1a"``), ``"§3.4 Lemma 1"``, an algorithm's
line (``"Algorithm 3.1 line 5"``), a figure, table, equation (``"equation (3.1)"``) or footnote
(``"§3.5.1 footnote 10"``).  A claim is backed
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
>>> next(c for c in claims if c.id == "3.5.2-upper-bound").thesis
'§3.5.2, equations (3.1) and (3.2)'
>>> Claim.from_row({"id": "x", "section": "§9", "where": ["§9"], "claim": "c", "backing": "hoped"})
Traceback (most recent call last):
...
topomark.spec.errors.TopomarkFault: claims.toml: claim 'x': backing 'hoped' is not one of proved, checked, tested, measured, assumed, unbacked
>>> Claim.from_row({"id": "x", "section": "§9", "where": ["line 12"], "claim": "c", "backing": "assumed",
...                 "evidence": "cited"})
Traceback (most recent call last):
...
topomark.spec.errors.TopomarkFault: claims.toml: claim 'x': where 'line 12' is not a thesis reference (a section, Case, Lemma, algorithm line, figure, table, equation or footnote)
"""

from __future__ import annotations

import re
import tomllib
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from topomark.spec.errors import TopomarkFault

__all__ = ["Claim", "BACKINGS", "VERDICTS", "REFERENCE", "DATA", "load", "summary", "chapter_of"]

BACKINGS = ("proved", "checked", "tested", "measured", "assumed", "unbacked")
"""The ways a claim is backed, strongest first."""

VERDICTS = ("held", "partly held", "not held")
"""What a measurement (or a test that contradicts the thesis) says of the claim."""

REFERENCE = re.compile(r"(§\d+(\.\d+)*( (Case \d+[ab]?|Cases \d+[ab]?(–\d+[ab]?)?|Lemma \d+|footnote \d+))?"
                       r"|Chapter \d+|Algorithm \d+\.\d+( lines? \d+(–\d+)?)?"
                       r"|(Figures?|Tables?) \d+\.\d+(\([a-z]\))?(–\d+\.\d+)?|equations? \(\d+\.\d+\)( and \(\d+\.\d+\))?)")
"""A reference into the thesis's structure, as ``where`` gives it: the finest unit that states the claim."""

DATA = Path(__file__).with_name("claims.toml")
"""The ledger's rows."""

_FIELDS = ("id", "section", "where", "claim", "backing", "evidence", "command", "verdict", "source", "checks",
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
    where: tuple[str, ...]
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

    @property
    def thesis(self) -> str:
        """The section and the places that state the claim, each once: ``"§6.2.1 Case 1a, Figure 6.4"``."""
        covered = any(w == self.section or w.startswith((self.section + " ", self.section + "."))
                      or (w.startswith("Chapter ") and "§" + w[8:] == self.section) for w in self.where)
        finer = [w for w in self.where if not any(x.startswith(w + " ") for x in self.where)]
        return ", ".join(([] if covered else [self.section]) + finer)

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
        if not self.where:
            raise TopomarkFault(f"claims.toml: claim {self.id!r}: where is empty: name the places that state it")
        for w in self.where:
            if not isinstance(w, str) or not REFERENCE.fullmatch(w):
                raise TopomarkFault(f"claims.toml: claim {self.id!r}: where {w!r} is not a thesis reference (a section, "
                                    "Case, Lemma, algorithm line, figure, table, equation or footnote)")
        if self.verdict and self.verdict not in VERDICTS:
            raise TopomarkFault(f"claims.toml: claim {self.id!r}: verdict {self.verdict!r} is not one of "
                                + ", ".join(VERDICTS))

    def reproduce(self) -> str:
        """The command that reproduces the evidence: the row's, else the tests it names."""
        if self.command:
            return self.command
        return "python -m pytest -q " + " ".join(self.tests) if self.tests else ""

    def to_json(self) -> dict:
        return {"id": self.id, "chapter": self.chapter, "section": self.section, "where": list(self.where),
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

    >>> s = summary([Claim("a", "§3.1", ("§3.1",), "c", "measured", verdict="held"),
    ...              Claim("b", "§3.2", ("§3.2",), "c", "assumed")])
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

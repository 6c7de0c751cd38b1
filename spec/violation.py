"""A failed check described: which condition, where, what it demanded and what was there.

A :class:`~topomark.spec.errors.CheckFailure` carries one (exit 1).  ``topomark.spec.errors.Violation`` is
this class too, imported from here when first used.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

__all__ = ["Violation"]


@dataclass(frozen=True)
class Violation:
    """A structured description of a failed check.

    ``check`` names the condition (``"I-1"``, ``"I-2"``, ``"isomorphism"``,
    ``"Lemma 1"`` ...), ``where`` the offending vertex or dart, and
    ``expected``/``found`` what the condition demanded and what was there.
    """

    check: str
    where: str
    expected: str
    found: str
    detail: str = ""
    data: dict[str, Any] = field(default_factory=dict, compare=False)

    def __str__(self) -> str:
        text = f"{self.check} violated at {self.where}: expected {self.expected}, found {self.found}"
        return f"{text} ({self.detail})" if self.detail else text

    def to_json(self) -> dict[str, Any]:
        return {
            "check": self.check,
            "where": self.where,
            "expected": self.expected,
            "found": self.found,
            "detail": self.detail,
        }

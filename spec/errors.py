"""The two kinds of failure topomark keeps apart.

* :class:`InvalidInput` (and its child :class:`InvalidWorld`): what the user gave
  us is not a valid world, map, motion or option.  The CLI exits with code 2.
* :class:`CheckFailure`: a loop invariant (thesis §3.4), an isomorphism or an
  internal consistency check failed.  That means an *implementation* is wrong.
  The CLI exits with code 1.

Checks are made with :func:`require`, never with bare ``assert`` statements, so
they survive ``python -O``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

__all__ = [
    "TopomarkError",
    "InvalidInput",
    "InvalidWorld",
    "Violation",
    "CheckFailure",
    "require",
    "require_input",
]


class TopomarkError(Exception):
    """Base class of every error topomark raises on purpose."""


class InvalidInput(TopomarkError, ValueError):
    """Input that is not acceptable: the CLI reports it and exits 2."""


class InvalidWorld(InvalidInput):
    """A rotation system, marker or start that violates §3.1.1."""


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


class CheckFailure(TopomarkError, AssertionError):
    """A violated invariant or failed internal check: the CLI exits 1."""

    def __init__(self, violation: Violation | str):
        if isinstance(violation, str):
            violation = Violation("internal check", "-", "true", "false", violation)
        self.violation = violation
        super().__init__(str(violation))


def require(condition: bool, message: str) -> None:
    """Raise :class:`CheckFailure` with ``message`` unless ``condition`` holds.

    Unlike ``assert``, this is not removed by ``python -O``.
    """
    if not condition:
        raise CheckFailure(message)


def require_input(condition: bool, message: str, kind: type[InvalidInput] = InvalidInput) -> None:
    """Raise ``kind`` (an :class:`InvalidInput`) with ``message`` unless ``condition`` holds."""
    if not condition:
        raise kind(message)

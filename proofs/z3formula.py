"""The propositional formula builder of the Z3 search (:mod:`topomark.proofs.z3search`, thesis §3.2, §3.7, §6.1).

Formulas are built as SMT-LIB text (literals are symbol names or Python
bools) and handed to Z3 in one piece: far faster than one Python API call
per clause.  :class:`Builder` collects declarations and assertions, with
one-hot variables as dicts value -> literal; the connectives fold the
constants ``True``/``False`` away.
"""

from __future__ import annotations

import re
from typing import Iterable

from topomark.spec.errors import CheckFailure

__all__ = ["Builder", "literal", "or_", "and_", "not_", "iff"]  # for the z3search modules


class Builder:
    """Collects declarations and assertions; one-hot variables are dicts value -> literal."""

    def __init__(self):
        self.decls: list[str] = []
        self.asserts: list[str] = []
        self._names: set[str] = set()

    @property
    def count(self) -> int:
        return len(self.asserts)

    def var(self, name: str) -> str:
        name = re.sub(r"[^A-Za-z0-9_]", "_", name)
        if name in self._names:
            raise CheckFailure(f"encoding bug: variable {name} declared twice")
        self._names.add(name)
        self.decls.append(f"(declare-const {name} Bool)")
        return name

    def add(self, *constraints) -> None:
        for c in constraints:
            if c is True:
                continue
            self.asserts.append(f"(assert {'false' if c is False else c})")

    def onehot(self, name: str, values: Iterable) -> dict:
        vs = {c: self.var(f"{name}_{c}") for c in values}
        lits = list(vs.values())
        self.add(or_(lits))
        if len(lits) > 1:
            self.asserts.append(f"(assert ((_ at-most 1) {' '.join(lits)}))")
        return vs

    def implies(self, premises: list, conclusion) -> None:
        """Clause: AND premises => conclusion (constant premises folded)."""
        ps = [p for p in premises if p is not True]
        if any(p is False for p in ps) or conclusion is True:
            return
        self.add(or_([not_(p) for p in ps] + [conclusion]))

    def text(self) -> str:
        return "\n".join(self.decls + self.asserts)


def literal(onehot: dict, value):
    """The literal 'variable = value' (False if the value is outside the domain)."""
    return onehot.get(value, False)


def _connective(op: str, unit: bool, items):
    """``(op items...)`` simplified: ``unit`` items dropped, the absorbing ``not unit`` wins, arity 0/1 collapsed."""
    items = [x for x in items if x is not unit]
    if any(x is (not unit) for x in items):
        return not unit
    if not items:
        return unit
    return items[0] if len(items) == 1 else f"({op} {' '.join(items)})"


def or_(items):
    return _connective("or", False, items)


def and_(items):
    return _connective("and", True, items)


def not_(x):
    if isinstance(x, bool):
        return not x
    return x[5:-1] if x.startswith("(not ") else f"(not {x})"


def iff(a, b):
    if isinstance(a, bool) and isinstance(b, bool):
        return a == b
    if isinstance(a, bool):
        return b if a else not_(b)
    if isinstance(b, bool):
        return a if b else not_(a)
    return f"(= {a} {b})"


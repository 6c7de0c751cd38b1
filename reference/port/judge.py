"""The exact judge of two port worlds: equivalent, or different with a plan that tells them apart.

Two maps are *equivalent* when no plan — charcoal marks included — gives different records on them, and they have
the same number of rooms (the contest's rule: a guess with another room count is wrong).  :func:`judge` decides it
exactly, with two independent deciders for each step, and a witness replayed on both maps before it is returned:

1. Without marks (:mod:`.plain`): partition refinement and a breadth-first search of the pair product must agree;
   the search gives the **shortest plan without marks** that separates the maps, the witness when there is one.
2. With marks (:mod:`.rooted`): when no plan without marks separates them, the maps are equivalent exactly when they
   are rootedly isomorphic (doors, targets and colours; breadth-first mapping and canonical forms must agree).
   Otherwise the witness is the shortest plan with **one** mark that separates them, which always exists when the
   alphabet has two colours or more (the proof is on the port judge's docs page).

A disagreement between two deciders, or a witness whose records do not differ when replayed with
:func:`topomark.spec.port_plan.run_plan`, is a :class:`~topomark.spec.errors.TopomarkFault` (exit 3).

>>> from topomark.reference.port.generate import random_port_world, cover
>>> base = random_port_world(3, rooms=4)
>>> v = judge(base, cover(base, 2, seed=5))
>>> v.equivalent, "[" in v.witness, v.records[0] != v.records[1]
(False, True, True)
>>> judge(base, base)
Verdict(equivalent=True, witness=None, records=None, reason='the maps are rootedly isomorphic: no plan tells them apart')
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.reference.port.plain import refine, separating_word
from topomark.reference.port.rooted import canonical_form, isomorphism, marked_witness
from topomark.spec.errors import TopomarkFault
from topomark.spec.port_plan import Action, parse_plan, run_plan
from topomark.spec.port_world import PortWorld

__all__ = ["Verdict", "judge", "replayed"]


@dataclass(frozen=True)
class Verdict:
    """What :func:`judge` found."""

    equivalent: bool
    witness: str | None
    """Plan text (:mod:`topomark.spec.port_plan` syntax) telling the maps apart, replayed; ``None`` if equivalent
    (or, for maps of different room counts, when no plan tells them apart)."""
    records: tuple[tuple[int, ...], tuple[int, ...]] | None
    """The witness's record on the first map and on the second."""
    reason: str
    """One sentence: why."""


def judge(a: PortWorld, b: PortWorld, *, echo_marks: bool = True, names: tuple[str, str] = ("a", "b")) -> Verdict:
    """Judge ``a`` against ``b`` (see the module's docstring); ``names`` name the maps in a fault report."""
    plain_equal, _ = refine(a, b)
    word = separating_word(a, b)
    _agree(plain_equal, word is None, "partition refinement and the pair-product search", names)
    if word is not None:
        plan = "".join(map(str, word))
        return _different(a, b, plan, echo_marks, names, "the shortest plan without marks that separates them")
    iso = isomorphism(a, b) is not None
    _agree(iso, canonical_form(a) == canonical_form(b), "breadth-first mapping and canonical forms", names)
    if iso:
        return Verdict(True, None, None, "the maps are rootedly isomorphic: no plan tells them apart")
    found = marked_witness(a, b)
    if found is not None:
        u, c, x = found
        plan = "".join(map(str, u)) + f"[{c}]" + "".join(map(str, x))
        return _different(a, b, plan, echo_marks, names,
                          "no plan without marks separates them; this plan with one mark does")
    if min(a.alphabet, b.alphabet) >= 2 and a.doors == b.doors:
        raise TopomarkFault(f"{names[0]} and {names[1]}: plainly equivalent, not rootedly isomorphic, yet no plan "
                            "with one mark separates them (the docs prove one does)", "one-mark witness exists")
    if a.rooms != b.rooms:
        return Verdict(False, None, None, f"room counts differ ({a.rooms} and {b.rooms}) though no plan tells the "
                       "maps apart")
    if a.doors != b.doors:
        return Verdict(False, None, None, f"door counts differ ({a.doors} and {b.doors}) though no plan valid on "
                       "both tells the maps apart")
    return Verdict(True, None, None, "with a one-colour alphabet marks show nothing, and no plan without marks "
                   "separates the maps")


def _agree(first: bool, second: bool, deciders: str, names: tuple[str, str]) -> None:
    if first != second:
        raise TopomarkFault(f"{names[0]} and {names[1]}: {deciders} disagree ({first} and {second})",
                            "port deciders agree")


def replayed(a: PortWorld, b: PortWorld, plan: str, *, echo_marks: bool = True
             ) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """The records of ``plan`` on ``a`` and on ``b``; a :class:`TopomarkFault` when they do not differ."""
    doors, colours = min(a.doors, b.doors), min(a.alphabet, b.alphabet)
    actions: tuple[Action, ...] = parse_plan(plan, doors=doors, alphabet=colours)
    records = (run_plan(a, actions, echo_marks=echo_marks), run_plan(b, actions, echo_marks=echo_marks))
    if records[0] == records[1]:
        raise TopomarkFault(f"the witness {plan!r} gives the same record on both maps", "witness replays")
    return records


def _different(a: PortWorld, b: PortWorld, plan: str, echo_marks: bool, names: tuple[str, str],
               reason: str) -> Verdict:
    try:
        records = replayed(a, b, plan, echo_marks=echo_marks)
    except TopomarkFault as e:
        raise TopomarkFault(f"{names[0]} and {names[1]}: {e}", e.check) from None
    return Verdict(False, plan, records, reason)

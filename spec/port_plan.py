"""Plans and records: what a port robot does and what it senses (the port-labelled model, :mod:`.port_world`).

A **plan** is a string of door digits ``0 .. doors-1``, with **charcoal marks** ``[c]`` between them: a mark
rewrites the colour of the room the robot is in to ``c`` until the plan ends (every plan starts from the world's own
colours).  Running a plan from the start room gives its **record**: the colour of the start room, then, for each
door, the colour of the room the robot enters, as it is at that moment (a room marked earlier in the plan shows its
mark).  The contest's official server also answered each mark with an entry, the colour just written
(``echo_marks=True``, the default here, as that server did); without the echo a record has one entry more than the
plan has doors.

Limits (the contest's task statement): a plan has at most ``factor × rooms`` doors — 18 in the contest's first
round, 6 in its later rounds — and marks do not count; an ``/explore`` call of ``k`` plans costs ``k + 1``
queries (:func:`explore_cost`).

This module defines the semantics; it judges nothing.

Examples
--------
>>> from topomark.spec.port_world import from_joins
>>> w = from_joins([0, 1], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=2)
>>> run_plan(w, parse_plan("0101", doors=2, alphabet=2))
(0, 1, 1, 0, 0)
>>> run_plan(w, parse_plan("[1]00", doors=2, alphabet=2))
(0, 1, 1, 1)
>>> run_plan(w, parse_plan("[1]00", doors=2, alphabet=2), echo_marks=False)
(0, 1, 1)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from topomark.spec.errors import InvalidInput, require_input
from topomark.spec.port_world import CONTEST_ALPHABET, CONTEST_DOORS, PortWorld

__all__ = ["Action", "InvalidPlan", "parse_plan", "plan_text", "run_plan", "doors_in", "check_length",
           "explore_cost", "ROUND_FACTORS", "MAX_PLAN_TEXT"]

MAX_PLAN_TEXT = 1_000_000
"""The longest plan text read at all, before its length is checked against a world (no world of
:data:`~topomark.spec.port_world.MAX_ROOMS` rooms needs more at 6 doors a room)."""

ROUND_FACTORS = {"lightning": 18, "full": 6}
"""Doors a plan may have per room of the world, by the contest's round: 18n in its first (lightning) round, 6n in
the full contest."""


class InvalidPlan(InvalidInput):
    """A plan that is not in the plan syntax, names a door or colour outside the world's, or is over its limit."""


@dataclass(frozen=True)
class Action:
    """One step of a plan: ``kind`` ``"door"`` (go through door ``value``) or ``"mark"`` (rewrite the current
    room's colour to ``value``)."""

    kind: str
    value: int


def parse_plan(text: str, *, doors: int = CONTEST_DOORS, alphabet: int = CONTEST_ALPHABET) -> tuple[Action, ...]:
    """The actions of plan ``text``; :class:`InvalidPlan` names the first character that is not a door digit
    below ``doors`` or a mark ``[c]`` with ``c`` below ``alphabet``.

    >>> [(a.kind, a.value) for a in parse_plan("0[2]5")]
    [('door', 0), ('mark', 2), ('door', 5)]
    >>> parse_plan("07")
    Traceback (most recent call last):
    ...
    topomark.spec.port_plan.InvalidPlan: plan character 2 ('7') is not a door (doors 0..5) or a mark [c]
    """
    require_input(isinstance(text, str), f"a plan is a string, not {type(text).__name__}", InvalidPlan)
    require_input(len(text) <= MAX_PLAN_TEXT, f"a plan of {len(text):,} characters is over the {MAX_PLAN_TEXT:,} "
                  "read at all", InvalidPlan)
    actions: list[Action] = []
    k = 0
    while k < len(text):
        ch = text[k]
        if ch == "[":
            close = text.find("]", k)
            inner = text[k + 1:close] if close > 0 else ""
            require_input(close > 0 and inner.isascii() and inner.isdigit() and len(inner) <= 18
                          and int(inner) < alphabet,
                          f"plan character {k + 1} starts a mark that is not [c] with a colour c in 0..{alphabet - 1}",
                          InvalidPlan)
            actions.append(Action("mark", int(inner)))
            k = close + 1
            continue
        require_input(ch.isascii() and ch.isdigit() and int(ch) < doors,
                      f"plan character {k + 1} ({ch!r}) is not a door (doors 0..{doors - 1}) or a mark [c]",
                      InvalidPlan)
        actions.append(Action("door", int(ch)))
        k += 1
    return tuple(actions)


def plan_text(actions: Sequence[Action]) -> str:
    """The plan text of ``actions`` (inverse of :func:`parse_plan`).

    >>> plan_text(parse_plan("1[3]20"))
    '1[3]20'
    """
    return "".join(str(a.value) if a.kind == "door" else f"[{a.value}]" for a in actions)


def doors_in(actions: Sequence[Action]) -> int:
    """How many doors a plan goes through (what its length limit counts)."""
    return sum(1 for a in actions if a.kind == "door")


def check_length(actions: Sequence[Action], rooms: int, round_name: str = "full") -> None:
    """Refuse a plan with more doors than the round allows for a world of ``rooms`` rooms (:data:`ROUND_FACTORS`).

    >>> check_length(parse_plan("0" * 19), 3)
    Traceback (most recent call last):
    ...
    topomark.spec.port_plan.InvalidPlan: the plan has 19 doors, over the full round's limit of 18 (6 × 3 rooms)
    """
    factor = ROUND_FACTORS[round_name]
    count = doors_in(actions)
    require_input(count <= factor * rooms, f"the plan has {count:,} doors, over the {round_name} round's limit of "
                  f"{factor * rooms:,} ({factor} × {rooms} rooms)", InvalidPlan)


def run_plan(world: PortWorld, actions: Sequence[Action], *, echo_marks: bool = True) -> tuple[int, ...]:
    """The record of ``actions`` run from ``world``'s start room (see the module's docstring)."""
    marked: dict[int, int] = {}
    room = world.start
    record = [world.colours[room]]
    for action in actions:
        if action.kind == "door":
            require_input(0 <= action.value < world.doors, f"door {action.value} is not a door of this world "
                          f"(doors 0..{world.doors - 1})", InvalidPlan)
            room = world.target(room, action.value)
            record.append(marked.get(room, world.colours[room]))
        else:
            require_input(0 <= action.value < world.alphabet, f"colour {action.value} is outside this world's "
                          f"alphabet 0..{world.alphabet - 1}", InvalidPlan)
            marked[room] = action.value
            if echo_marks:
                record.append(action.value)
    return tuple(record)


def explore_cost(plans: int) -> int:
    """Queries an ``/explore`` call of ``plans`` plans costs: one per plan and one for the call."""
    return plans + 1

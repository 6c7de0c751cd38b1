"""Robot semantics: states, motions and perception sequences (thesis §3.1.1).

A robot *state* is ``(vertex, entry)``: the vertex it stands at and the exit
index of the edge it came in by.  A *motion* ``l`` leaves through exit
``(entry + l) mod deg`` — ``l`` counts exits clockwise from the entry edge and
``l = 0`` goes back the way it came.  At the start the robot faces one exit,
which plays the role of the entry edge, so the thesis's Figure 3.6 motion
sequence ``(0, 1, 2, 2, 1)`` begins by traversing the faced edge.

The *perception sequence* ``P`` of a motion sequence ``M`` is the signature of
every vertex reached; the start vertex's own signature is not part of it
(footnote 5 of §3.1.1).

Examples
--------
>>> from topomark.spec.world import World
>>> w = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})
>>> step(w, ("a", 0), 1)
('c', 0)
>>> [str(s) for s in perceive(w, ("a", 0), [0, 1])]
['[2,A,A]', '[2,A,A]']
"""

from __future__ import annotations

from typing import Iterable, Protocol, Sequence

from topomark.spec.errors import InvalidInput
from topomark.spec.signature import Signature, signature_at
from topomark.spec.world import World

__all__ = ["State", "Rotation", "exit_of", "step", "run", "perceive", "sense"]

State = tuple[str, int]


class Rotation(Protocol):
    """What a motion needs: degrees and where each dart leads (a :class:`World`, or a run's marker layer)."""

    def degree(self, v: str) -> int: ...

    def target(self, dart: State) -> State: ...


def exit_of(world: Rotation, state: State, motion: int) -> int:
    """The absolute exit index motion ``motion`` leaves ``state`` through."""
    v, entry = state
    d = world.degree(v)
    if not (isinstance(motion, int) and 0 <= motion < d):
        raise InvalidInput(f"motion {motion!r} does not exist at vertex {v!r} of degree {d} (allowed 0..{d - 1})")
    return (entry + motion) % d


def step(world: Rotation, state: State, motion: int) -> State:
    """The state reached by one motion: the far end of the chosen exit, entered by its reverse dart."""
    return world.target((state[0], exit_of(world, state, motion)))


def sense(world: World, state: State) -> Signature:
    """The signature sensed in ``state``."""
    return signature_at(world, state[0], state[1])


def run(world: World, state: State, motions: Iterable[int]) -> list[State]:
    """Every state visited after each motion (the start state excluded)."""
    states = []
    for motion in motions:
        state = step(world, state, motion)
        states.append(state)
    return states


def perceive(world: World, state: State, motions: Sequence[int]) -> list[Signature]:
    """The perception sequence P of motion sequence M from ``state`` (§3.1.1)."""
    return [sense(world, s) for s in run(world, state, motions)]

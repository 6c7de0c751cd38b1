"""The compiled Enhancements 4 and 5: expanded local signatures on the execution trie (thesis §4.2).

The engine's counterpart of :mod:`~topomark.reference.explorers.expansion`:
Enhancement-4 (Algorithm 4.4) senses the other neighbours of each new vertex
after a non-loop augmentation (line 22); Enhancement-5 (Algorithm 4.5) senses
every place within distance d of v_u on entering it (line 7).  Both keep
those perceptions in D, which is the store T of :mod:`.records` limited to
depth d and made only when v_u is new, and both filter H before validation
(Algorithm 4.4 line 7, 4.5 line 8) by tracing everything known around v_u on
S and T from each hypothesis — which :func:`~.enhanced.validate_on_trie` does
with Enhancement-3's tracing (:func:`~.enhanced.contradicted`).

A composition's techniques are bits beside :mod:`.enhanced`'s:

* :data:`PRUNE` — H keeps only the hypotheses whose expanded signature agrees
  with what is known around v_u, the ``virtual`` node for v_k behind e
  included (:func:`add_virtual`); the records of T beyond e join the trie
  before any motion;
* :data:`EXPAND_NEW` — Enhancement-4's expansion of a new vertex;
* :data:`EXPAND_PLACE` — Enhancement-5's expansion on entering v_u;
* :data:`DEPTH2` — the expansion's distance d is 2 (else 1).

:func:`expand` makes the reference's choice: a place already sensed in this
iteration's trie (validation, a record grafted from T) is not visited again.

Examples
--------
>>> expansion_depth(EXPAND_PLACE | DEPTH2), expansion_depth(EXPAND_NEW), recorded_depth(EXPAND_NEW | PRUNE, False)
(2, 1, 0)
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.digest import PURPOSE
from topomark.reference.engine.mapstate import known_signature
from topomark.reference.engine.robot import fault
from topomark.reference.engine.trie import DEGREE, META, FULL, AT, add_child, back, find_child, forward

__all__ = ["PRUNE", "EXPAND_NEW", "EXPAND_PLACE", "DEPTH2", "EVERY_DEPTH", "PURPOSE_EXPANSION", "expansion_depth",
           "recorded_depth", "add_virtual", "expand"]

PRUNE, EXPAND_NEW, EXPAND_PLACE, DEPTH2 = 16, 32, 64, 128
"""The bits of Enhancements 4 and 5 in a technique set (:data:`~.enhanced.TECHNIQUES`)."""
EVERY_DEPTH = 1 << 30
"""The depth to record to when every node is recorded (Enhancement-3's T, which the combinations of §4.3 keep)."""
PURPOSE_EXPANSION = PURPOSE["expansion"]
"""The purpose of the expansion's traversals: the investment of Enhancements 4 and 5."""


@step
def expansion_depth(techniques: int) -> int:
    """The distance d of the composition's expansion."""
    return 2 if techniques & DEPTH2 else 1


@step
def recorded_depth(techniques: int, new: bool) -> int:
    """How deep into the trie Enhancements 4/5 record into D after the join (0: nothing): d when v_u is new
    (Algorithm 4.4 line 22, 4.5 line 23).  With Enhancement-3 every node is recorded (:data:`EVERY_DEPTH`)."""
    if new and techniques & (EXPAND_NEW | EXPAND_PLACE):
        return expansion_depth(techniques)
    return 0


@kernel
def add_virtual(S: tuple, T: tuple, vk: int, i: int) -> None:
    """The robot came from v_k through e: motion 0 from v_u reaches v_k entered by exit ``i``, as S says (the
    ``virtual`` node, the trie's first child; :func:`~.records.record_trie` leaves it out)."""
    degree, code = known_signature(S, vk, i)
    add_child(T, 0, 0, degree, code)


@step
def _complete(T: tuple, node: int) -> bool:
    """Whether every exit of ``node`` but its entry has a child: its neighbours are known."""
    for m in range(1, T[DEGREE][node]):
        if find_child(T, node, m) < 0:
            return False
    return True


@kernel
def _walk_one(robot: np.ndarray, T: tuple) -> None:
    """Sense, out and back, each neighbour of the robot's node not yet in the trie."""
    node = T[META][AT]
    for m in range(1, T[DEGREE][node]):
        if find_child(T, node, m) >= 0:
            continue
        forward(robot, T, m, PURPOSE_EXPANSION)
        if fault(robot) or T[META][FULL]:
            return
        back(robot, T, PURPOSE_EXPANSION)
        if fault(robot):
            return


@kernel
def expand(robot: np.ndarray, T: tuple, d: int) -> None:
    """Sense every place reachable from the robot's node by 1..``d`` (1 or 2) motions through exits other than
    the entry, skipping what the trie knows already; the robot ends where it began."""
    if d == 1:
        _walk_one(robot, T)
        return
    node = T[META][AT]
    for m in range(1, T[DEGREE][node]):
        child = find_child(T, node, m)
        if child >= 0 and _complete(T, child):
            continue
        forward(robot, T, m, PURPOSE_EXPANSION)
        if fault(robot) or T[META][FULL]:
            return
        _walk_one(robot, T)
        if fault(robot) or T[META][FULL]:
            return
        back(robot, T, PURPOSE_EXPANSION)
        if fault(robot):
            return

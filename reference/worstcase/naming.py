"""The generator text that names a worst world, so a reader can regenerate it (thesis §7.2).

Every figure of the worst-case report (§7.2) comes from one world; the report names it by a generator text
(``family:param=…``) that ``topomark explore`` accepts.  :func:`generator_text` finds that name: the world of a
restart family at its size (:func:`~.structural.family_world`: ``strip:n=20,cap=1``), or a kept worst world
(:data:`~topomark.reference.worlds.worst_cases.WORST_CASES`: ``worst-case:case=basic-n20-d4-search``) equal to
it, rotation and start alike.  A world that is neither has no name (None), and the report says so.

>>> from topomark.reference.worlds.expensive import strip
>>> generator_text(strip(20, cap=1)), generator_text(strip(20, cap=1).with_start(None))
('strip:n=20,cap=1', None)
"""

from __future__ import annotations

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World
from topomark.spec.worldfile import world_to_json

from topomark.reference.worlds.worst_cases import WORST_CASES, worst_case_world
from topomark.reference.worstcase.structural import RESTART_FAMILIES, family_world

__all__ = ["generator_text"]


def _same(a: World, b: World) -> bool:
    return world_to_json(a) == world_to_json(b)


def generator_text(world: World, algorithm: str | None = None) -> str | None:
    """The generator text of a family or kept worst world equal to ``world`` (start included), or None; of kept
    worlds, one kept for ``algorithm`` first (the same world can be kept for two algorithms, under two names)."""
    for family in RESTART_FAMILIES:
        try:
            candidate, text = family_world(family, world.n)
        except InvalidInput:  # no such size in this family (k5e-chain: n a multiple of 5)
            continue
        if _same(candidate, world):
            return text
    kept = sorted(WORST_CASES.items(), key=lambda item: item[1]["algorithm"] != algorithm)  # stable: index order
    for name, entry in kept:
        if entry["n"] == world.n and entry["m"] == world.m and _same(worst_case_world(name), world):
            return f"worst-case:case={name}"
    return None

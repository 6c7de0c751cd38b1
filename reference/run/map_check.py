"""Judging a map file against a world file (thesis §3.1.3, extended isomorphism).

A map written by an explorer carries the marker the robot dropped; the world
file it was made in usually does not (Algorithm 3.1's robot brings its own
marker, §3.3).  :func:`check_map` therefore decides which markers take part,
by one documented rule (``spec/protocol.md``, "Judging a map"):

1. ``markers`` — the world file carries markers: they are part of the world
   and the map must show every one of them (and no others);
2. ``lighthouse`` — the world file carries none but has a start, and the map
   carries exactly one marker, a directional vertex marker: the world gets
   the lighthouse Algorithm 3.1 drops at the start (pointing at the faced
   exit) and the two are compared markers included, so the map must also
   place v0 and its reference exit correctly;
3. ``graph`` — otherwise the embedded graphs are compared, markers ignored.

The verdict carries the rule applied and, if negative, the first mismatch in
words (from :func:`topomark.spec.isomorphism.find_isomorphism`), and a
positive verdict's witness is re-verified independently.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, cast

from topomark.spec.errors import CheckFailure, clip
from topomark.spec.isomorphism import IsoResult, Witness, find_isomorphism, verify_witness
from topomark.spec.marker import VertexMarker
from topomark.spec.world import World

__all__ = ["MapVerdict", "check_map", "marker_rule", "RULES"]

RULES = {
    "markers": "the world file's markers are compared with the map's",
    "lighthouse": "the world gets Algorithm 3.1's lighthouse at its start (pointing at the faced exit); "
                  "markers compared",
    "graph": "markers ignored (the world file has none to compare with)",
}


@dataclass(frozen=True, repr=False)
class MapVerdict:
    """Whether a map is extended-isomorphic to its world (§3.1.3), and under which marker rule.

    ``isomorphic`` is the verdict; ``rule`` which markers took part (a key of :data:`RULES`: ``markers``,
    ``lighthouse`` or ``graph``); ``result`` the certificate: the witness, verified independently, when
    isomorphic, else the first mismatch.  :meth:`words` says it in a sentence.
    """

    isomorphic: bool
    rule: str
    result: IsoResult

    def __repr__(self) -> str:
        """``MapVerdict(isomorphic, rule='graph', witness verified)`` or ``MapVerdict(not isomorphic, rule=...,
        mismatch: ...)``: the verdict in one short line (the witness itself stays in ``result``)."""
        if self.isomorphic:
            return f"MapVerdict(isomorphic, rule={self.rule!r}, witness verified)"
        return f"MapVerdict(not isomorphic, rule={self.rule!r}, mismatch: {clip(str(self.result.mismatch), 600)})"

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"isomorphic": self.isomorphic, "rule": self.rule, "rule_text": RULES[self.rule]}
        if self.result.witness is not None:  # present exactly when isomorphic
            out["witness"] = self.result.witness.to_json()
        if self.result.mismatch is not None:
            out["mismatch"] = self.result.mismatch.to_json()
        return out

    def words(self) -> str:
        if self.isomorphic:
            return f"isomorphic (extended isomorphism; {RULES[self.rule]}; witness verified)"
        return f"not isomorphic ({RULES[self.rule]}): {self.result.mismatch}"


def marker_rule(world: World, map_: World) -> tuple[str, World]:
    """The rule that applies, and the world to compare the map with."""
    if world.markers:
        return "markers", world
    lone = map_.markers[0] if len(map_.markers) == 1 else None
    if world.start is not None and isinstance(lone, VertexMarker) and lone.directional and lone.count == 1:
        return "lighthouse", world.with_markers([VertexMarker(world.start.at, 1, world.start.facing)], world.start)
    return "graph", world


def check_map(world: World, map_: World) -> MapVerdict:
    """Is ``map_`` extended-isomorphic to ``world`` under :func:`marker_rule`?"""
    rule, target = marker_rule(world, map_)
    markers = rule != "graph"
    result = find_isomorphism(target, map_, markers=markers)  # mismatches read "expected <world>, found <map>"
    if result.isomorphic:
        bad = verify_witness(target, map_, cast(Witness, result.witness), markers=markers)
        if bad is not None:
            raise CheckFailure(bad)
    return MapVerdict(result.isomorphic, rule, result)

"""A trace's header: its format, algorithm, policies and — for ``topomark/trace@2`` — algorithm family, lighthouse, kit.

:func:`check_header` judges a header record whose fields already have the
right kinds (:mod:`topomark.reference.trace.reader`) and returns the events the
rest of the trace may hold; any defect is one :class:`~topomark.spec.errors.
InvalidInput` (exit 2) naming the line (``spec/trace.md``):

* ``format``: ``topomark/trace@1`` or ``topomark/trace@2``;
* ``algorithm``: a registered algorithm (trace@1; trace@2 in a family of
  registered algorithms), or any non-empty name (the ``robot`` family);
* ``policies``: exactly ``edge``, ``hypothesis``, ``path``, each a valid
  policy (:func:`header_policies`) — in the ``robot`` family an object the
  recorder's algorithm owns;
* trace@2: ``family`` one of :data:`~topomark.reference.trace.families.
  ALGORITHM_FAMILIES`, covering the algorithm; ``lighthouse`` one of
  :data:`~topomark.reference.explorers.lighthouses.LIGHTHOUSES` (``null``
  only in a family without one); ``kit`` a valid
  :class:`~topomark.spec.kit.Kit`, the lighthouse's own when there is one.
"""

from __future__ import annotations

import json
from typing import Any

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.kit import Kit

from topomark.reference.algorithms.registry import in_family
from topomark.reference.trace.records import TRACE_FORMAT, TRACE_FORMAT_2
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse
from topomark.reference.explorers.policies import Policies
from topomark.reference.trace.families import ALGORITHM_FAMILIES, ROBOT_EVENTS, AlgorithmFamily

__all__ = ["FORMATS", "check_header", "header_policies", "header_family", "header_kit", "header_lighthouse"]

FORMATS = (TRACE_FORMAT, TRACE_FORMAT_2)
EVENTS_1 = ("drop", "move", "iteration")
"""The events after a trace@1 header (before the end)."""


def header_policies(value: dict, where: str) -> Policies:
    """The header's ``policies`` object as :class:`Policies`: exactly the three kinds, each a valid name."""
    kinds = ("edge", "hypothesis", "path")
    for key in value:
        if key not in kinds:
            raise InvalidInput(f"{where}: header.policies: unknown policy kind {key!r} (the kinds are "
                               f"{', '.join(kinds)})")
    for key in kinds:
        if key not in value:
            raise InvalidInput(f"{where}: header.policies: no {key} policy")
    try:
        return Policies(**value)
    except InvalidInput as exc:
        raise InvalidInput(f"{where}: header.policies: {exc}") from None


def header_family(header: dict[str, Any]) -> AlgorithmFamily:
    """The header's family: trace@1 is Algorithm 3.1's."""
    return ALGORITHM_FAMILIES[header.get("family", "algorithm-3.1")]


def header_lighthouse(header: dict[str, Any]) -> Lighthouse | None:
    """The header's lighthouse: trace@1's is always the directional vertex marker."""
    name = header.get("lighthouse", "directional-vertex")
    return None if name is None else LIGHTHOUSES[name]


def header_kit(header: dict[str, Any]) -> Kit:
    """The header's kit: trace@1's is the directional vertex marker's."""
    return Kit.from_json(header["kit"]) if "kit" in header else LIGHTHOUSES["directional-vertex"].kit


def check_header(rec: dict[str, Any], where: str) -> tuple[str, ...]:
    """Judge a header (see the module docstring); return the events that may follow it before the end."""
    if rec["format"] not in FORMATS:
        raise InvalidInput(f"{where}: unknown trace format {rec['format']!r} (this is {' or '.join(FORMATS)})")
    family = ALGORITHM_FAMILIES["algorithm-3.1"]
    if rec["format"] == TRACE_FORMAT_2:
        if rec["family"] not in ALGORITHM_FAMILIES:
            raise InvalidInput(f"{where}: header.family: unknown family {_show(rec['family'])} (the families are "
                               f"{', '.join(ALGORITHM_FAMILIES)})")
        family = ALGORITHM_FAMILIES[rec["family"]]
    if not family.covers(rec["algorithm"]):
        known = f"the registered algorithms are {', '.join(in_family(family.name))}" if family.registered else "a name"
        raise InvalidInput(f"{where}: header.algorithm: unknown algorithm {_show(rec['algorithm'])} "
                           f"({known})")
    if family.registered:
        header_policies(rec["policies"], where)
    if rec["format"] == TRACE_FORMAT:
        return EVENTS_1
    _check_kit(rec, family, where)
    return ROBOT_EVENTS + family.events


def _check_kit(rec: dict[str, Any], family: AlgorithmFamily, where: str) -> None:
    name = rec["lighthouse"]
    if name is None and family.lighthouse:
        raise InvalidInput(f"{where}: header.lighthouse: the {family.name} family needs a lighthouse (one of "
                           f"{', '.join(LIGHTHOUSES)})")
    if name is not None and name not in LIGHTHOUSES:
        raise InvalidInput(f"{where}: header.lighthouse: unknown lighthouse {_show(name)} (the lighthouses are "
                           f"{', '.join(LIGHTHOUSES)})")
    try:
        kit = Kit.from_json(rec["kit"])
    except InvalidInput as exc:
        raise InvalidInput(f"{where}: header.kit: {exc}") from None
    if name is not None and kit != LIGHTHOUSES[name].kit:
        raise InvalidInput(f"{where}: header.kit {json.dumps(rec['kit'])[:80]} is not the {name} lighthouse's kit "
                           f"{json.dumps(LIGHTHOUSES[name].kit.to_json())}")


def _show(value: Any) -> str:
    return clip(repr(value), 80, note="")

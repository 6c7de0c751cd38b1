"""Algorithms 4.3, 4.4 and 4.5 (d = 2) as listed: the Chapter 4 compositions that follow their listings to the
letter (thesis §4.1–4.2).

``enh3``, ``enh4`` and ``enh5-d2`` (:mod:`~topomark.reference.explorers.compositions`) each change their listing
in one place (their registrations' ``changes``).  The explorers here are the same techniques with that change left
out (each technique's ``as_listed``), registered beside them as ``enh3-listing``, ``enh4-listing`` and
``enh5-d2-listing``, so that a program following the listing has a reference run of its own.

Algorithm 4.3, Enhancement-3 (``enh3-listing``; :class:`~.tracing.ExecutedPathsOnSAndUnknownPlaces` with
``as_listed``, after :class:`~.overlap.OverlapStage2`):

* lines 1–7 → Algorithm 3.1's (:class:`~.algorithm31.LighthouseExplorer`); line 2's T is
  :attr:`~.enhanced.EnhancedExplorer.T`;
* lines 8–9 → :meth:`~.enhanced.EnhancedExplorer.validate` walks the first hypothesis unchecked: nothing has
  been executed for e yet, and T's records beyond e are **not** put into the trie on entering v_u
  (:attr:`~.enhanced.Enhancement.grafts` is false) — that is ``enh3``'s change;
* lines 16–24 → the tracer's ``contradiction``, run after every mismatch on the motions executed for e, looking
  unknown places up in T (lines 20–21) as they are reached along those motions;
* lines 25–31 → stage 2 (:class:`~.overlap.OverlapStage2`): the hypothesis with the longest overlap, from the
  nearest overlapping node;
* lines 32–35 → the loop or non-loop join; lines 36–37 → :func:`~.records.record_trie`.

Algorithm 4.4, Enhancement-4 (``enh4-listing``; :class:`~.expansion.ExpandedSignaturesOfNewVertices` with
``as_listed``):

* lines 1–6 → Algorithm 3.1's; line 3's D is T, records of depth 1;
* line 7 → ``prune``: v_k' shows v_u's signature and the far end of e' (from D) shows v_k's;
* lines 8–21 → Algorithm 3.1's validation;
* line 22 → ``after_non_loop``: :func:`~.expansion.expand` with ``every``: the robot explores **all** the other
  neighbours of the new v_u, out and back, one already sensed in this iteration too (``enh4`` skips those);
  what it senses goes into D (``recorded_depth`` 1).

Algorithm 4.5, Enhancement-5 with d = 2 (``enh5-d2-listing``; :class:`~.expansion.ExpandedSignaturesOfCurrentPlace`
with d = 2 and ``as_listed``):

* lines 1–6 → Algorithm 3.1's; line 3's D is T, records of depth 2;
* line 7 → ``on_enter``: :func:`~.expansion.expand` with ``every``: through each other exit of v_u, and from
  each neighbour through each of its other exits, out and back, whether D already shows the place or not
  (``enh5-d2`` skips those);
* line 8 → ``prune`` on what was just explored (v_k behind e included, "enumerated from the entry edge");
* lines 9–22 → Algorithm 3.1's validation; line 23 → ``recorded_depth`` 2, no motion.

Choice (the listing is silent), the same as ``enh5-d2``'s: "all the distance d neighbors of v_u" are reached
through v_u's other exits ("the robot conducts extra traversals on each other incident edge of v_u", §4.2),
never back over e: v_k is in S.

Examples
--------
>>> sorted(AS_LISTED)
['enh3-listing', 'enh4-listing', 'enh5-d2-listing']
>>> [e.grafts for e in AS_LISTED.values()]
[False, False, False]
"""

from __future__ import annotations

from topomark.reference.explorers.enhanced import EnhancedExplorer, Enhancement
from topomark.reference.explorers.expansion import ExpandedSignaturesOfCurrentPlace, ExpandedSignaturesOfNewVertices
from topomark.reference.explorers.overlap import OverlapStage2
from topomark.reference.explorers.tracing import ExecutedPathsOnSAndUnknownPlaces

__all__ = ["AS_LISTED", "LISTING_EXPLORERS", "VARIANT_OF"]

AS_LISTED: dict[str, Enhancement] = {e.name: e for e in (
    Enhancement("enh3-listing", (OverlapStage2(), ExecutedPathsOnSAndUnknownPlaces(as_listed=True)),
                "§4.1, Enhancement-3, Algorithm 4.3"),
    Enhancement("enh4-listing", (ExpandedSignaturesOfNewVertices(1, as_listed=True),),
                "§4.2, Enhancement-4, Algorithm 4.4"),
    Enhancement("enh5-d2-listing", (ExpandedSignaturesOfCurrentPlace(2, as_listed=True),),
                "§4.2, Enhancement-5, Algorithm 4.5"),
)}
"""Each Chapter 4 listing that a registered composition changes, as listed, by its registered name."""

VARIANT_OF = {"enh3-listing": "enh3", "enh4-listing": "enh4", "enh5-d2-listing": "enh5-d2"}
"""The composition each listing entry is the literal form of (whose ``listing_entry`` it is)."""


def _make(enh: Enhancement) -> type:
    return type(f"Explorer_{enh.name.replace('-', '_')}", (EnhancedExplorer,),
                {"enhancement": enh, "name": enh.name, "__doc__": f"{enh.section} as listed: see the module docstring."})


LISTING_EXPLORERS: dict[str, type] = {name: _make(enh) for name, enh in AS_LISTED.items()}
"""The explorer class of each listing entry."""

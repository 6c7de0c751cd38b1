"""Executed paths traced on the map: Enhancement-2 (on S) and Enhancement-3 (… and unknown places) (§4.1).

Algorithm 4.2 lines 16–20: "for each remaining hypothesis h'' in H — assume
h'' is true, trace all the previously executed motions for e; if a motion
mapped onto a known place in S, but the observed perception does not match
the signature of the known place on S then remove h'' from H (reject h''
without motion!)".  Algorithm 4.3 lines 17–24 continue past unexplored
edges into T: "else (mapped onto unknown place) try to retrieve signature by
searching T" (:mod:`~topomark.reference.explorers.records`); Enhancement-3
also records every executed path into T after the join.

Tracing is incremental: per hypothesis, the state at each node of the
execution trie is the map dart reached (or None past an unexplored edge) and
the records of T reached; only nodes added since the last check are traced.

Choice (the thesis is silent): the hypothesized edge e''/e itself is part of
the traced map (it is part of S if h'' holds); tracing on S alone stops at
any other unexplored edge.

Correspondence with Algorithm 4.2 (``enh2`` follows it step by step): lines 1–15, 21–33 as Algorithm 4.1's
(:mod:`.overlap`, stage 2 for lines 23–28); lines 16–20 → :meth:`ExecutedPathsOnS.contradiction`, run by
``reject_without_motion`` after every mismatch on the paths executed for e since the last check (the earlier
ones were traced then; no path is executed before line 9, so nothing is rejected before it).  ``enh3`` adds T
(lines 2, 21, 36–37 → :meth:`ExecutedPathsOnSAndUnknownPlaces.store`, :func:`~.records.record_trie`) and
changes its listing: T's records beyond e count as known before any motion (:func:`~.records.graft`;
``changes`` in its registration).  With ``as_listed`` they do not (the composition's ``grafts`` is false): T is
looked up only while tracing the motions executed for e, Algorithm 4.3 to the letter (``enh3-listing``,
:mod:`~topomark.reference.explorers.enhancements_as_listed`).
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.spec.signature import signature_at

from topomark.reference.explorers.enhanced import Technique

__all__ = ["ExecutedPathsOnS", "ExecutedPathsOnSAndUnknownPlaces"]

_NOTHING: dict = {}


@dataclass(frozen=True)
class ExecutedPathsOnS(Technique):
    """Enhancement-2: trace every executed path on S from the hypothesized (v_k'', e''); reject on a mismatch."""

    section = "§4.1, Enhancement-2, Algorithm 4.2"
    rejected_by = "map"
    trace = "map"

    def start(self, h) -> tuple:
        """At v_u, assumed to be v_k'' entered by e'': that map dart, and no record yet."""
        return h.dart, ()

    def prepare(self, new) -> None:
        return None

    def store(self, explorer) -> dict:
        """The records tracing may continue into (none: S only)."""
        return _NOTHING

    def contradiction(self, explorer, h, state: dict, new: list, ctx, it) -> int | None:
        """-1 if a new perception contradicts S (or T) traced from h's dart, else None."""
        S, T = explorer.P, self.store(explorer)  # S as perceived: a probing lighthouse's v0 with its virtual head
        links = S.links
        link = {h.dart: it.edge, it.edge: h.dart}
        for node in new:
            ps = state.get(node.parent)
            if ps is None:
                continue
            m = node.motion
            md, recs = ps
            nm, nrecs = None, []
            if md is not None:
                x, entry = md
                row = links(x)
                t = (x, (entry + m) % len(row))
                nm = row[t[1]]
                if nm is None:
                    nm = link.get(t)
                    rec = T.get(t)
                    if rec is not None:
                        nrecs.append(rec)
                if nm is not None and signature_at(S, nm[0], nm[1]) != node.sig:
                    return -1
            for r in recs:
                rec = r.children.get(m)
                if rec is not None:
                    nrecs.append(rec)
            for rec in nrecs:
                if rec.sig != node.sig:
                    return -1
            if nm is not None or nrecs:
                state[node] = (nm, tuple(nrecs))
        return None


@dataclass(frozen=True)
class ExecutedPathsOnSAndUnknownPlaces(ExecutedPathsOnS):
    """Enhancement-3: tracing continues into T; after the join every executed path is recorded into T."""

    as_listed: bool = False  # Algorithm 4.3 to the letter: T looked up only while tracing executed motions

    section = "§4.1, Enhancement-3, Algorithm 4.3"
    trace = "map+T"

    def store(self, explorer) -> dict:
        return explorer.T

    def recorded_depth(self, new: bool) -> float:
        return float("inf")

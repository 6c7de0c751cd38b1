"""The Chapter 4 algorithms as compositions of techniques on Algorithm 3.1's template (thesis §4.1–4.3).

Registered names (``topomark explore --algorithm NAME``):

===========  ===============================================================  ====================================
name         techniques                                                       thesis
===========  ===============================================================  ====================================
``enh1``     overlap stage 1, overlap stage 2                                 §4.1, Enhancement-1, Algorithm 4.1
``enh2``     overlap stage 2, executed paths that map onto S                  §4.1, Enhancement-2, Algorithm 4.2
``enh3``     overlap stage 2, executed paths on S and unknown places (T)      §4.1, Enhancement-3, Algorithm 4.3
``enh4``     expanded signatures of new vertices (d = 1)                      §4.2, Enhancement-4, Algorithm 4.4
``enh5-d1``  expanded signatures of the current place, d = 1                  §4.2, Enhancement-5, Algorithm 4.5
``enh5-d2``  expanded signatures of the current place, d = 2                  §4.2, Enhancement-5, Algorithm 4.5
``enh3+4``   enh3's techniques and Enhancement-4's                            §4.3, Table 4.8
``enh3+5``   enh3's techniques and Enhancement-5's with d = 2                 §4.3, Table 4.7
===========  ===============================================================  ====================================

Enhancement-2 and -3 take stage 2 of Enhancement-1 as their listings do
(Algorithms 4.2, 4.3: "technique in stage-2 of enhancement-1 is used");
their tracing subsumes stage 1 (an overlapped prefix of h'' lies on its own
path in S).  In the combinations of §4.3 the expansion's perceptions are
records of T like Enhancement-3's, and Enhancement-5 is combined with
d = 2, the version the thesis combines.  ``basic`` — no technique — is
Algorithm 3.1 itself (:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`).
"""

from __future__ import annotations

from topomark.reference.explorers.enhanced import EnhancedExplorer, Enhancement
from topomark.reference.explorers.expansion import ExpandedSignaturesOfCurrentPlace, ExpandedSignaturesOfNewVertices
from topomark.reference.explorers.overlap import OverlapStage1, OverlapStage2
from topomark.reference.explorers.tracing import ExecutedPathsOnS, ExecutedPathsOnSAndUnknownPlaces

__all__ = ["ENHANCEMENTS", "EXPLORERS"]

_ENH3 = (OverlapStage2(), ExecutedPathsOnSAndUnknownPlaces())

ENHANCEMENTS: dict[str, Enhancement] = {e.name: e for e in (
    Enhancement("enh1", (OverlapStage1(), OverlapStage2()), "§4.1, Enhancement-1, Algorithm 4.1"),
    Enhancement("enh2", (OverlapStage2(), ExecutedPathsOnS()), "§4.1, Enhancement-2, Algorithm 4.2"),
    Enhancement("enh3", _ENH3, "§4.1, Enhancement-3, Algorithm 4.3"),
    Enhancement("enh4", (ExpandedSignaturesOfNewVertices(1),), "§4.2, Enhancement-4, Algorithm 4.4"),
    Enhancement("enh5-d1", (ExpandedSignaturesOfCurrentPlace(1),), "§4.2, Enhancement-5, Algorithm 4.5"),
    Enhancement("enh5-d2", (ExpandedSignaturesOfCurrentPlace(2),), "§4.2, Enhancement-5, Algorithm 4.5"),
    Enhancement("enh3+4", _ENH3 + (ExpandedSignaturesOfNewVertices(1),), "§4.3, Enhancements 3+4, Table 4.8"),
    Enhancement("enh3+5", _ENH3 + (ExpandedSignaturesOfCurrentPlace(2),), "§4.3, Enhancements 3+5, Table 4.7"),
)}
"""Each Chapter 4 algorithm by its registered name."""


def _make(enh: Enhancement) -> type:
    return type(f"Explorer_{enh.name.replace('+', '_').replace('-', '_')}", (EnhancedExplorer,),
                {"enhancement": enh, "name": enh.name, "__doc__": f"{enh.section}: see the module docstring."})


EXPLORERS: dict[str, type] = {name: _make(enh) for name, enh in ENHANCEMENTS.items()}
"""The explorer class of each composition."""

"""Registration of Algorithm 3.1, ``basic`` (thesis §3.3, L498–L552), and of its Chapter 4 enhancements
(§4.1–4.3, L885–L1305): ``enh1`` … ``enh5-d2``, ``enh3+4``, ``enh3+5``.

All are *lighthouse algorithms*: they establish v0 with any lighthouse strategy
(:mod:`topomark.reference.explorers.lighthouses`; the listed kit is the default
directional vertex marker's), take the three policies, and are checked with
Algorithm 3.1's loop conditions
(:data:`~topomark.reference.algorithms.algorithm_spec.ALGORITHM_3_1_CHECKS`).
Their explorers are :class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`
and the compositions of :mod:`topomark.reference.explorers.compositions`.

Decision (the thesis is silent): Chapter 4 states no worst-case bound for
its enhancements (§4.1–4.3 report measured reductions only).  Enhancements
1–3 change only how hypotheses are validated and retraced, so they are given
Algorithm 3.1's bound (3.1)+(3.2) (§3.5.2, L626–L645) as a stated
*inheritance*, and the checker measures it; Enhancements 4 and 5 add
expansion traversals the thesis does not bound, so their ``bound`` is ``None``.

Examples
--------
>>> [s.name for s in SPECS]
['basic', 'enh1', 'enh2', 'enh3', 'enh4', 'enh5-d1', 'enh5-d2', 'enh3+4', 'enh3+5']
>>> SPECS[0].bound_for(3, 3), SPECS[4].bound_for(3, 3)  # a triangle: (3.1) + (3.2); enh4: none stated
(22, None)
"""

from __future__ import annotations

from topomark.reference.algorithms.algorithm_spec import ALGORITHM_3_1_CHECKS, AlgorithmSpec
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.compositions import ENHANCEMENTS, EXPLORERS
from topomark.reference.explorers.lighthouses import LIGHTHOUSES

__all__ = ["SPECS", "POLICY_OPTIONS"]

POLICY_OPTIONS = ("policy edge=nearest|fifo|lifo", "policy hypothesis=fifo|lifo|shortest", "policy path=shortest|dfs",
                  "lighthouse " + "|".join(LIGHTHOUSES),
                  *(f"lighthouse option {o.replace('_', '-')}=N (" + ", ".join(h.name for h in LIGHTHOUSES.values()
                                                                         if o in h.options) + ")"
                    for o in ("seed", "walk_limit", "neighbourhood", "threshold")))
"""The options of a lighthouse algorithm, as ``topomark algorithms`` lists them: the policies and lighthouses."""

_KIT = LIGHTHOUSES["directional-vertex"].kit
_BOUND = "(3.1)+(3.2) = O(m²n), §3.5.2"


def _lighthouse_algorithm(name: str, thesis: str, explorer, bound: str | None, bound_fn) -> AlgorithmSpec:
    """Algorithm 3.1's template: one marker (the lighthouse's), deterministic, the policy options, its checks."""
    return AlgorithmSpec(name=name, thesis=thesis, kit=_KIT, bound=bound, markers="1", deterministic=True,
                         options=POLICY_OPTIONS, checks=ALGORITHM_3_1_CHECKS, bound_fn=bound_fn, explorer=explorer)


def _enhancement(name: str) -> AlgorithmSpec:
    """A Chapter 4 composition, with Algorithm 3.1's bound where it only changes validation (module docstring)."""
    enh = ENHANCEMENTS[name]
    inherits = not (enh.prune or enh.expand_new or enh.expand_place)
    bound = f"{_BOUND}, inherited (§4.1 changes validation only)" if inherits else None
    return _lighthouse_algorithm(name, enh.section, EXPLORERS[name], bound, upper_bound if inherits else None)


SPECS = (
    _lighthouse_algorithm("basic", "§3.3, Algorithm 3.1", LighthouseExplorer, _BOUND, upper_bound),
    *(_enhancement(name) for name in ENHANCEMENTS),
)

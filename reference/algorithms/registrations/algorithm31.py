"""Registration of Algorithm 3.1, ``basic`` (thesis §3.3, §3.4), and of its Chapter 4 enhancements
(§4.1–4.3): ``enh1`` … ``enh5-d2``, ``enh3+4``, ``enh3+5``, and the listings three of them change, as written:
``enh3-listing``, ``enh4-listing``, ``enh5-d2-listing``.

All are *lighthouse algorithms*: they establish v0 with any lighthouse strategy
(:mod:`topomark.reference.explorers.lighthouses`; the listed kit is the default
directional vertex marker's), take the three policies, and are checked with
Algorithm 3.1's loop conditions
(:data:`~topomark.reference.algorithms.algorithm_spec.ALGORITHM_3_1_CHECKS`).
Their explorers are :class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`
and the compositions of :mod:`topomark.reference.explorers.compositions`.

Decisions:

* **Which bound the enhancements keep.**  Chapter 4 says its enhancements "do not improve the theoretical
  exploration cost bound O(m²n) of the algorithm" (Chapter 4) and reports measured reductions only; it states no
  exact bound for any of them.  Enhancements 1–3 add no motion ("These approaches require no addition of motion
  by the robot", §4.1): they only change how hypotheses are validated and retraced, so they keep Algorithm
  3.1's exact bound (3.1)+(3.2) (§3.5.2), and every checked run holds them to it.  Enhancements 4 and
  5 add expansion traversals that (3.1)+(3.2) does not count ("O(m·d_max) extra traversals may be required",
  §4.2), so theirs is the asymptotic O(m²n) of Chapter 4, measured by the bench (``tables``), never checked per run.
* **Three listings as written.**  ``enh3``, ``enh4`` and ``enh5-d2`` change their listings (:data:`CHANGES`);
  Algorithms 4.3, 4.4 and 4.5 (d = 2) as written are registered beside them
  (:mod:`~topomark.reference.explorers.enhancements_as_listed`; each variant's ``listing_entry``), so a program
  following a listing has a reference run and a suite of its own.  ``enh3-listing`` adds no motion and keeps
  (3.1)+(3.2) (``thesis``).  ``enh4-listing`` and ``enh5-d2-listing`` are held to topomark's bounds of the
  listing as written (``listing``; ``docs/bounds.md``): Algorithm 3.1's passes with H pruned, plus line 22's
  2Σ(d_k − 1) ≤ 2(2m − n) expansion traversals (:func:`enh4_listing_bound`), or line 7's walk to every place
  within distance 2 on each of the m passes, 2Σ d_x over v_u's other neighbours ≤ 2·min((n − 1)(n − 2),
  2m − 2) (:func:`enh5_d2_listing_bound`).  The variants keep Chapter 4's O(m²n).  ``enh3+4`` and ``enh3+5``
  get no literal entry: §4.3 combines its parts "in a strategic manner" and lists nothing.
* **What the exact bound counts** (``cost-bound``).  (3.1)+(3.2) bounds the passes through Algorithm 3.1's loop
  body (§3.5.2: "the number of edge traversals required in one pass through the loop body"), which starts with
  the marker already at v0 (line 1).  A lighthouse that is searched for first (§5.1: "first conduct a
  random walk ... and then explores the world using the deterministic single directional marker algorithm";
  §6.1; §5.2.1) walks before the loop starts: those ``establish`` moves (``walk_steps``, held to the
  walk limit, §5.1) are not counted.  Nor are ``probe`` moves: a lighthouse whose back-link needs "extra
  traversals looking for the marked neighbors" (Figure 3.21(b), §5.1: "It becomes more expensive to
  validate back-link") pays them on top of the loop, and the thesis bounds them nowhere.  Every other move
  (travel, new, validation, retrace) counts.

Examples
--------
>>> [s.name for s in SPECS]  # doctest: +NORMALIZE_WHITESPACE
['basic', 'enh1', 'enh2', 'enh3', 'enh4', 'enh5-d1', 'enh5-d2', 'enh3+4', 'enh3+5', 'enh3-listing', 'enh4-listing',
 'enh5-d2-listing']
>>> SPECS[0].bound_for(3, 3), SPECS[4].bound_for(3, 3)  # a triangle: (3.1) + (3.2); enh4: asymptotic only
(22, None)
>>> SPECS[4].bound_note
'asymptotic: measured by bench tables, not checked per run'
"""

from __future__ import annotations

from typing import Any, Callable

from topomark.reference.algorithms.algorithm_spec import ALGORITHM_3_1_CHECKS, AlgorithmSpec
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.compositions import ENHANCEMENTS, EXPLORERS
from topomark.reference.explorers.enhancements_as_listed import AS_LISTED, LISTING_EXPLORERS, VARIANT_OF
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.policies import EDGE_POLICIES

__all__ = ["SPECS", "POLICY_OPTIONS", "BOUND", "CHANGES", "lighthouse_algorithm", "policy_options",
           "enh4_listing_bound", "enh5_d2_listing_bound"]


def policy_options(edge: str = "nearest") -> tuple[str, ...]:
    """The options of a lighthouse algorithm, as ``topomark algorithms`` lists them: the three policies (each
    kind's default first; ``edge``, the edge policy its runs take unless ``--policy edge=...`` says otherwise)
    and the lighthouses with their options."""
    edges = "|".join(dict.fromkeys((edge, *EDGE_POLICIES)))
    return (f"policy edge={edges}", "policy hypothesis=fifo|lifo|shortest", "policy path=shortest|dfs",
            "lighthouse " + "|".join(LIGHTHOUSES),
            *(f"lighthouse option {o.replace('_', '-')}=N (" + ", ".join(h.name for h in LIGHTHOUSES.values()
                                                                   if o in h.options) + ")"
              for o in ("seed", "walk_limit", "neighbourhood", "threshold")))


POLICY_OPTIONS = policy_options()
"""The options of ``basic`` and the Chapter 4 enhancements (:func:`policy_options`, edge policy ``nearest``)."""

_KIT = LIGHTHOUSES["directional-vertex"].kit
BOUND = "(3.1)+(3.2) = O(m²n), §3.5.2"
"""Algorithm 3.1's cost bound as stated: what :func:`lighthouse_algorithm` registers by default."""
_FORMULA = "(3.1)+(3.2) = Σ_{n_s=1}^{n−1}[n_s + 2(n_s−1)(2m−2(n_s−1))] + Σ_{i=1}^{m−n+1}[n + 2(n−1)(2m−2(n−1)−2(i−1))] " \
           "(§3.5.2)"
_UNCOUNTED = ("establish", "probe", "drop")
"""The moves (3.1)+(3.2) does not count: a lighthouse's search walk, its back-link probes, and its drop trip (the
``three-undirected-vertex`` lighthouse's walk to a neighbour and back to drop there, Figure 3.21(b)) — all made
before, or beside, the loop body the bound counts (module docstring)."""


def lighthouse_algorithm(name: str, thesis: str, explorer: Callable[..., Any], bound: str = BOUND,
                         exact: bool = True, edge_policy: str | None = None, **fields: Any) -> AlgorithmSpec:
    """The registration template of Algorithm 3.1's family (§3.3): a lighthouse algorithm (any lighthouse, the
    default directional vertex marker's kit), one marker, deterministic, the policy options of
    :func:`policy_options`, Algorithm 3.1's checks, written in the ``algorithm-3.1`` trace family.

    ``explorer`` is built as ``explorer(robot, policies, observer, lighthouse)``
    (:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer` or a subclass).  ``exact``: held to
    (3.1)+(3.2) (``cost-bound``, the lighthouse's own moves not counted), else ``bound`` is asymptotic, measured
    by the bench ``tables``.  ``edge_policy`` names the edge choice its runs take at line 5 unless
    ``--policy edge=...`` chooses another (a name of
    :data:`~topomark.reference.explorers.edge_choices.EDGE_CHOICES`; default ``nearest``).  Any other
    :class:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec` field may be given by name.

    >>> spec = lighthouse_algorithm("basic-fifo", "§3.3, Algorithm 3.1, oldest edge first", LighthouseExplorer,
    ...                             edge_policy="fifo")
    >>> spec.policies().edge, spec.options[0], spec.bound_for(3, 3)
    ('fifo', 'policy edge=fifo|nearest|lifo', 22)
    """
    how = dict(bound_fn=upper_bound, bound_formula=_FORMULA, bound_excludes=_UNCOUNTED, bound_source="thesis") \
        if exact else \
        dict(bound_bench="tables")
    return AlgorithmSpec(**{**dict(name=name, thesis=thesis, kit=_KIT, bound=bound, markers="1", deterministic=True,
                                   options=policy_options(edge_policy or "nearest"), checks=ALGORITHM_3_1_CHECKS,
                                   explorer=explorer, edge_policy=edge_policy, ways=_WAYS), **how, **fields})


_WAYS = ("correct", "hypothesis-rejected", "hypothesis-confirmed")
"""How a run of Algorithm 3.1 (and of each Chapter 4 composition) goes: hypotheses rejected and confirmed (§3.3),
ending with the map; a lighthouse search that gives up is the lighthouse strategy's way, not the algorithm's."""


_T_BEYOND_E = ("Algorithm 4.3 traces only the motions executed for e, after a mismatch (lines 16–24), looking unknown "
               "places up in T: this explorer also counts T's records beyond e itself as known at v_u before any "
               "motion, so a hypothesis they contradict is rejected before the first one is walked (lines 8–9 walk "
               "it unchecked) and at every later check")
_NEIGHBOURS_SENSED = ("Algorithm 4.4 line 22 has the robot explore all the other neighbours of a new v_u: this "
                      "explorer skips each one already sensed in this iteration (a rejected hypothesis's first "
                      "motion), 2 traversals fewer for each")
_PLACES_KNOWN = ("Algorithm 4.5 line 7 has the robot explore all the distance-d neighbours of v_u: with d = 2 this "
                 "explorer skips the places T's records beyond e already show (sensed when v_k was new, line 23), "
                 "2 traversals fewer for each, and does not walk v_k's side (v_k is in S)")
CHANGES = {
    "enh3": _T_BEYOND_E,
    "enh4": _NEIGHBOURS_SENSED,
    "enh5-d2": _PLACES_KNOWN,
    "enh3+4": f"§4.3 gives no listing; its parts change theirs: {_T_BEYOND_E}; {_NEIGHBOURS_SENSED}",
    "enh3+5": f"§4.3 gives no listing; its parts change theirs: {_T_BEYOND_E}; {_PLACES_KNOWN}",
}
"""What each Chapter 4 composition changes relative to its listing (``changes``; the others follow theirs, as
their modules' correspondences say): each is shown, on the smallest world the enumeration finds, by
``tests/test_listing_audit.py``."""


def _enhancement(name: str) -> AlgorithmSpec:
    """A Chapter 4 composition: (3.1)+(3.2) where it adds no motion, else O(m²n) asymptotic (module docstring)."""
    enh = ENHANCEMENTS[name]
    inherits = not (enh.prune or enh.expand_new or enh.expand_place)
    bound = f"{BOUND}, inherited (§4.1 adds no motion)" if inherits else \
        "O(m²n) (Chapter 4; its expansion traversals are outside (3.1)+(3.2), §4.2)"
    listed = next((k for k, v in VARIANT_OF.items() if v == name), None)
    return lighthouse_algorithm(name, enh.section, EXPLORERS[name], bound, inherits, changes=CHANGES.get(name),
                                listing_entry=listed)


def enh4_listing_bound(n: int, m: int) -> int:
    """Topomark's bound for Algorithm 4.4 as listed (``enh4-listing``; module docstring): (3.1)+(3.2) + 2(2m − n)."""
    return upper_bound(n, m) + 2 * max(0, 2 * m - n)


def enh5_d2_listing_bound(n: int, m: int) -> int:
    """Topomark's bound for Algorithm 4.5 as listed with d = 2 (``enh5-d2-listing``; module docstring):
    (3.1)+(3.2) + 2m·min((n − 1)(n − 2), 2m − 2)."""
    return upper_bound(n, m) + 2 * m * max(0, min((n - 1) * (n - 2), 2 * m - 2))


_LISTING = "topomark's bound for the thesis's listing as written (docs/bounds.md), behind O(m²n) (Chapter 4)"
_LISTING_BOUNDS = {
    "enh4-listing": (enh4_listing_bound, f"(3.1) + (3.2) + 2(2m − n), {_LISTING}: Algorithm 3.1's passes with H "
                                         "pruned, and line 22's 2Σ(d_k − 1) ≤ 2(2m − n) expansion traversals (§4.2)"),
    "enh5-d2-listing": (enh5_d2_listing_bound, f"(3.1) + (3.2) + 2m·min((n − 1)(n − 2), 2m − 2), {_LISTING}: "
                                               "Algorithm 3.1's passes with H pruned, and line 7's walk to every place "
                                               "within distance 2 of v_u on each of the m passes"),
}


def _as_listed(name: str) -> AlgorithmSpec:
    """A Chapter 4 listing as written, registered beside the composition that changes it (module docstring)."""
    enh, explorer = AS_LISTED[name], LISTING_EXPLORERS[name]
    thesis = f"{enh.section}, as listed"
    if name not in _LISTING_BOUNDS:  # Enhancement-3 adds no motion (§4.1): Algorithm 3.1's own bound
        return lighthouse_algorithm(name, thesis, explorer, f"{BOUND}, inherited (§4.1 adds no motion)")
    bound_fn, formula = _LISTING_BOUNDS[name]
    return lighthouse_algorithm(name, thesis, explorer, "O(m²n) (Chapter 4); bound_fn: topomark's, for the listing as "
                                "written", bound_fn=bound_fn, bound_formula=formula, bound_source="listing")


SPECS = (
    lighthouse_algorithm("basic", "§3.3, Algorithm 3.1", LighthouseExplorer),
    *(_enhancement(name) for name in ENHANCEMENTS),
    *(_as_listed(name) for name in AS_LISTED),
)

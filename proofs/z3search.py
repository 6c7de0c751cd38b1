"""Bounded search for indistinguishable, non-isomorphic world pairs with Z3 (thesis §3.2, §3.7, §6.1).

The thesis shows that some marker classes do not let a robot map every world
(§3.2.1 Figure 3.3: no marker; §3.2.2 Figure 3.4: one undirected vertex marker;
§3.7 Figure 3.21(a): two undirected vertex markers; §6.1 Figure 6.1(a): one
undirected edge marker) by exhibiting two worlds that are *indistinguishable*
(every motion sequence gives the same perception sequence, §3.1.1) but not
extended-isomorphic.  It argues that the other classes (a directional vertex
marker §3.3, three undirected markers Figure 3.21(b), a directional edge marker
§6.1, a vertex and an edge marker §6.2) always suffice.  This module asks Z3
the same question within bounds: *is there a pair of worlds with at most N
vertices and degrees at most D that is indistinguishable and not isomorphic?*

:func:`search` answers ``found`` (with a re-checked pair), ``none`` (UNSAT for
every size pair: no counterexample within the bounds) or ``unknown`` (the
solver gave up or timed out — never reported as ``none``).  :func:`prove`
runs the same search for a sufficient class and reports it as a bounded proof.

Encoding (one solver per size pair n_A <= n_B; the relation is symmetric)
-----------------------------------------------------------------------------
Each part lives in its own module, whose docstring gives the details:

* :mod:`topomark.proofs.z3formula` -- the SMT-LIB formula builder and its
  connectives;
* :mod:`topomark.proofs.z3world` -- one world as variables (degrees, targets,
  motions), the symmetry breaking that gives each world with its start
  exactly one encoding, and the optional planarity (genus 0) constraint;
* :mod:`topomark.proofs.z3markers` -- the class's markers at the start
  vertex 0 and the signature features a robot senses;
* :mod:`topomark.proofs.z3pair` -- indistinguishability (a bisimulation
  relating the starts, §3.1.1) and non-isomorphism (a defect in every
  anchored propagation of a candidate extended isomorphism, §3.1.3);
* :mod:`topomark.proofs.z3decode` -- decoding a model into two worlds and
  re-checking them with the specification's own predicates;
* :mod:`topomark.proofs.z3fixing` -- pinning the encoding to a given pair
  (:func:`pair_is_model`), to test it on the thesis's figures;
* :mod:`topomark.proofs.z3results` -- the result records.

This module drives the search and re-exports the names above.

*Bounds.*  Size pairs are tried smallest first (larger world, then total),
so the first ``found`` is smallest in the larger world's size; for a pair
the degree bound is clamped to n_B - 1 (a simple graph has no larger degree).

*Validation* (``tests/test_z3search.py``, :mod:`topomark.proofs.bench_z3`):
the single-world encoding has exactly one model per placed world up to
start-preserving isomorphism (model counting, with and without planarity);
found/none and the smallest size agree with brute-force enumeration for all
eight classes up to 5 vertices and degree 4; with both worlds pinned
(:func:`pair_is_model`) the formula accepts the thesis's counterexample
pairs (Figures 3.3, 3.4, 3.21(a), 6.1(a)) and rejects the distinguishable
ones (Figures 3.6, 3.21(b), 6.1(b)) and isomorphic pairs.

Every model is decoded into two worlds and re-checked with the
specification's own predicates (:mod:`topomark.proofs.z3decode`); a failure
raises :class:`CheckFailure` because it means this encoding is wrong.

>>> r = search("none", 4, 2)   # Figure 3.3: cycles of different lengths
>>> r.outcome, sorted(w.n for w in r.worlds), str(r.perceptions[0])
('found', [3, 4], '[2,A,A]')
"""

from __future__ import annotations

import time

import z3

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.markerclass import marker_class
from topomark.spec.spelling import option

from topomark.proofs.z3decode import covering_walk, decode_pair, reachable_relation, recheck
from topomark.proofs.z3fixing import canonical_labelling, pair_is_model
from topomark.proofs.z3formula import Builder  # noqa: F401 - re-exported for tests/test_z3search.py
from topomark.proofs.z3pair import PairEncoding
from topomark.proofs.z3results import ProofReport, SearchResult, SizeCheck, relation_to_json
from topomark.proofs.z3world import WorldVars  # noqa: F401 - re-exported for tests/test_z3search.py

__all__ = [
    "SearchResult", "ProofReport", "SizeCheck", "search", "prove", "size_pairs", "decode_pair",
    "recheck", "covering_walk", "canonical_labelling", "pair_is_model", "reachable_relation", "relation_to_json",
    "SUFFICIENT", "SYMMETRY_BREAKING", "MAX_VERTICES",
]

MAX_VERTICES = 8
SUFFICIENT = ("directional-vertex", "directional-edge", "vertex-and-edge", "three-undirected-vertex")
SYMMETRY_BREAKING = (
    "start = vertex 0 facing exit 0",
    "vertices numbered in BFS order from the start (exits explored in index order)",
    "exit 0 of every other vertex is its BFS-parent edge (canonical: one encoding per world and start)",
    "markers anchored at vertex 0 (head/marked neighbour/marked edge via one exit variable)",
    "pairs ordered n_A <= n_B",
)



# -- driver ---------------------------------------------------------------------------
def size_pairs(max_vertices: int, min_vertices: int = 2) -> list[tuple[int, int]]:
    """Size pairs n_A <= n_B in the order searched: smaller largest world first, then smaller total."""
    pairs = [(x, y) for x in range(min_vertices, max_vertices + 1) for y in range(x, max_vertices + 1)]
    return sorted(pairs, key=lambda p: (p[1], p[0] + p[1], p[0]))


def _validate(marker: str, max_vertices: int, max_degree: int, min_vertices: int) -> None:
    marker_class(marker)
    if not isinstance(max_vertices, int) or max_vertices < 2:
        raise InvalidInput(f"{option('max-vertices')} must be an integer >= 2 (a world has at least 2 vertices), "
                           f"got {max_vertices!r}")
    if max_vertices > MAX_VERTICES:
        raise InvalidInput(f"{option('max-vertices', max_vertices)} is too large for the solver (at most {MAX_VERTICES})")
    if not isinstance(max_degree, int) or max_degree < 1:
        raise InvalidInput(f"{option('max-degree')} must be an integer >= 1, got {max_degree!r}")
    if not isinstance(min_vertices, int) or not 2 <= min_vertices <= max_vertices:
        raise InvalidInput(f"min_vertices must be between 2 and {max_vertices}, got {min_vertices!r}")


def _check_pair(marker, n_a, n_b, dmax, remaining, planar=False):
    started = time.monotonic()
    enc = PairEncoding(marker, n_a, n_b, dmax, planar)
    solver = z3.SolverFor("QF_FD")
    if remaining is not None:
        left = remaining - (time.monotonic() - started)
        if left <= 0:
            return z3.unknown, None, enc
        solver.set("timeout", max(1, int(left * 1000)))
    solver.from_string(enc.b.text())
    verdict = solver.check()
    return verdict, solver, enc


def search(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
           min_vertices: int = 2, planar: bool = False) -> SearchResult:
    """Look for a counterexample of ``marker`` with at most ``max_vertices`` vertices and degree ``max_degree``.

    Size pairs are tried smallest first, so a ``found`` pair is smallest in
    the larger world's size.  ``timeout`` (seconds) bounds the whole search.
    With ``planar=True`` both worlds must be planar embeddings (genus 0, like
    the thesis's drawings); by default any orientable embedding is allowed
    (§3.1.1: "not necessarily a planar surface").
    """
    _validate(marker, max_vertices, max_degree, min_vertices)
    t0 = time.monotonic()
    result = SearchResult("none", marker, max_vertices, max_degree, 0.0, planar=planar)
    for n_a, n_b in size_pairs(max_vertices, min_vertices):
        remaining = None if timeout is None else timeout - (time.monotonic() - t0)
        if remaining is not None and remaining <= 0:
            result.outcome, result.reason = "unknown", "timeout"
            break
        t1, c1 = time.monotonic(), time.process_time()
        dmax = min(max_degree, n_b - 1)  # a simple graph on n_b vertices has no larger degree
        verdict, solver, enc = _check_pair(marker, n_a, n_b, dmax, remaining, planar)
        result.checks.append(SizeCheck(n_a, n_b, str(verdict), time.monotonic() - t1, time.process_time() - c1))
        if verdict == z3.sat:
            _fill_found(result, marker, solver.model(), enc, planar)
            break
        if verdict == z3.unknown:
            why = solver.reason_unknown() if solver is not None else "timeout"
            result.outcome, result.reason = "unknown", "timeout" if "timeout" in why or "canceled" in why else why
            if remaining is not None:
                break
    result.seconds = time.monotonic() - t0
    return result


def _fill_found(result: SearchResult, marker: str, model, enc, planar: bool = False) -> None:
    a, b, rel = decode_pair(model, enc)
    if planar and (a.genus(), b.genus()) != (0, 0):
        raise CheckFailure(f"decoded worlds have genus {a.genus()} and {b.genus()}, not planar")
    recheck(marker, a, b, rel)
    reach = reachable_relation(a, b)
    recheck(marker, a, b, reach)
    motions, perceptions = covering_walk(a, b)
    from topomark.spec.robot import perceive
    if list(perceptions) != perceive(b, b.start_state(), motions):
        raise CheckFailure("the covering walk perceives differently in the two worlds")
    result.outcome, result.reason = "found", ""
    result.worlds, result.relation = (a, b), reach
    result.motions, result.perceptions = motions, perceptions


def prove(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
          planar: bool = False) -> ProofReport:
    """Show there is no counterexample for ``marker`` within the bounds (UNSAT for every size pair)."""
    t0 = time.monotonic()
    res = search(marker, max_vertices, max_degree, timeout, planar=planar)
    outcome = {"none": "proved", "found": "counterexample", "unknown": "unknown"}[res.outcome]
    bounds = {"max_vertices": max_vertices, "max_degree": max_degree, "min_vertices": 2,
              "size_pairs": len(size_pairs(max_vertices)), "planar_only": planar}
    return ProofReport(outcome, marker, bounds, SYMMETRY_BREAKING, f"z3 {z3.get_version_string()}",
                       time.monotonic() - t0, res)

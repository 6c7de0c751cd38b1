"""Re-checking one iteration's hypothesis records against the rebuilt map (thesis §3.3 lines 8-20, §3.4).

:func:`check_hypotheses` judges the ``hypotheses`` of an ``iteration``
record (``spec/trace.md``) with S and U as they were when H was formed
(e already taken out of U), and returns the first
:class:`~topomark.spec.errors.Violation` or None:

S carries the marks the robot sensed (the lighthouse's at v0 and those seen
at new vertices, :mod:`~topomark.reference.replay.algorithm31_layer`), so every expected
perception below includes them, whatever the lighthouse (§6.1).

* **H**: every recorded e' = (v_k', i') is a hypothesis of line 8: a dart of
  U, v_k' ≠ v_k, whose end shows v_u's signature in S
  (:func:`~topomark.spec.signature.signature_at`); none is listed twice; the
  record lists all of H except the ``pruned`` hypotheses its ``enhancement``
  counters claim (only Enhancements 4/5 prune); the order is the header's
  hypothesis policy (:meth:`~topomark.reference.explorers.policies.Policies.
  order_hypotheses`, over U's order and |M|);
* **(M, P^E)**: M is a simple path of S from v_k' (entered by e') to v0 and
  P^E the signatures S shows along it (lines 11-12); **Lemma 1** on the pairs
  (:func:`~topomark.spec.invariants.check_lemma1`, the checker's own);
* **outcomes**: ``perceived`` agrees with ``outcome`` — case 3 sensed all of
  P^E, case 1/2 matched P^E up to a mismatch before/at the end of M,
  ``untested`` sensed nothing; ``rejected_by`` is one the algorithm uses
  (``overlap``: Enhancement 1's stage 1; ``map``: tracing, Enhancements 2/3)
  and only on a case 1/2; ``without_motion`` counts them;
* **truth**: at most one case 3; a loop join not made by the marker has
  exactly one, and it is the joined e' (the true join: I-1, checked after the
  join, proves the joined dart is the world's); a non-loop join has none and
  no ``untested``; a rejected hypothesis is never the joined dart.

Not checked, because the trace does not carry what it would take: which
``validation`` move sensed which entry of ``perceived`` (the moves themselves
are replayed on the world), the ``perceived`` of hypotheses rejected without
motion (``overlap``/``map``: they rest on earlier perceptions the trace does
not attribute), and whether M is the path the path policy picks (any simple
path to v0 serves §3.3).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from topomark.spec.errors import Violation
from topomark.spec.invariants import check_lemma1
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.policies import Policies
from topomark.reference.trace.reader import signature

__all__ = ["check_hypotheses"]

V0 = 0
_WITHOUT_MOTION = ("overlap", "map")


@dataclass(frozen=True)
class _Hyp:
    dart: MapDart
    motions: tuple[int, ...]
    expected: tuple[Signature, ...]
    perceived: tuple[Signature, ...]
    outcome: str
    rejected_by: str


def _read(h: dict[str, Any], where: str) -> _Hyp:
    return _Hyp(tuple(h["dart"]), tuple(h["motions"]), tuple(signature(x, where) for x in h["expected"]),
                tuple(signature(x, where) for x in h["perceived"]), h["outcome"], h.get("rejected_by", ""))


def check_hypotheses(S: PartialMap, rec: dict[str, Any], sig: Signature, policies: Policies, enhancement,
                     it: str, where: str) -> Violation | None:
    """The first false claim among ``rec``'s hypotheses (see the module docstring), or None."""
    hyps = [_read(h, where) for h in rec["hypotheses"]]
    counters = rec.get("enhancement")
    for check in (_in_H(S, rec, sig, hyps, counters, enhancement, policies), _paths(S, hyps),
                  check_lemma1(hyps), _outcomes(hyps, counters, enhancement), _truth(rec, hyps)):
        if check is not None:
            return Violation(check.check, check.where, check.expected, check.found,
                             it + (f"; {check.detail}" if check.detail else ""))
    return None


def _bad(where: str, expected: str, found: str, detail: str = "") -> Violation:
    return Violation("hypothesis", where, expected, found, detail)


def _in_H(S: PartialMap, rec: dict, sig: Signature, hyps: list[_Hyp], counters: dict | None, enhancement,
          policies: Policies) -> Violation | None:
    vk = rec["edge"][0]
    H = [d for d in S.unexplored if d[0] != vk and S.degree(d[0]) == sig.degree and signature_at(S, *d) == sig]
    members = set(H)
    seen: set[MapDart] = set()
    for h in hyps:
        if h.dart not in members:
            found = ("not in U" if h.dart not in S.unexplored else f"at v_k = {vk}" if h.dart[0] == vk
                     else "a dart whose end shows another signature")
            return _bad(f"hypothesis {list(h.dart)}", f"e' in H: a dart of U off v_k whose end shows {sig}", found,
                        "Algorithm 3.1 line 8")
        if h.dart in seen:
            return _bad(f"hypothesis {list(h.dart)}", "each hypothesis listed once", "listed twice")
        seen.add(h.dart)
    pruned = counters["pruned"] if counters is not None else 0
    if pruned and not (enhancement is not None and enhancement.prune):
        return _bad("enhancement.pruned", "0 (this algorithm does not prune H)", str(pruned))
    if len(H) - len(hyps) != pruned:
        missing = [list(d) for d in H if d not in seen]
        return _bad("hypotheses", f"H = {[list(d) for d in H]} ({len(H)} darts) less {pruned} pruned",
                    f"{len(hyps)} listed", f"not listed: {missing[:5]}")
    position = {d: k for k, d in enumerate(S.unexplored)}
    in_U_order = sorted(hyps, key=lambda h: position[h.dart])
    want = [h.dart for h in policies.order_hypotheses(in_U_order, [len(h.motions) for h in in_U_order])]
    if want != [h.dart for h in hyps]:
        return _bad("hypotheses", f"the {policies.hypothesis} hypothesis policy's order {[list(d) for d in want]}",
                    str([list(h.dart) for h in hyps]))
    return None


def _paths(S: PartialMap, hyps: list[_Hyp]) -> Violation | None:
    for h in hyps:
        where = f"hypothesis {list(h.dart)}"
        if not h.motions or len(h.motions) != len(h.expected):
            return _bad(where, "M and P^E of one length >= 1", f"|M| = {len(h.motions)}, |P^E| = {len(h.expected)}")
        x, entry = h.dart
        visited = {x}
        for k, (m, want) in enumerate(zip(h.motions, h.expected)):
            if not 0 <= m < S.degree(x):
                return _bad(where, f"motion {k + 1} of M an exit 0..{S.degree(x) - 1}", str(m))
            t = S.arc((x, (entry + m) % S.degree(x)))
            if t is None:
                return _bad(where, f"motion {k + 1} of M along an explored edge of S", "an unexplored exit")
            x, entry = t
            if signature_at(S, x, entry) != want:
                return _bad(where, f"P^E[{k}] = {signature_at(S, x, entry)} (S's signature there)", str(want))
            if x in visited:
                return _bad(where, "M a simple path (lines 11-12)", f"map vertex {x} visited twice")
            visited.add(x)
        if x != V0:
            return _bad(where, "M ending at v0", f"M ending at map vertex {x}")
    return None


def _outcomes(hyps: list[_Hyp], counters: dict | None, enhancement) -> Violation | None:
    tracing = enhancement.trace if enhancement is not None else ""
    for h in hyps:
        where = f"hypothesis {list(h.dart)}"
        if h.rejected_by:
            allowed = {"motion"} if enhancement is not None else set()
            allowed |= {"overlap"} if tracing == "path" else {"map"} if tracing else set()
            if h.rejected_by not in allowed:
                return _bad(where, f"rejected_by one of {sorted(allowed)} (this algorithm)", repr(h.rejected_by))
            if h.outcome not in ("case 1", "case 2"):
                return _bad(where, "rejected_by only on a rejected hypothesis (case 1 or 2)", h.outcome)
            if h.rejected_by in _WITHOUT_MOTION:
                continue
        bad = _sensed(h)
        if bad is not None:
            return _bad(where, bad[0], bad[1], f"outcome {h.outcome}")
    without = sum(h.rejected_by in _WITHOUT_MOTION for h in hyps)
    if counters is not None and counters["without_motion"] != without:
        return _bad("enhancement.without_motion", f"{without} (hypotheses rejected by overlap or map)",
                    str(counters["without_motion"]))
    return None


def _sensed(h: _Hyp) -> tuple[str, str] | None:
    """What ``perceived`` should be for the outcome, and what it is, or None if they agree."""
    got = [str(s) for s in h.perceived]
    if h.outcome == "untested":
        return None if not got else ("nothing perceived", str(got))
    if h.outcome == "case 3":
        return None if h.perceived == h.expected else (f"perceived = P^E = {[str(s) for s in h.expected]}", str(got))
    k = len(h.perceived) - 1
    last = len(h.motions) - 1
    if k < 0 or k > last or h.perceived[:k] != h.expected[:k] or h.perceived[k] == h.expected[k]:
        return ("perceptions matching P^E up to one mismatch", str(got))
    if (k == last) != (h.outcome == "case 2"):
        return (f"{'case 2' if k == last else 'case 1'} (the mismatch is at motion {k + 1} of {last + 1})",
                h.outcome)
    return None


def _truth(rec: dict, hyps: list[_Hyp]) -> Violation | None:
    far = tuple(rec["joined"][1])
    confirmed = [h for h in hyps if h.outcome == "case 3"]
    if len(confirmed) > 1:
        return _bad("hypotheses", "at most one confirmed (case 3)", str([list(h.dart) for h in confirmed]))
    for h in hyps:
        if h.outcome in ("case 1", "case 2") and rec["augmentation"] == "loop" and h.dart == far:
            return _bad(f"hypothesis {list(h.dart)}", "a rejected hypothesis not the true join",
                        f"rejected ({h.outcome}) yet joined")
    if rec["augmentation"] == "loop" and not rec["by_marker"]:
        if not confirmed or confirmed[0].dart != far:
            return _bad("hypotheses", f"the joined e' = {list(far)} confirmed (case 3, line 19)",
                        f"confirmed: {[list(h.dart) for h in confirmed]}")
    if rec["augmentation"] == "non-loop":
        if confirmed:
            return _bad("hypotheses", "none confirmed before a non-loop join (line 22)",
                        f"{list(confirmed[0].dart)} confirmed")
    if not confirmed and any(h.outcome == "untested" for h in hyps):
        return _bad("hypotheses", "untested only after a confirmation",
                    str([list(h.dart) for h in hyps if h.outcome == "untested"]))
    return None

"""Recorded perceptions at unknown places: the store T of Enhancement-3 and D of Enhancements 4/5 (§4.1–4.2).

Algorithm 4.3 line 2 keeps T, "a container to store perceptions of
unexplored edges"; lines 36–37: "based on validated place v_u and back-link
e, trace all executed motions in validating e, and add to T the perceptions
from unknown places".  A record is keyed by the unexplored map dart (x, t)
its path leaves S by, and is a trie of perceptions beyond it, indexed by
relative exits: ``v_x-3-[4,A,A]-2-[2,A,A]-1-[3,A,A]-2-[5,A,A]`` (Figure 4.5).
Algorithms 4.4/4.5 keep D, "neighbor signature info of known places": the
same kind of record, limited to depth d, made only when v_u is new — here it
lives in the same T.

* :func:`record_trie` — after the join, route the iteration's execution trie
  from the validated (v_u, e) through S into T (nodes deeper than the
  technique's depth, and the ``virtual`` node, are left out).
* :func:`migrate` — when a dart with a record becomes explored, the record
  moves to wherever the dart now leads.
* :func:`graft` — a record under the dart e = (v_k, i) describes paths from
  v_u: it joins the iteration's trie as known perceptions before any motion.

Every routing compares the recorded perception with S's signature where the
record meets S: a contradiction means the map is wrong.  With a lighthouse of
explicit place and back-link the map cannot be (Lemma 1, §3.4): a bug,
:class:`~topomark.spec.errors.ExplorerFault`; with one that is not explicit
the thesis predicts it, a wrong loop closing (§5.2.1): the ``failed`` outcome
(:func:`~topomark.reference.explorers.inconsistency.inconsistent`).
"""

from __future__ import annotations

from collections import Counter
from typing import Callable

from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.execution_trie import ExecutionTrie, TrieNode
from topomark.reference.explorers.inconsistency import inconsistent

__all__ = ["Record", "record_trie", "migrate", "graft"]


class Record:
    """A record of T: the signature sensed beyond an unexplored dart, and what lies beyond (Figure 4.5)."""

    __slots__ = ("sig", "children")

    def __init__(self, sig: Signature):
        self.sig = sig
        self.children: dict[int, Record] = {}


def _contradiction(S: PartialMap, where: str, far: MapDart, sig: Signature, light,
                   detail: str = "a perception contradicts the map") -> Exception:
    return inconsistent(light, f"Enhancement-3 record at {where}: {detail} (perceived {sig}, the map has "
                               f"{signature_at(S, far[0], far[1])})", "Lemma 1 (§3.4)")


def _absorb(S: PartialMap, T: dict, stats: Counter, dart: MapDart, node, keep: Callable, light=None) -> None:
    """Route ``node``'s children (trie nodes or records) from map dart ``dart`` into S / T."""
    x, entry = dart
    for m, child in node.children.items():
        if isinstance(child, TrieNode) and not keep(child):
            continue
        t = (x, (entry + m) % S.degree(x))
        far = S.arc(t)
        if far is not None:
            if signature_at(S, far[0], far[1]) != child.sig:
                raise _contradiction(S, f"map dart {far}", far, child.sig, light)
            _absorb(S, T, stats, far, child, keep, light)
        else:
            rec = T.get(t)
            if rec is None:
                rec = T[t] = Record(child.sig)
                stats["recorded"] += 1
            _merge(stats, rec, child, keep)


def _merge(stats: Counter, rec: Record, node, keep: Callable) -> None:
    for m, child in node.children.items():
        if isinstance(child, TrieNode) and not keep(child):
            continue
        sub = rec.children.get(m)
        if sub is None:
            sub = rec.children[m] = Record(child.sig)
            stats["recorded"] += 1
        _merge(stats, sub, child, keep)


def record_trie(S: PartialMap, T: dict, stats: Counter, trie: ExecutionTrie, root: MapDart, depth: float,
                light=None) -> None:
    """Trace the iteration's trie from the validated (v_u, e) = ``root`` and store, to ``depth``, what lies
    beyond unexplored darts (Algorithm 4.3 lines 36–37; Algorithm 4.4 line 22, 4.5 line 23 with depth d)."""

    def keep(node: TrieNode) -> bool:
        return node.kind != "virtual" and node.depth <= depth

    _absorb(S, T, stats, root, trie.root, keep, light)


def migrate(S: PartialMap, T: dict, stats: Counter, darts, light=None) -> None:
    """Records under darts that just became explored move to where those darts lead."""
    for dart in darts or ():
        rec = T.pop(dart, None)
        if rec is not None:
            far = S.target(dart)
            if signature_at(S, far[0], far[1]) != rec.sig:
                raise _contradiction(S, f"T[{dart}]", far, rec.sig, light, "a recorded perception contradicts the map")
            _absorb(S, T, stats, far, rec, lambda _: True, light)


def graft(T: dict, trie: ExecutionTrie, edge: MapDart, light=None) -> int:
    """Perceptions recorded beyond e are perceptions of paths from v_u: add them to the trie before any motion.

    Returns how many nodes the trie gained.
    """
    rec = T.get(edge)
    if rec is None:
        return 0
    if rec.sig != trie.root.sig:
        raise inconsistent(light, f"Enhancement-3 record at T[{edge}]: the recorded perception {rec.sig} "
                                  f"contradicts the robot's senses, {trie.root.sig}", "Lemma 1 (§3.4)")
    return trie.graft(trie.root, rec)

"""Expanded local signatures: Enhancement-4 (of new vertices) and Enhancement-5 (of the current place) (§4.2).

Algorithm 3.1 ignores that for h' = (e', v_k') to hold, the unknown end
v_u' of e' must correspond to v_k, so its signature must be v_k's.  These
techniques invest extra traversals (purpose ``expansion``) to know more of
each place's neighbourhood, kept in D (records of T,
:mod:`~topomark.reference.explorers.records`, to depth d, made only when
v_u is new):

:class:`ExpandedSignaturesOfNewVertices` — Enhancement-4, Algorithm 4.4.
    After a non-loop augmentation the robot senses each other neighbour of
    the new vertex (out and back) and records D (line 22); e' is a
    hypothesis only if v_k' shows v_u's signature *and* the recorded far end
    of e' shows v_k's signature (seen from e) (line 7).
:class:`ExpandedSignaturesOfCurrentPlace` — Enhancement-5, Algorithm 4.5,
    distance d.  On entering v_u the robot senses every place within
    distance d of v_u reachable through v_u's other exits (line 7; d = 2: the
    neighbours' other neighbours as well), then H keeps only hypotheses whose
    known neighbourhood (S, and D of earlier new vertices) agrees with
    everything sensed, including the far end of e' against v_k (line 8); a
    new v_u's expansion is recorded into D without motion (line 23).

The filter traces everything known around v_u — the ``virtual`` node for v_k
behind e, records grafted from T, the expansion — on S and T from each
hypothesized (v_k', e'), as Enhancement-3 traces executed paths.

Choices (the thesis is silent): a neighbour already sensed during this
iteration (validation, or a record) is not visited again; v_k's side of v_u's
distance-2 neighbourhood is not walked (v_k is in S; its known neighbours
are not re-sensed).  The first changes Algorithm 4.4 line 22's moves (``enh4``)
and Algorithm 4.5 line 7's with d = 2 (``enh5-d2``): their registrations say so
(``changes``).  With d = 1 (``enh5-d1``) nothing is known at v_u's other exits
on entering it (a record beyond e holds v_u's own signature only), so it
follows Algorithm 4.5 step by step: lines 1–6, 9–22 are Algorithm 3.1's
(:mod:`.algorithm31`); line 7 → :meth:`ExpandedSignaturesOfCurrentPlace.on_enter`
(:func:`expand`); line 8 → ``prune`` (v_k behind e, ``known_on_entering``);
line 23 → ``recorded_depth``.  With ``as_listed`` a technique walks every place
within d, sensed before or not (:func:`walk_every`): Algorithm 4.4 line 22 and
Algorithm 4.5 line 7 to the letter, the explorers ``enh4-listing`` and
``enh5-d2-listing`` (:mod:`~topomark.reference.explorers.enhancements_as_listed`).
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.spec.signature import signature_at

from topomark.reference.explorers.enhanced import Technique
from topomark.reference.explorers.execution_trie import ExecutionTrie, TrieNode
from topomark.reference.explorers.tracing import ExecutedPathsOnSAndUnknownPlaces

__all__ = ["ExpandedSignaturesOfNewVertices", "ExpandedSignaturesOfCurrentPlace", "expand", "walk_every"]

_ON_S_AND_D = ExecutedPathsOnSAndUnknownPlaces()


def expand(trie: ExecutionTrie, it, d: int) -> None:
    """Sense every place reachable from the robot's node by 1..d motions through exits other than the entry."""
    start = trie.at

    def missing(node: TrieNode, depth: int) -> bool:
        if depth == 0:
            return False
        for m in range(1, node.sig.degree):
            child = node.children.get(m)
            if child is None or missing(child, depth - 1):
                return True
        return False

    def walk(depth: int) -> None:
        node = trie.at
        for m in range(1, node.sig.degree):
            child = node.children.get(m)
            if child is not None and not missing(child, depth - 1):
                continue
            trie.forward(m, "expansion")
            it.expansion += 1
            if depth > 1:
                walk(depth - 1)
            trie.back("expansion")
            it.expansion += 1

    walk(d)
    assert trie.at is start


def walk_every(trie: ExecutionTrie, it, d: int) -> None:
    """Algorithm 4.4 line 22 and 4.5 line 7 as listed: walk to every place within distance d through exits other
    than the entry, out and back, whether it was sensed before or not."""
    start = trie.at
    for m in range(1, trie.at.sig.degree):
        trie.forward(m, "expansion")
        it.expansion += 1
        if d > 1:
            walk_every(trie, it, d - 1)
        trie.back("expansion")
        it.expansion += 1
    assert trie.at is start


@dataclass(frozen=True)
class _ExpandedSignatures(Technique):
    """What Enhancements 4 and 5 share: v_k known behind e, H filtered, D recorded for new vertices to depth d."""

    d: int = 1
    as_listed: bool = False  # walk every place within d, sensed before or not (Algorithm 4.4 line 22, 4.5 line 7)
    prunes = True

    def known_on_entering(self, explorer, it) -> None:
        """The robot came from v_k through e: motion 0 from v_u reaches v_k entered by exit i (in S)."""
        trie = explorer.trie
        if 0 not in trie.root.children:
            vk, i = it.edge
            trie.add(trie.root, 0, signature_at(explorer.P, vk, i), "virtual")

    def prune(self, explorer, it, found: list) -> list:
        """H keeps only hypotheses whose expanded signature agrees with everything known around v_u."""
        states = explorer.states(_ON_S_AND_D, found)
        new = explorer.trie.new
        kept = [h for h in found if _ON_S_AND_D.contradiction(explorer, h, states[id(h)], new, None, it) is None]
        it.pruned += len(found) - len(kept)
        explorer.stats["pruned"] += len(found) - len(kept)
        return kept

    def recorded_depth(self, new: bool) -> float:
        return self.d if new else 0


@dataclass(frozen=True)
class ExpandedSignaturesOfNewVertices(_ExpandedSignatures):
    """Enhancement-4: sense the neighbours of each new vertex (Algorithm 4.4 line 22)."""

    section = "§4.2, Enhancement-4, Algorithm 4.4"
    expands_new = True

    def after_non_loop(self, explorer, it) -> None:
        (walk_every if self.as_listed else expand)(explorer.trie, it, self.d)


@dataclass(frozen=True)
class ExpandedSignaturesOfCurrentPlace(_ExpandedSignatures):
    """Enhancement-5: sense every place within distance d of v_u on entering it (Algorithm 4.5 line 7)."""

    section = "§4.2, Enhancement-5, Algorithm 4.5"

    @property
    def expands_place(self) -> int:
        return self.d

    def on_enter(self, explorer, it) -> None:
        (walk_every if self.as_listed else expand)(explorer.trie, it, self.d)

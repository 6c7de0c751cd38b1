"""The choices Algorithm 3.1 leaves open, as named deterministic policies (thesis §3.3).

* **edge policy** — which unexplored edge e to take from U (line 5):
  ``nearest`` (default: the entry of U whose known end is nearest the robot in
  S, ties broken by U's order), ``fifo`` (oldest entry first), ``lifo``
  (newest entry first), or any edge choice registered by name
  (:mod:`~topomark.reference.explorers.edge_choices`).
* **hypothesis policy** — the order hypotheses are removed from H (line 10):
  ``fifo`` (default: U's order), ``lifo``, ``shortest`` (shortest validation
  path first, ties by U's order).
* **path policy** — which simple path to v0 validates a hypothesis (line 11):
  ``shortest`` (default: the path in a breadth-first tree of S rooted at v0,
  exits scanned in index order), ``dfs`` (the path in a depth-first tree).
  Either way one tree per iteration serves every hypothesis.
"""

from __future__ import annotations

from collections import deque
from typing import Container, cast

from topomark.spec.errors import ExplorerFault, unknown_name
from topomark.spec.mapstate import MapDart, PartialMap

from topomark.reference.explorers.edge_choices import BUILT_IN, EDGE_CHOICES

__all__ = ["EDGE_POLICIES", "HYPOTHESIS_POLICIES", "PATH_POLICIES", "Policies", "bfs", "bfs_preorder", "in_preorder",
           "nearest", "open_ends_beyond", "parents_toward", "tree_to_v0"]

EDGE_POLICIES = BUILT_IN
"""The built-in edge policies; :data:`~topomark.reference.explorers.edge_choices.EDGE_CHOICES` holds them all."""
HYPOTHESIS_POLICIES = ("fifo", "lifo", "shortest")
PATH_POLICIES = ("shortest", "dfs")


class Policies:
    """A validated choice of edge, hypothesis and path policy."""

    def __init__(self, edge: str = "nearest", hypothesis: str = "fifo", path: str = "shortest"):
        for name, value, allowed in (("edge", edge, tuple(EDGE_CHOICES)), ("hypothesis", hypothesis, HYPOTHESIS_POLICIES),
                                     ("path", path, PATH_POLICIES)):
            if value not in allowed:
                raise unknown_name(f"{name} policy", value, allowed)
        self.edge, self.hypothesis, self.path = edge, hypothesis, path

    def to_json(self) -> dict[str, str]:
        return {"edge": self.edge, "hypothesis": self.hypothesis, "path": self.path}

    def next_edge(self, S: PartialMap, root: int) -> tuple[MapDart, dict[int, MapDart]]:
        """Remove the next e from U (:meth:`choose_edge`, the robot at ``root``) and return it with the parent
        darts of :func:`bfs` from ``root`` that lead to its end.  For ``nearest`` the search stops after the
        first layer holding an end listed in U: e is the first entry of U with an end in that layer (the same
        choice and parents as a whole search; U keeps its ends and answers which entry comes first, see
        :class:`~topomark.spec.unexplored.Unexplored`); other policies, and a subclass that chooses its own way,
        search the whole map."""
        if self.edge == "nearest" and type(self).choose_edge is Policies.choose_edge:
            U = S.unexplored
            found, _, parent = _layers(S, root, U.ends())
            return U.pop(cast(int, U.first_at(found))), parent  # _layers stops at a layer with an end in U
        dist, _, parent = bfs(S, root)
        return self.choose_edge(S, dist), parent

    def choose_edge(self, S: PartialMap, dist: dict[int, int]) -> MapDart:
        """Remove and return the next e from U (Algorithm 3.1's line 5) as the edge policy's choice
        (:data:`~topomark.reference.explorers.edge_choices.EDGE_CHOICES`); ``dist`` holds distances in S from
        the robot.  A choice that names no entry of U is a bug of the choice, not of the run's input."""
        U = S.unexplored
        k = EDGE_CHOICES[self.edge](S, dist)
        if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k < len(U):
            raise ExplorerFault(f"the edge choice {self.edge!r} returned {k!r}, not an index of U (0..{len(U) - 1})")
        return U.pop(k)

    def order_hypotheses(self, hypotheses: list, lengths: list[int]) -> list:
        if self.hypothesis == "lifo":
            return hypotheses[::-1]
        if self.hypothesis == "shortest":
            order = sorted(range(len(hypotheses)), key=lambda k: (lengths[k], k))
            return [hypotheses[k] for k in order]
        return list(hypotheses)


def bfs(S: PartialMap, root: int) -> tuple[dict[int, int], dict[int, int], dict[int, MapDart]]:
    """Breadth-first over S's explored edges, exits scanned in index order.

    Returns per reached vertex its distance from ``root``, the exit that leads
    one step toward ``root``, and the parent dart (parent, exit) it was reached by.  The last search of each
    map is kept (S only grows: its journal's length names its state), so asking again before S changes is
    free; callers read the result and never mutate it.
    """
    key = (len(S.journal), root)
    memo = getattr(S, "_bfs_memo", None)
    if memo is not None and memo[0] == key:
        return memo[1]
    memo = (key, _bfs(S, root))
    setattr(S, "_bfs_memo", memo)  # kept on the map itself, not a field of PartialMap
    return memo[1]


def _bfs(S: PartialMap, root: int) -> tuple[dict[int, int], dict[int, int], dict[int, MapDart]]:
    dist, toward, parent = {root: 0}, {}, {}
    todo = deque([root])
    links, n = S.links, S.n
    while todo and len(dist) < n:  # every vertex reached: nothing more can be added (8x on dense maps)
        v = todo.popleft()
        d = dist[v] + 1
        for i, t in enumerate(links(v)):
            if t is not None and t[0] not in dist:
                dist[t[0]] = d
                toward[t[0]] = t[1]
                parent[t[0]] = (v, i)
                todo.append(t[0])
    return dist, toward, parent


def nearest(S: PartialMap, root: int, wanted: Container[int]) -> tuple[int | None, dict[int, MapDart]]:
    """The vertex of ``wanted`` nearest ``root`` in S (the least-numbered among the nearest; None if none is
    reached) and the parent darts of :func:`bfs` from ``root``, the search stopped after that vertex's layer —
    the same parents, for every vertex it reached, at a fraction of a whole search when the vertex is near."""
    found, _, parent = _layers(S, root, wanted)
    return (min(found) if found else None), parent


def _layers(S: PartialMap, root: int, wanted: Container[int]) -> tuple[list[int], dict[int, int], dict[int, MapDart]]:
    """:func:`bfs` layer by layer from ``root``, stopped after the first layer holding a vertex of ``wanted``:
    those vertices, and the distances and parents of every vertex reached (bfs's, as the queue meets the
    layers in the same order)."""
    parent: dict[int, MapDart] = {}
    dist, layer, d = {root: 0}, [root], 0
    if root in wanted:
        return [root], dist, parent
    joined = S.joined
    while layer:
        d, found, following = d + 1, [], []
        for v in layer:
            for i, w in joined(v):
                if w not in dist:
                    dist[w], parent[w] = d, (v, i)
                    following.append(w)
                    if w in wanted:
                        found.append(w)
        if found:
            return found, dist, parent
        layer = following
    return [], dist, parent


def parents_toward(S: PartialMap, root: int, target: int) -> dict[int, MapDart]:
    """:func:`bfs`'s parent darts from ``root``, enough to walk to ``target``: the kept search if S and the
    root are unchanged since, else bfs's queue stopped once it meets ``target`` (the same parents)."""
    memo = getattr(S, "_bfs_memo", None)
    if memo is not None and memo[0] == (len(S.journal), root):
        return memo[1][2]
    return _parents_until(S, root, {target})


def _parents_until(S: PartialMap, root: int, wanted: set[int]) -> dict[int, MapDart]:
    """:func:`bfs`'s queue from ``root``, stopped as it meets the last vertex of ``wanted`` (or S is exhausted):
    the parent dart of each vertex met, bfs's (the queue meets them in the same order; a vertex met has its
    tree path's vertices met before it)."""
    seen, parent, todo = {root}, {}, deque([root])
    left = len(wanted - seen)
    joined = S.joined
    while todo and left:
        v = todo.popleft()
        for i, w in joined(v):
            if w not in seen:
                seen.add(w)
                parent[w] = (v, i)
                todo.append(w)
                if w in wanted:
                    left -= 1
                    if not left:
                        return parent
    return parent


def open_ends_beyond(S: PartialMap, vk: int) -> set[int]:
    """The ends listed in U other than ``vk`` and its neighbours in S: the known vertices a new edge from
    ``vk`` could reach (not v_k, S has no self-loop; not a neighbour, S has no multi-edge)."""
    near = {vk} | {w for _, w in S.joined(vk)}
    return {v for v in S.unexplored.ends() if v not in near}


def in_preorder(S: PartialMap, root: int, chosen: set[int]) -> list[int]:
    """The vertices of ``chosen`` in :func:`bfs_preorder` from ``root``: a vertex's place in that preorder is its
    path's exits from the root, compared as sequences (children go by exit; an ancestor, a prefix, first), so
    bfs's queue need only run until it has met them all (S is connected: fewer than two need no search)."""
    if len(chosen) < 2:
        return list(chosen)
    parent = _parents_until(S, root, chosen)

    def exits_from_root(v: int) -> list[int]:  # preorder is the order of these, compared as sequences
        path = []
        while v != root:
            v, i = parent[v]
            path.append(i)
        return path[::-1]
    return sorted(chosen, key=exits_from_root)


def bfs_preorder(S: PartialMap, root: int) -> list[int]:
    """The vertices of :func:`bfs`'s tree of S in preorder (children by the exit their parent reaches them by):
    the order in which a robot walking that tree depth-first from ``root`` first meets them."""
    _, _, parent = bfs(S, root)
    children: dict[int, list[int]] = {}
    for child, (up, _exit) in sorted(parent.items(), key=lambda kv: kv[1][1]):
        children.setdefault(up, []).append(child)
    order, todo = [], [root]
    while todo:
        v = todo.pop()
        order.append(v)
        todo.extend(reversed(children.get(v, ())))
    return order


def _dfs(S: PartialMap, root: int) -> dict[int, int]:
    toward: dict[int, int] = {}
    seen = {root}
    stack = [(root, 0)]
    while stack:
        v, i = stack.pop()
        if i >= S.degree(v):
            continue
        stack.append((v, i + 1))
        t = S.arc((v, i))
        if t is not None and t[0] not in seen:
            seen.add(t[0])
            toward[t[0]] = t[1]
            stack.append((t[0], 0))
    return toward


def tree_to_v0(S: PartialMap, policy: Policies, v0: int = 0) -> dict[int, int]:
    """For each vertex of S, the exit that leads one step closer to v0 along the policy's tree."""
    return bfs(S, v0)[1] if policy.path == "shortest" else _dfs(S, v0)

"""U, the unexplored darts, as an ordered list that keeps count of what it holds (thesis §3.1.3, §3.4).

Algorithm 3.1 keeps U as an explicit list (line 3: "U ← incident edges in v_0"; line 5: "remove an unexplored
edge e from U"; line 8: H from U's edges; line 25: "remove e' from U"; line 28: "add other edges in v_u to U"),
so that an explorer which forgets an entry, or lists one twice, is caught by invariant I-2 rather than hidden
by a derived value (:mod:`topomark.spec.mapstate`).  Three questions are asked of U every iteration, and each
was a pass over it — O(|U|), and |U| grows to about 2m on a complete world, so O(m²) over a run:

* which map vertices have an entry in U (the nearest-first choice of line 5, §3.3; the candidates of the §6.2
  footprint searches) — :meth:`Unexplored.ends`;
* which entry, first in U's order, has its end in a given set (the nearest-first tie-break) —
  :meth:`Unexplored.first_at`; and which entries, in U's order, leave a few given vertices (the candidates'
  entries of edgeINFO, §6.2.2; the hypotheses of Algorithm 3.1 and Case 5's phase II) — :meth:`Unexplored.at`;
* does U list every open dart exactly once (I-2, the checker) — answered by the checker from
  :attr:`Unexplored.changes`, the entries added and removed, in order, which it counts for itself.

:class:`Unexplored` is a ``list`` (U's order, indexing, equality with lists are a list's) that keeps those
counts as it changes.  Entries carry increasing stamps while U only grows at its end (``append``, ``extend``)
and loses entries (``pop``, ``remove``, ``del U[k]``); any other change (``insert``, assignment, slices,
``sort``, ``reverse``, ``clear``) renumbers them, a pass over U.  An entry that is not a dart ``(int, int)``
is kept (U takes an explorer's input as it is; I-2 names it) and is no vertex's entry.

Examples
--------
>>> U = Unexplored([(0, 0), (0, 1), (0, 2)])
>>> U.extend([(1, 1), (1, 2)]); U.pop(1)
(0, 1)
>>> sorted(U.ends()), U.first_at({1}), U.first_at({2}), U.at([1, 0])
([0, 1], 2, None, [(0, 0), (0, 2), (1, 1), (1, 2)])
>>> U.remove((0, 0)); U.remove((0, 2)); sorted(U.ends())
[1]
>>> U.changes[-2:]
[(-1, (0, 0)), (-1, (0, 2))]
"""

from __future__ import annotations

from bisect import bisect_left
from itertools import chain
from typing import Any, Callable, Iterable, KeysView, SupportsIndex

__all__ = ["Unexplored"]


def _first(pair: tuple[Any, ...]) -> Any:
    return pair[0]


def _end(entry: Any) -> int | None:
    """The map vertex a dart ``(v, i)`` leaves; None for anything that is not a dart."""
    if type(entry) is tuple and len(entry) == 2 and type(entry[0]) is int:
        return entry[0]
    return None


class Unexplored(list[Any]):
    """U: a list of map darts that keeps, per end vertex, its entries by stamp in U's order."""

    __slots__ = ("_stamps", "_by_end", "_next", "changes")

    def __init__(self, entries: Iterable[Any] = ()) -> None:
        super().__init__()
        self.changes: list[tuple[int, Any]] = []  # (+1, entry) added, (-1, entry) removed, in order
        self._stamps: list[int] = []  # one per entry, increasing along U
        self._by_end: dict[int, dict[int, Any]] = {}  # end vertex -> {stamp: entry}, stamps increasing
        self._next = 0
        self.extend(entries)

    def __reduce__(self) -> tuple[type[Unexplored], tuple[list[Any]]]:
        return (Unexplored, (list(self),))  # a copy keeps U's entries and order (not its history)

    # -- the questions ---------------------------------------------------------
    def ends(self) -> KeysView[int]:
        """The map vertices that have an entry in U (the set ``{v for v, _ in U}``, kept)."""
        return self._by_end.keys()

    def first_at(self, ends: Iterable[int]) -> int | None:
        """The index of U's first entry whose end is in ``ends``; None if there is none."""
        by_end = self._by_end
        stamps = [next(iter(by_end[v])) for v in ends if v in by_end]
        return bisect_left(self._stamps, min(stamps)) if stamps else None

    def at(self, ends: Iterable[int]) -> list[Any]:
        """The entries whose end is in ``ends`` (each vertex once), in U's order."""
        by_end = self._by_end
        mine = [by_end[v] for v in dict.fromkeys(ends) if v in by_end]
        if len(mine) == 1:
            return list(mine[0].values())
        return [entry for _, entry in sorted(chain.from_iterable(d.items() for d in mine), key=_first)]

    # -- changes kept incrementally ---------------------------------------------
    def append(self, entry: Any) -> None:
        super().append(entry)
        self._stamps.append(self._next)
        v = _end(entry)
        if v is not None:
            self._by_end.setdefault(v, {})[self._next] = entry
        self._next += 1
        self.changes.append((1, entry))

    def extend(self, entries: Iterable[Any]) -> None:
        for entry in list(entries):  # U.extend(U) adds U's entries once, as a list does
            self.append(entry)

    # list's own += takes any iterable too; typeshed's list.__add__ takes only lists, hence the ignore
    def __iadd__(self, entries: Iterable[Any]) -> "Unexplored":  # type: ignore[misc]
        self.extend(entries)
        return self

    def pop(self, index: SupportsIndex = -1) -> Any:
        entry = super().pop(index)
        stamp = self._stamps.pop(index)
        v = _end(entry)
        if v is not None:
            mine = self._by_end[v]
            del mine[stamp]
            if not mine:
                del self._by_end[v]
        self.changes.append((-1, entry))
        return entry

    def remove(self, entry: Any) -> None:
        try:
            index = self.index(entry)
        except ValueError:
            raise ValueError("list.remove(x): x not in list") from None
        self.pop(index)

    def __delitem__(self, index: SupportsIndex | slice) -> None:
        if isinstance(index, slice):
            self._rewrite(list.__delitem__, index)
        else:
            self.pop(index)

    # -- every other change: a pass over U ------------------------------------------
    def _rewrite(self, change: Callable[..., Any], *args: Any) -> Any:
        before = list(self)
        result = change(self, *args)
        self.changes.extend((-1, entry) for entry in before)
        self.changes.extend((1, entry) for entry in self)
        self._renumber()
        return result

    def _renumber(self) -> None:
        self._stamps = list(range(len(self)))
        self._by_end = {}
        for stamp, entry in enumerate(self):
            v = _end(entry)
            if v is not None:
                self._by_end.setdefault(v, {})[stamp] = entry
        self._next = len(self)

    def insert(self, index: SupportsIndex, entry: Any) -> None:
        self._rewrite(list.insert, index, entry)

    def __setitem__(self, index: Any, value: Any) -> None:
        self._rewrite(list.__setitem__, index, value)

    def __imul__(self, times: SupportsIndex) -> "Unexplored":
        self._rewrite(list.__imul__, times)
        return self

    def clear(self) -> None:
        self._rewrite(list.clear)

    def sort(self, *args: Any, **kwargs: Any) -> None:
        list.sort(self, *args, **kwargs)
        self._renumber()  # the same entries: nothing added or removed

    def reverse(self) -> None:
        list.reverse(self)
        self._renumber()

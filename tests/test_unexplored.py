"""U keeps its ends, its first entry at a set of ends, and its record of changes, through every list change
(spec/unexplored.py): each answer is compared with the pass over U it replaces."""

from __future__ import annotations

import copy
import pickle
from collections import Counter

import pytest
from hypothesis import given, settings, strategies as st

from topomark.spec.mapstate import PartialMap
from topomark.spec.unexplored import Unexplored

darts = st.tuples(st.integers(0, 5), st.integers(0, 3))
entries = st.one_of(darts, darts, darts, st.just([0, 0]), st.just((1,)), st.just("x"))

# every way a list can change: (name, arguments drawn, how to apply it to U and to a plain list alike)
CHANGES = st.one_of(
    st.tuples(st.just("append"), entries),
    st.tuples(st.just("extend"), st.lists(entries, max_size=4)),
    st.tuples(st.just("iadd"), st.lists(entries, max_size=3)),
    st.tuples(st.just("pop"), st.integers(-8, 8)),
    st.tuples(st.just("remove"), darts),
    st.tuples(st.just("del"), st.integers(-8, 8)),
    st.tuples(st.just("delslice"), st.tuples(st.integers(0, 6), st.integers(0, 6))),
    st.tuples(st.just("insert"), st.tuples(st.integers(-8, 8), darts)),
    st.tuples(st.just("set"), st.tuples(st.integers(-8, 8), darts)),
    st.tuples(st.just("setslice"), st.tuples(st.integers(0, 6), st.lists(darts, max_size=3))),
    st.tuples(st.just("imul"), st.integers(0, 2)),
    st.tuples(st.just("clear"), st.none()),
    st.tuples(st.just("sort"), st.none()),
    st.tuples(st.just("reverse"), st.none()),
)


def apply(U: list, change) -> list:
    """Apply one change; the value it returns, or the exception it raises (a list and U must agree on both)."""
    name, arg = change
    try:
        if name == "append":
            U.append(arg)
        elif name == "extend":
            U.extend(arg)
        elif name == "iadd":
            U += arg
        elif name == "pop":
            return U.pop(arg)
        elif name == "remove":
            U.remove(arg)
        elif name == "del":
            del U[arg]
        elif name == "delslice":
            del U[arg[0]:arg[1]]
        elif name == "insert":
            U.insert(*arg)
        elif name == "set":
            U[arg[0]] = arg[1]
        elif name == "setslice":
            U[arg[0]:arg[0] + 1] = arg[1]
        elif name == "imul":
            U *= arg
        elif name == "clear":
            U.clear()
        elif name == "sort":
            U.sort(key=repr)
        else:
            U.reverse()
    except (IndexError, ValueError) as exc:
        return type(exc)
    return None


def is_dart(x) -> bool:
    return type(x) is tuple and len(x) == 2 and type(x[0]) is int


def first_at_by_pass(U: list, ends: set) -> int | None:
    return next((k for k, x in enumerate(U) if is_dart(x) and x[0] in ends), None)


@settings(max_examples=300, deadline=None)
@given(st.lists(entries, max_size=6), st.lists(CHANGES, max_size=25), st.sets(st.integers(0, 6)))
def test_U_answers_as_a_pass_over_it_would(start, changes, asked):
    """After any sequence of list changes: U is the list, ends() is {v for darts (v, i) in U}, first_at is the
    first such entry, and replaying the record of changes gives U's entries."""
    U, plain = Unexplored(start), list(start)
    for change in changes:
        assert apply(U, change) == apply(plain, change)
        assert U == plain and type(U) is Unexplored
        assert set(U.ends()) == {x[0] for x in U if is_dart(x)}
        assert U.first_at(asked) == first_at_by_pass(U, asked)
        for v in U.ends():
            assert U.first_at({v}) == first_at_by_pass(U, {v})
            assert U.at([v]) == [x for x in U if is_dart(x) and x[0] == v]
        assert U.at(sorted(asked, reverse=True)) == [x for x in U if is_dart(x) and x[0] in asked]
    replayed: Counter = Counter()
    for sign, entry in U.changes:
        replayed[repr(entry)] += sign
    assert {k: c for k, c in replayed.items() if c} == Counter(repr(x) for x in U)


def test_a_copy_is_a_U_with_the_same_entries():
    U = Unexplored([(0, 1), (2, 0), (0, 2)])
    U.pop(0)
    for other in (copy.copy(U), copy.deepcopy(U), pickle.loads(pickle.dumps(U))):
        assert type(other) is Unexplored and other == U and other is not U
        assert set(other.ends()) == {0, 2} and other.first_at({0}) == 1


def test_a_map_keeps_U_as_an_Unexplored_and_shares_one_given():
    """Assigning a list to S.unexplored makes U a copy of it; assigning another map's U shares it (a marker walk's
    S and M have one U)."""
    S, M = PartialMap(), PartialMap()
    given_list = [(0, 0)]
    S.unexplored = given_list
    assert type(S.unexplored) is Unexplored and S.unexplored == [(0, 0)] and S.unexplored is not given_list
    S.unexplored = M.unexplored
    M.unexplored.append((0, 1))
    assert S.unexplored is M.unexplored and S.unexplored == [(0, 1)]
    assert type(S.copy().unexplored) is Unexplored


@pytest.mark.parametrize("bad", [(1,), [0, 0], "x", (True, 0), ("a", 0)])
def test_an_entry_that_is_not_a_dart_is_kept_but_is_no_vertex_s(bad):
    U = Unexplored([bad, (3, 1)])
    assert U == [bad, (3, 1)] and set(U.ends()) == {3} and U.first_at({3}) == 1

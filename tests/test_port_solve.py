"""Maps consistent with records (:mod:`topomark.proofs.port_consistent`, :mod:`topomark.reference.port.solve`):
every answer replayed, pinning checked against the truth, brute force on tiny worlds, seeded faults."""

from __future__ import annotations

import itertools
import json
import random

import pytest
from hypothesis import given, settings, strategies as st

from topomark.proofs.port_consistent import ConsistentSearch
from topomark.reference.port import solve as solve_module
from topomark.reference.port.judge import Verdict, judge
from topomark.reference.port.generate import cover, random_port_world
from topomark.reference.port.solve import exchange_from_json, solve_records
from topomark.reference.port.solve_separate import canonical_form, separating_plan
from topomark.spec.errors import InvalidInput, InvalidWorld, TopomarkFault
from topomark.spec.port_plan import Action, parse_plan, plan_text, run_plan
from topomark.spec.port_world import PortWorld, from_joins


def random_plans(seed: int, world: PortWorld, count: int, length: int, marks: bool = False) -> list:
    rng = random.Random(seed)
    plans = []
    for _ in range(count):
        text = ""
        for _ in range(length):
            if marks and rng.random() < 0.2:
                text += f"[{rng.randrange(world.alphabet)}]"
            text += str(rng.randrange(world.doors))
        plans.append(parse_plan(text, doors=world.doors, alphabet=world.alphabet))
    return plans


def check_solution(truth: PortWorld, plans, records, echo: bool = True) -> str:
    """Solve, then check the answer from outside: records replayed, verdict against the truth."""
    sol = solve_records(plans, records, truth.rooms, doors=truth.doors, alphabet=truth.alphabet, echo_marks=echo)
    assert sol.status in ("pinned", "ambiguous")  # the truth itself is consistent
    for world in filter(None, (sol.first, sol.second)):
        assert [run_plan(world, p, echo_marks=echo) for p in plans] == list(records)
    if sol.status == "pinned":
        assert canonical_form(sol.first) == canonical_form(truth)
        assert separating_plan(sol.first, truth) is None
        assert judge(sol.first, truth, echo_marks=echo).equivalent
    else:
        assert sol.witness is not None and sol.first is not None and sol.second is not None
        assert run_plan(sol.first, sol.witness, echo_marks=echo) != run_plan(sol.second, sol.witness, echo_marks=echo)
        assert canonical_form(sol.first) != canonical_form(sol.second)
        verdict = judge(sol.first, sol.second, echo_marks=echo)
        assert not verdict.equivalent and verdict.witness == plan_text(sol.witness)
    return sol.status


@pytest.mark.parametrize("seed", range(6))
def test_solutions_reproduce_records_and_pinning_finds_the_truth(seed):
    truth = random_port_world(seed, 2 + seed % 3, doors=3, alphabet=3)
    plans = random_plans(seed, truth, 2, 6 * truth.rooms, marks=seed % 2 == 1)
    check_solution(truth, plans, [run_plan(truth, p) for p in plans])


def test_a_contest_sized_three_room_map_is_pinned_by_enough_plans():
    truth = random_port_world(11, 3)
    plans = random_plans(4, truth, 6, 18, marks=True)
    assert check_solution(truth, plans, [run_plan(truth, p) for p in plans]) == "pinned"


def test_few_plans_leave_the_map_ambiguous_with_a_replayed_witness():
    truth = random_port_world(11, 3)
    plans = [parse_plan("0")]
    assert check_solution(truth, plans, [run_plan(truth, p) for p in plans]) == "ambiguous"


def test_records_without_the_echo():
    truth = random_port_world(5, 3, doors=3, alphabet=3)
    plans = random_plans(9, truth, 3, 9, marks=True)
    check_solution(truth, plans, [run_plan(truth, p, echo_marks=False) for p in plans], echo=False)


def test_marks_tell_a_cover_from_its_base():
    """A 2-copy map and its base give the same records without marks; with marks (and 2n rooms asked) they don't."""
    base = random_port_world(3, 2, doors=3, alphabet=2)
    double = cover(base, 2, seed=1)
    plans = random_plans(2, double, 4, 12, marks=True)
    records = [run_plan(double, p) for p in plans]
    sol = solve_records(plans, records, 4, doors=3, alphabet=2)
    assert sol.first is not None
    assert [run_plan(sol.first, p) for p in plans] == records


@settings(max_examples=12, deadline=None)
@given(st.builds(random_port_world, st.integers(0, 2**32), st.integers(1, 3), doors=st.integers(2, 3),
                 alphabet=st.integers(2, 3)), st.integers(0, 2**16))
def test_hypothesis_worlds(truth, seed):
    plans = random_plans(seed, truth, 2, 4 * truth.rooms, marks=seed % 3 == 0)
    check_solution(truth, plans, [run_plan(truth, p) for p in plans])


def test_an_altered_record_gives_no_map_or_another():
    """Seeded fault: one colour of a record changed; the truth no longer fits and the solver does not return it."""
    truth = random_port_world(11, 3)
    plans = random_plans(4, truth, 6, 18)
    records = [list(run_plan(truth, p)) for p in plans]
    records[2][7] = (records[2][7] + 1) % 4
    sol = solve_records(plans, [tuple(r) for r in records], 3)
    assert sol.status == "none" or canonical_form(sol.first) != canonical_form(truth)


def test_no_map_of_too_few_rooms():
    one = solve_records([parse_plan("0")], [(0, 1)], 1)
    assert one.status == "none"


# -- brute force on tiny worlds ----------------------------------------------------------------------------------

def all_worlds(rooms: int, doors: int, alphabet: int):
    ends = [(r, d) for r in range(rooms) for d in range(doors)]

    def matchings(left):
        if not left:
            yield []
            return
        e, rest = left[0], left[1:]
        yield from ([(e, e)] + m for m in matchings(rest))
        for k, f in enumerate(rest):
            yield from ([(e, f)] + m for m in matchings(rest[:k] + rest[k + 1:]))

    for passages in matchings(ends):
        for colours in itertools.product(range(alphabet), repeat=rooms):
            try:
                yield from_joins(list(colours), passages, 0, doors=doors, alphabet=alphabet)
            except InvalidWorld:
                continue  # not every room reachable


@pytest.mark.parametrize("rooms,doors", [(1, 2), (2, 1), (2, 2)])
def test_against_brute_force(rooms, doors):
    worlds = list(all_worlds(rooms, doors, 2))
    rng = random.Random(rooms * 10 + doors)
    for trial in range(12):
        truth = rng.choice(worlds)
        plans = random_plans(trial, truth, 1 + trial % 2, 1 + trial % 4, marks=trial % 2 == 0)
        records = [run_plan(truth, p) for p in plans]
        if trial % 4 == 3:
            records[0] = (records[0][0] ^ 1,) + records[0][1:]  # seeded fault: no world of these may fit
        fits = {canonical_form(w) for w in worlds if [run_plan(w, p) for p in plans] == records}
        sol = solve_records(plans, records, rooms, doors=doors, alphabet=2)
        want = "none" if not fits else "pinned" if len(fits) == 1 else "ambiguous"
        assert sol.status == want, (plans, records)
        if sol.first is not None:
            assert canonical_form(sol.first) in fits


def test_each_canonical_form_is_found_once():
    """Symmetry breaking: with no records, the solver enumerates each rooted world exactly once."""
    worlds = list(all_worlds(2, 2, 1))
    search = ConsistentSearch(2, [()], [(0,)], doors=2, alphabet=1)
    found = []
    while (f := search.find(unlike=found[-1:])).status == "found":
        found.append(f.world)
    forms = [canonical_form(w) for w in found]
    assert len(forms) == len(set(forms)) == len({canonical_form(w) for w in worlds})
    assert all(form[1] == canonical_form(w)[1] for form, w in zip(forms, found))


# -- the separating plan ---------------------------------------------------------------------------------------

@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**32), st.integers(1, 4), st.integers(1, 4), st.integers(2, 3), st.booleans())
def test_two_deciders_of_equivalence_agree(seed, n1, n2, doors, copy):
    a = random_port_world(seed, n1, doors=doors, alphabet=2)
    b = cover(a, 2, seed) if copy else random_port_world(seed + 1, n2, doors=doors, alphabet=2)
    plan = separating_plan(a, b)
    assert (plan is None) == (canonical_form(a) == canonical_form(b)) == judge(a, b).equivalent
    if plan is not None:
        assert run_plan(a, plan) != run_plan(b, plan)


def test_a_relabelled_copy_is_equivalent():
    a = random_port_world(8, 5)
    perm = [0, 3, 1, 4, 2]
    joins = [None] * 5
    for r in range(5):
        joins[perm[r]] = tuple((perm[r2], d2) for r2, d2 in a.joins[r])
    colours = [0] * 5
    for r in range(5):
        colours[perm[r]] = a.colours[r]
    b = PortWorld(tuple(colours), tuple(joins), 0)
    assert separating_plan(a, b) is None and canonical_form(a) == canonical_form(b)


def test_a_fault_in_the_decoder_is_caught(monkeypatch):
    """Seeded fault: Z3's world replaced by another; the replay of the records refuses it."""
    truth = random_port_world(11, 3)
    plans = random_plans(4, truth, 2, 18)
    other = random_port_world(12, 3)
    monkeypatch.setattr(ConsistentSearch, "_decode", lambda self, model: other)
    with pytest.raises(TopomarkFault, match="does not give record"):
        solve_records(plans, [run_plan(truth, p) for p in plans], 3)


def test_a_fault_in_the_separator_is_caught(monkeypatch):
    """Seeded fault: the separator says no plan tells Z3's two maps apart; the cross-check refuses."""
    truth = random_port_world(11, 3)
    monkeypatch.setattr(solve_module, "separating_plan", lambda a, b, echo_marks=True: None)
    with pytest.raises(TopomarkFault, match="no plan separates"):
        solve_records([parse_plan("0")], [run_plan(truth, parse_plan("0"))], 3)


def test_the_judge_disagreeing_with_z3_is_caught(monkeypatch):
    """Seeded fault: the judge calls Z3's two different maps equivalent; the cross-check refuses (exit 3)."""
    truth = random_port_world(11, 3)
    monkeypatch.setattr(solve_module, "judge", lambda a, b, **kw: Verdict(True, None, None, "seeded"))
    with pytest.raises(TopomarkFault, match="the judge finds them equivalent"):
        solve_records([parse_plan("0")], [run_plan(truth, parse_plan("0"))], 3)


def test_a_fault_in_the_blocking_clause_is_caught(monkeypatch):
    """Seeded fault: the second search ignores ``unlike``; the canonical forms show the 'second' map is the first."""
    truth = random_port_world(11, 3)
    plans = random_plans(4, truth, 6, 18, marks=True)
    real = ConsistentSearch.find
    monkeypatch.setattr(ConsistentSearch, "find", lambda self, unlike=(), timeout=None: real(self, timeout=timeout))
    with pytest.raises(TopomarkFault, match="canonical form"):
        solve_records(plans, [run_plan(truth, p) for p in plans], 3)


def test_a_timeout_is_unknown_not_a_verdict():
    truth = random_port_world(2, 12)
    plans = random_plans(1, truth, 3, 72)
    sol = solve_records(plans, [run_plan(truth, p) for p in plans], 12, timeout=0.001)
    assert sol.status == "unknown" and "timeout" in sol.reason


# -- input ---------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("obj,message", [
    ({"plans": ["0"], "results": [[0, 1]], "id": "team-secret"}, "unknown key 'id'"),
    ({"plans": ["07"], "results": [[0, 1, 2]]}, r"plans\[0\]: plan character 2"),
    ({"plans": ["0"], "results": []}, "1 plans but 0 results"),
    ({"plans": ["0"]}, "'results' is missing"),
    ({"plans": ["0"], "results": [[0, True]]}, r"results\[0\]\[1\]"),
])
def test_bad_exchanges(obj, message):
    with pytest.raises(InvalidInput, match=message) as e:
        exchange_from_json(obj)
    assert "team-secret" not in str(e.value)


@pytest.mark.parametrize("record,message", [((0,), "has 1 colours"), ((0, 7), "not a colour"),
                                            ((0, 1, 2), "echo of mark")])
def test_bad_records(record, message):
    plan = parse_plan("0[1]") if len(record) == 3 else parse_plan("0")
    with pytest.raises(InvalidInput, match=message):
        ConsistentSearch(2, [plan], [record])


def test_the_command(tmp_path, capsys):
    from topomark.reference.cli.main import main

    truth = random_port_world(11, 3)
    plans = random_plans(4, truth, 6, 18, marks=True)
    exchange = tmp_path / "ex.json"
    exchange.write_text(json.dumps({"plans": [plan_text(p) for p in plans],
                                    "results": [list(run_plan(truth, p)) for p in plans], "queryCount": 7}))
    out = tmp_path / "map.json"
    assert main(["port", "solve", str(exchange), "--rooms", "3", "-o", str(out), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "pinned" and json.loads(out.read_text()) == data["map"]
    assert main(["port", "solve", str(exchange), "--rooms", "3", "-o", str(out)]) == 2  # no --force
    assert "--force" in capsys.readouterr().err
    assert main(["port", "solve", str(exchange), "--rooms", "2"]) == 1
    assert "no map of 2 rooms" in capsys.readouterr().out
    exchange.write_text(json.dumps({"plans": ["1"], "results": [list(run_plan(truth, parse_plan("1")))]}))
    assert main(["port", "solve", str(exchange), "--rooms", "3", "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["status"] == "ambiguous" and data["records"][0] != data["records"][1]
    assert main(["port", "solve", str(exchange), "--rooms", "3", "--doors", "11"]) == 2
    assert main(["port", "solve", str(exchange), "--rooms", "0"]) == 2
    assert main(["port", "solve", str(exchange), "--rooms", "3", "--doors", "3", "-o", str(tmp_path / "m")]) == 2
    assert "-o writes a contest map" in capsys.readouterr().err

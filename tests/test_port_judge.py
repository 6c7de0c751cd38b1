"""The exact judge of port maps: two deciders per step cross-checked, witnesses replayed, seeded faults caught,
minimise, the suite and the CLI (topomark.reference.port.judge and its neighbours)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from topomark.reference.cli.main import main
from topomark.reference.port import exhaustive, judge as judge_module, minimise as minimise_module
from topomark.reference.port.generate import cover, random_port_world
from topomark.reference.port.judge import judge, replayed
from topomark.reference.port.minimise import minimise
from topomark.reference.port.plain import refine, separating_word
from topomark.reference.port.rooted import canonical_form, isomorphism
from topomark.reference.port.suite import run_suite, summary
from topomark.reference.port.variants import door_permuted, passage_swapped, relabelled
from topomark.spec.errors import TopomarkFault
from topomark.spec.port_plan import doors_in, parse_plan
from topomark.spec.port_world import from_joins

DATA = Path(__file__).parent / "data" / "icfpc2025"

worlds = st.builds(random_port_world, st.integers(0, 2**32), st.integers(1, 8), doors=st.integers(2, 4),
                   alphabet=st.integers(1, 3))

# The smallest pair that differs only in how parallel passages pair their door-ends: one room, two doors.
SELF = from_joins([0], [((0, 0), (0, 0)), ((0, 1), (0, 1))], 0, doors=2, alphabet=2)
CROSSED = from_joins([0], [((0, 0), (0, 1))], 0, doors=2, alphabet=2)


def test_pairing_of_parallel_doors_is_invisible():
    v = judge(SELF, CROSSED)
    assert v.equivalent and v.witness is None
    assert isomorphism(SELF, CROSSED) == {0: 0}


@settings(max_examples=60, deadline=None)
@given(worlds, worlds)
def test_plain_deciders_agree(a, b):
    equal, _ = refine(a, b)
    word = separating_word(a, b)
    assert equal == (word is None)
    if word is not None:
        assert replayed(a, b, "".join(map(str, word)))


@settings(max_examples=60, deadline=None)
@given(worlds, st.integers(0, 2**32))
def test_relabelled_is_equivalent_and_forms_agree(w, seed):
    import random
    perm = list(range(w.rooms))
    random.Random(seed).shuffle(perm)
    r = relabelled(w, perm)
    assert judge(w, r).equivalent
    assert isomorphism(w, r) is not None and canonical_form(w) == canonical_form(r)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**32), st.integers(1, 5), st.integers(2, 3))
def test_cover_differs_from_base_only_with_a_mark(seed, rooms, copies):
    base = random_port_world(seed, rooms, alphabet=2)
    c = cover(base, copies, seed)
    v = judge(base, c)
    assert not v.equivalent and v.witness is not None and "[" in v.witness
    assert v.witness.count("[") == 1 and doors_in(parse_plan(v.witness)) <= 3 * c.rooms
    m, mb = minimise(c), minimise(base)
    assert [len(f) for f in m.fibres] == [copies * len(f) for f in mb.fibres]  # a cover's blocks lie over the base's
    if mb.quotient is None:  # the base's blocks differ in size: so do the cover's, and neither has a port quotient
        assert m.quotient is None and m.copies is None
    else:
        assert m.quotient is not None and m.copies == copies * (mb.copies or 0)
        assert separating_word(m.quotient, c) is None and judge(m.quotient, mb.quotient).equivalent


def test_exhaustive_small_worlds_agree_with_brute_force():
    worlds_ = exhaustive.enumerate_worlds(1, 2, 2) + exhaustive.enumerate_worlds(2, 2, 2)
    found = exhaustive.check(worlds_, max_doors=6)
    assert found["agree"], found
    assert found["longest"] == 2


def test_seeded_fault_wrong_witness_is_caught(monkeypatch):
    base = random_port_world(3, rooms=4)
    monkeypatch.setattr(judge_module, "marked_witness", lambda a, b: ((), 0, (0,)))  # "[0]0": says nothing
    with pytest.raises(TopomarkFault, match="same record"):
        judge(base, cover(base, 2, seed=5))


def test_seeded_fault_plain_deciders_disagree(monkeypatch):
    a = from_joins([0, 1], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=2)
    b = door_permuted(a, 1, [1, 0])
    monkeypatch.setattr(judge_module, "separating_word", lambda a, b: None)
    with pytest.raises(TopomarkFault, match="disagree"):
        judge(a, b, names=("A", "B"))


def test_seeded_fault_rooted_deciders_disagree(monkeypatch):
    base = random_port_world(3, rooms=4)
    monkeypatch.setattr(judge_module, "canonical_form", lambda w: id(w))
    with pytest.raises(TopomarkFault, match="canonical forms"):
        judge(base, relabelled(base, [3, 2, 1, 0]))


def test_seeded_fault_bad_quotient_is_caught(monkeypatch):
    base = random_port_world(3, rooms=4)
    monkeypatch.setattr(minimise_module, "_quotient", lambda w, fibres, of: door_permuted(base, 0, [1, 0, 2, 3, 4, 5]))
    with pytest.raises(TopomarkFault, match="not plainly equivalent"):
        minimise(cover(base, 2, seed=5))


def test_unequal_blocks_have_no_quotient():
    # room 0 and room 2 are plainly equivalent, room 1 alone: blocks of sizes 2 and 1
    w = from_joins([0, 1, 0], [((0, 0), (1, 0)), ((2, 0), (1, 1)), ((0, 1), (0, 1)), ((2, 1), (2, 1))], 0, doors=2,
                   alphabet=2)
    m = minimise(w)
    assert m.quotient is None and m.copies is None and sorted(map(len, m.fibres)) == [1, 2]


def test_passage_swap_changes_or_not():
    w = random_port_world(11, rooms=6)
    ends = [x for x, y in w.passages() if x != y]
    changed = passage_swapped(w, ends[0], ends[1])
    v = judge(w, changed)
    assert v.equivalent or replayed(w, changed, v.witness or "")


def test_suite_on_the_copied_maps():
    results = run_suite(DATA)
    s = summary(results)
    assert s["maps"] == s["imported"] == s["ok"] == s["minimal_as_manifest"] >= 3
    assert s["kinds"]["relabelled"]["equivalent"] == s["maps"]  # type: ignore[index]


def test_suite_flags_a_wrong_manifest(tmp_path):
    manifest = tmp_path / "MANIFEST.tsv"
    manifest.write_text("file\tminimal_rooms\naleph/000.json\t7\n")
    results = run_suite(DATA, manifest)
    assert [r.file for r in results if not r.ok] == ["aleph/000.json"]


def test_cli_judge_and_minimise(tmp_path, capsys):
    aleph = str(DATA / "aleph" / "000.json")
    assert main(["port", "judge", aleph, aleph]) == 0
    out = tmp_path / "q.json"
    assert main(["port", "minimise", aleph, "-o", str(out), "--json"]) == 0
    assert json.loads(capsys.readouterr().out.split("\n", 1)[1])["copies"] == 2
    assert main(["port", "judge", aleph, str(out), "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert "[" in data["witness"] and data["records"]["a"] != data["records"]["b"]
    assert main(["port", "minimise", aleph, "-o", str(out)]) == 2  # exists: --force needed
    bad = tmp_path / "bad.json"
    bad.write_text('{"problemName": "x", "map": {"rooms": [0], "startingRoom": 0, "connections": []}, "id": "t"}')
    assert main(["port", "judge", str(bad), aleph]) == 2
    assert "'id'" in capsys.readouterr().err


def test_cli_fault_is_exit_3(monkeypatch, capsys):
    aleph = str(DATA / "aleph" / "000.json")
    monkeypatch.setattr(judge_module, "isomorphism", lambda a, b: None)  # a broken decider: forms still agree
    assert main(["port", "judge", aleph, aleph]) == 3
    assert "000.json" in capsys.readouterr().err


def test_cli_suite_bad_manifest_is_exit_2(tmp_path, capsys):
    assert main(["port", "suite", str(DATA), "--manifest", str(tmp_path / "missing.tsv")]) == 2
    bad = tmp_path / "bad.tsv"
    bad.write_text("file\tminimal_rooms\naleph/000.json\tsix\n")
    assert main(["port", "suite", str(DATA), "--manifest", str(bad)]) == 2
    assert "line 2" in capsys.readouterr().err

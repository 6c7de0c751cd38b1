"""``topomark replay`` checks every claim a trace records, or rejects the record (spec/trace.md, issue 15 item 11).

Each case takes a real trace of ``topomark explore``, tampers with one claim
and runs the real CLI: a false claim is a divergence (exit 1) and names the
line; a record that is not well-formed is bad input (exit 2, one message
naming file and line, no traceback).
"""

from __future__ import annotations

import copy
import json
import os
from dataclasses import replace

import pytest

from faults import FAULTS
from topomark.reference.algorithms.registry import algorithm_spec, in_family
from topomark.reference.trace import reader as tracefile
from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.explorers.policies import Policies
from topomark.spec.invariants import check_lemma1
from topomark.spec.signature import Signature
from topomark.spec.world import Start
from topomark.spec.worldfile import dumps_world

WORLD = g.complete(5)  # iteration 6 has rejected (case 2), confirmed (case 3) and untested hypotheses
TRACE = explore(WORLD).trace
ENH4 = g.lattice(4, 4)
ENH4_TRACE = explore(ENH4, "enh4").trace


def run(tmp_path, capsys, world, text: str | bytes, *extra: str) -> tuple[int, str, str]:
    (tmp_path / "w.json").write_text(dumps_world(world))
    path = tmp_path / "t.jsonl"
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    code = main(["replay", str(tmp_path / "w.json"), str(path), *extra])
    out, err = capsys.readouterr()
    return code, out, err


def index(trace, pred) -> int:
    return next(k for k, rec in enumerate(trace) if pred(rec))


def mixed(trace) -> int:
    """The first iteration with a confirmed and a rejected hypothesis."""
    return index(trace, lambda r: r["event"] == "iteration" and {"case 3", "case 2"} <= {
        h["outcome"] for h in r["hypotheses"]})


def hyp(trace, k: int, outcome: str) -> dict:
    return next(h for h in trace[k]["hypotheses"] if h["outcome"] == outcome)


# -- false claims: exit 1, the line named ----------------------------------------------
def _claim_failure(t):
    t[-1].update(verified=False, violation={"check": "I-1", "where": "vertex 3", "expected": "x", "found": "y",
                                            "detail": "iteration 4"})
    return len(t) - 1


def _confirm_rejected(t):
    k = mixed(t)
    h = hyp(t, k, "case 2")
    h.update(outcome="case 3", perceived=h["expected"])
    return k


def _reject_confirmed(t):
    k = mixed(t)
    h = hyp(t, k, "case 3")
    h.update(outcome="case 2", perceived=h["expected"][:-1] + ["[9,A,A]"])
    return k


def _remove_rejected(t):
    k = mixed(t)
    t[k]["hypotheses"].remove(hyp(t, k, "case 2"))
    return k


def _duplicate(t):
    k = mixed(t)
    t[k]["hypotheses"].insert(0, copy.deepcopy(t[k]["hypotheses"][0]))
    return k


def _reorder(t):
    k = mixed(t)
    t[k]["hypotheses"].reverse()
    return k


def _wrong_expected(t):
    k = mixed(t)
    h = hyp(t, k, "case 2")
    h["expected"][0] = "[9,A,A]"
    return k


def _untested_without_confirmation(t):
    k = index(t, lambda r: r["event"] == "iteration" and r["augmentation"] == "non-loop" and r["hypotheses"])
    t[k]["hypotheses"][0].update(outcome="untested", perceived=[])
    return k


def _cost(t):
    t[-1]["cost"] += 1
    return len(t) - 1


def _new_as_travel(t):
    k = index(t, lambda r: r["event"] == "move" and r["purpose"] == "new" and r["step"] > 3)
    t[k]["purpose"] = "travel"
    return k + 1  # the next move tests hypotheses of an iteration that has no new edge yet


def _validation_as_new(t):
    k = index(t, lambda r: r["event"] == "move" and r["purpose"] == "validation")
    t[k]["purpose"] = "new"
    return k


def _by_marker(t):
    k = index(t, lambda r: r["event"] == "iteration" and r["by_marker"])
    t[k]["by_marker"] = False
    return k


@pytest.mark.parametrize("tamper", [_claim_failure, _confirm_rejected, _reject_confirmed, _remove_rejected,
                                    _duplicate, _reorder, _wrong_expected, _untested_without_confirmation, _cost,
                                    _new_as_travel, _validation_as_new, _by_marker], ids=lambda f: f.__name__[1:])
def test_a_false_claim_diverges_at_its_line(tmp_path, capsys, tamper):
    trace = copy.deepcopy(TRACE)
    k = tamper(trace)
    code, out, err = run(tmp_path, capsys, WORLD, dump_trace(trace))
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:"), (out, err)
    assert "Traceback" not in err


@pytest.mark.parametrize("field, delta", [("pruned", 1), ("expansion", 1), ("without_motion", 1)])
def test_enhancement_counters_are_checked(tmp_path, capsys, field, delta):
    trace = copy.deepcopy(ENH4_TRACE)
    k = index(trace, lambda r: r["event"] == "iteration" and r["enhancement"]["expansion"] > 0)
    trace[k]["enhancement"][field] += delta
    code, out, _ = run(tmp_path, capsys, ENH4, dump_trace(trace))
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:") and field in out


def test_an_enhancement_object_in_a_basic_trace_is_a_false_claim(tmp_path, capsys):
    trace = copy.deepcopy(TRACE)
    k = index(trace, lambda r: r["event"] == "iteration")
    trace[k]["enhancement"] = {"pruned": 0, "without_motion": 0, "expansion": 0, "known": 0}
    code, out, _ = run(tmp_path, capsys, WORLD, dump_trace(trace))
    assert code == 1 and "header's algorithm is basic" in out


def test_a_claimed_failure_that_replay_does_not_find_is_named(tmp_path, capsys):
    trace = copy.deepcopy(TRACE)
    _claim_failure(trace)
    code, out, _ = run(tmp_path, capsys, WORLD, dump_trace(trace), "--json")
    data = json.loads(out)
    assert code == 1 and data["divergence"]["check"] == "trace claim" and "I-1 violated" in data["message"]
    assert data["recorded_failure"] is False


def test_a_trace_that_records_its_own_failure_is_consistent_but_negative(tmp_path, capsys):
    out = explore(WORLD, replace(algorithm_spec("basic"), explorer=FAULTS["MisindexedLoopEdge"]))
    assert out.violation is not None and out.trace[-1]["verified"] is False
    code, text, _ = run(tmp_path, capsys, WORLD, dump_trace(out.trace), "--json")
    data = json.loads(text)
    assert code == 1 and data["recorded_failure"] is True
    assert "consistent: the trace records its own failure" in data["message"]


def test_an_unjudged_run_is_verified_by_replay(tmp_path, capsys):
    trace = explore(WORLD, check=False).trace
    assert trace[-1]["verified"] is False and trace[-1]["violation"] is None
    code, out, _ = run(tmp_path, capsys, WORLD, dump_trace(trace))
    assert code == 0 and out.startswith("VERIFIED") and "did not judge" in out


def test_lemma1_is_the_checkers_predicate():
    sig = Signature.parse("[2,A,A]")

    class H:
        def __init__(self, dart):
            self.dart, self.motions, self.expected = dart, (0, 1), (sig, sig)

    assert check_lemma1([H((1, 0))]) is None
    bad = check_lemma1([H((1, 0)), H((2, 1))])
    assert bad.check == "Lemma 1" and "(1, 0)" in bad.where and "(2, 1)" in bad.where


# -- bad input: exit 2, one message naming the file and line ------------------------------
def _lines(trace=TRACE) -> list[str]:
    return dump_trace(trace).splitlines()


def _set(k: int, **fields):
    def edit(lines):
        rec = json.loads(lines[k])
        rec.update(fields)
        return lines[:k] + [json.dumps(rec)] + lines[k + 1:]
    return edit


def _set_hyp(**fields):
    def edit(lines):
        k = mixed(TRACE)
        rec = json.loads(lines[k])
        rec["hypotheses"][0].update(fields)
        return lines[:k] + [json.dumps(rec)] + lines[k + 1:], k
    return edit


MOVE = index(TRACE, lambda r: r["event"] == "move" and r["step"] == 4)
MIXED = mixed(TRACE)


@pytest.mark.parametrize("edit, line, words", [
    (_set(0, algorithm="nope"), 1, "unknown algorithm 'nope'"),
    (_set(0, policies={"edge": "nearest", "hypothesis": "fifo", "path": "shortest", "speed": "x"}), 1,
     "unknown policy kind 'speed'"),
    (_set(0, policies={"edge": "warp", "hypothesis": "fifo", "path": "shortest"}), 1, "unknown edge policy 'warp'"),
    (_set(0, policies={"edge": "nearest", "hypothesis": "fifo"}), 1, "no path policy"),
    (_set(MOVE, purpose="teleport"), MOVE + 1, "move.purpose must be one of"),
    (_set(MOVE, perception="[²,A,A]"), MOVE + 1, "move.perception"),
    (_set(MOVE, speed=3), MOVE + 1, "unknown field 'speed' in a move event"),
    (_set(MIXED, augmentation="sideways"), MIXED + 1, "iteration.augmentation must be one of"),
    (lambda ls: _set_hyp(outcome="case 4")(ls)[0], MIXED + 1, "iteration.hypotheses[0].outcome"),
    (lambda ls: _set_hyp(colour="red")(ls)[0], MIXED + 1, "unknown field 'colour' in iteration.hypotheses[0]"),
    (lambda ls: _set_hyp(expected=["[2,A"])(ls)[0], MIXED + 1, "iteration.hypotheses[0].expected[0]"),
    (lambda ls: _set_hyp(rejected_by="luck")(ls)[0], MIXED + 1, "rejected_by must be one of"),
    (_set(-1, verified=True, violation={"check": "I-1", "where": "w", "expected": "e", "found": "f",
                                        "detail": ""}), len(TRACE), "verified: true and names a violation"),
    (_set(-1, verified=False, violation={"check": "I-1"}), len(TRACE), "end.violation without field 'where'"),
    (_set(-1, note="x"), len(TRACE), "unknown field 'note' in a end event"),
    (lambda ls: ls[:MOVE] + ["[" * 100 + "]" * 100] + ls[MOVE + 1:], MOVE + 1, "nested deeper than 64"),
    (lambda ls: ls[:MOVE] + [ls[MOVE].replace('"step":4', '"step":' + "4" * 5000)] + ls[MOVE + 1:], MOVE + 1,
     "(5000 digits) is out of range"),
    (lambda ls: ls[:MOVE] + [ls[MOVE].replace('"step":4', '"step":NaN')] + ls[MOVE + 1:], MOVE + 1,
     "NaN is not a JSON number"),
    # bad input outranks a divergence earlier in the trace
    (lambda ls: _set(-1, cost=0)(_set(MOVE, speed=3)(ls)), MOVE + 1, "unknown field 'speed'"),
], ids=["algorithm", "policy-kind", "policy-name", "policy-missing", "purpose", "signature-digits", "move-field",
        "augmentation", "outcome", "hypothesis-field", "hypothesis-signature", "rejected-by", "verified-and-violation",
        "violation-shape", "end-field", "deep", "huge-int", "nan", "after-divergence"])
def test_malformed_records_exit_2_naming_the_line(tmp_path, capsys, edit, line, words):
    code, out, err = run(tmp_path, capsys, WORLD, "\n".join(edit(_lines())) + "\n")
    assert code == 2 and f"t.jsonl line {line}:" in err and words in err, err
    assert err.count("\n") == 1 and "Traceback" not in err and not out


def test_a_non_utf8_line_is_named(tmp_path, capsys):
    lines = [x.encode() for x in _lines()]
    lines[MOVE] = lines[MOVE].replace(b'"move"', b'"mo\xffe"')
    code, _, err = run(tmp_path, capsys, WORLD, b"\n".join(lines) + b"\n")
    assert code == 2 and f"line {MOVE + 1}: not UTF-8" in err


def test_an_overlong_line_is_refused_without_reading_it_whole(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(tracefile, "MAX_LINE_BYTES", 200)
    code, _, err = run(tmp_path, capsys, WORLD, "\n".join(_lines()) + "\n")
    k = next(k for k, x in enumerate(_lines()) if len(x) >= 200)
    assert code == 2 and f"line {k + 1}: longer than 200 bytes" in err


@pytest.mark.parametrize("kind", ["fifo", "dev-zero", "directory"])
def test_a_trace_that_is_not_a_regular_file_is_refused(tmp_path, capsys, kind):
    (tmp_path / "w.json").write_text(dumps_world(WORLD))
    path = {"fifo": tmp_path / "t.fifo", "dev-zero": "/dev/zero", "directory": tmp_path}[kind]
    if kind == "fifo":
        os.mkfifo(path)
    assert main(["replay", str(tmp_path / "w.json"), str(path)]) == 2
    err = capsys.readouterr().err
    assert f"{path}: not a regular file" in err and err.count("\n") == 1


# -- every honest trace verifies ---------------------------------------------------------------
@pytest.mark.parametrize("algorithm", list(in_family("algorithm-3.1")))
def test_every_algorithm_replays_verified_through_the_cli(tmp_path, capsys, algorithm):
    for world, policies in ((g.random_graph(8, 0.5, seed=5), Policies()),
                            (g.lattice(3, 4).with_start(Start("1,1", "0,1")), Policies("lifo", "shortest", "dfs")),
                            (g.complete(5), Policies("fifo", "lifo", "shortest"))):
        out = explore(world, algorithm, policies)
        assert out.verified
        code, text, err = run(tmp_path, capsys, world, dump_trace(out.trace))
        assert code == 0 and text.startswith("VERIFIED"), (text, err)

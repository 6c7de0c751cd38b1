"""Tests of topomark.proofs.bench_enumerate: the timed enumeration and its two counts (§3.1.1, §3.1.3)."""

from __future__ import annotations

import json

from topomark.proofs import bench_enumerate
from topomark.proofs.bench_enumerate import main, measure


def test_counts_agree_with_burnside_and_exit_zero(capsys):
    assert main(["5", "3", "--min-vertices", "4"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert {n: row["worlds"] for n, row in out["sizes"].items()} == {"4": 9, "5": 22}
    assert out["agree"] and all(row["worlds"] == row["burnside"] for row in out["sizes"].values())
    sizes = measure(3, 2)["sizes"]
    assert {n: (row["graphs"], row["worlds"]) for n, row in sizes.items()} == {2: (1, 1), 3: (2, 2)}


def test_a_count_off_by_one_is_a_fault(monkeypatch, capsys):
    """Seeded fault: Burnside's side says one world more at n = 4; the bench exits 3 saying so."""
    real = bench_enumerate.count_by_size
    monkeypatch.setattr(bench_enumerate, "count_by_size",
                        lambda *a: {n: c + (n == 4) for n, c in real(*a).items()})
    assert main(["4", "3"]) == 3
    assert "fault in topomark itself" in capsys.readouterr().err


def test_bad_sizes_are_bad_input(capsys):
    for argv in (["11", "3"], ["5", "0"], ["5", "3", "--min-vertices", "6"]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.startswith("topomark: ") and "Traceback" not in err

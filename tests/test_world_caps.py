"""Size bounds of ``topomark world``: every generator parameter that sets a size is refused before anything is
built when the world would pass the world limit (topomark.spec.world.MAX_VERTICES / MAX_EDGES), and
``world --draw`` refuses a world above its own, much smaller, cap (proofs/drawing.py) with exit 2."""

from __future__ import annotations

import tracemalloc
import pytest

from topomark.proofs import drawing
from topomark.proofs.drawing import MAX_DRAW_VERTICES
from topomark.reference.cli.main import main
from topomark.reference.worlds.generators import generate
from topomark.spec.errors import InvalidInput
from topomark.spec.world import MAX_EDGES, MAX_VERTICES

OVER = MAX_VERTICES + 1
SIZES = [  # a generator and parameters one past the world limit (vertices, or edges for the dense ones)
    ("cycle", {"n": OVER}), ("chain", {"n": OVER}), ("lattice", {"rows": 501, "cols": 500}),
    ("lattice", {"rows": 1, "cols": OVER}), ("lattice-hole", {"rows": 501, "cols": 500}),
    ("lattice-hole", {"rows": OVER, "cols": 1}), ("complete", {"n": 1415}),  # 1415 * 1414 / 2 > MAX_EDGES
    ("complete-hole", {"n": 1415}), ("small-world", {"n": OVER}), ("small-world", {"n": 100_000, "k": 22}),
    ("random", {"n": OVER}), ("wheel-hub-last", {"n": OVER}),
]


@pytest.mark.parametrize("name, params", SIZES, ids=[f"{n}-{'-'.join(map(str, p.values()))}" for n, p in SIZES])
def test_a_size_past_the_world_limit_is_refused_before_building(name, params):
    assert 1415 * 1414 // 2 > MAX_EDGES
    tracemalloc.start()
    try:
        with pytest.raises(InvalidInput, match="at most|limit|too"):
            generate(name, **params)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 2_000_000, peak  # nothing of the size asked for was built


def test_draw_refuses_a_world_above_the_cap_with_exit_2(tmp_path, capsys):
    out = tmp_path / "big.svg"
    assert main(["world", "--draw", "lattice:rows=32,cols=32", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "1,024 vertices" in err and f"at most {MAX_DRAW_VERTICES:,}" in err and "Traceback" not in err
    assert not out.exists()
    assert main(["world", "--draw", "lattice:rows=4,cols=4", "-o", str(out)]) == 0 and out.exists()


def test_draw_states_its_cap_in_the_help(capsys):
    with pytest.raises(SystemExit):
        main(["world", "--help"])
    assert f"at most {MAX_DRAW_VERTICES:,} vertices" in " ".join(capsys.readouterr().out.split())


def test_a_layout_library_missing_is_bad_input_not_a_fault(tmp_path, capsys, monkeypatch):
    """networkx lays out a non-planar world of 500 vertices or more with scipy, an optional library."""
    def no_scipy(*args, **kwargs):
        raise ModuleNotFoundError("No module named 'scipy'", name="scipy")

    monkeypatch.setattr(drawing.nx, "spring_layout", no_scipy)
    assert main(["world", "--draw", "complete:n=6", "-o", str(tmp_path / "k6.svg")]) == 2
    assert "needs scipy" in capsys.readouterr().err

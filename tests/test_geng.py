"""Tests of topomark.proofs.geng: nauty's geng where installed, our generator otherwise, the same list (§3.1.1).

The cross-check against geng skips, saying why, only where geng is not
installed (CI installs Debian's ``nauty``); the fallback and every check on
geng's output are tested always, the checks with a fake geng.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import networkx as nx
import pytest

from topomark.proofs import geng
from topomark.proofs.enumerate import connected_graphs
from topomark.proofs.geng import from_geng, geng_program, graph6_lines, graph_classes, source
from topomark.proofs.graphs import canonical, classes
from topomark.spec.errors import InvalidInput, TopomarkFault

PROGRAM = geng_program()
# Off CI, a machine without geng skips the cross-check with this visible reason; CI (.ci/run sets CI=true and
# installs nauty) never skips it: without geng there the test runs and fails on its first assertion.
needs_geng = pytest.mark.skipif(PROGRAM is None and not os.environ.get("CI"), reason="nauty's geng is not installed (Debian: apt-get install "
                                                        "nauty); its cross-check with our generator cannot run")


def _certificates(gs: list[nx.Graph]) -> list[tuple[int, ...]]:
    return [canonical(tuple(sum(1 << w for w in g[v]) for v in sorted(g))).adjacency for g in gs]


@needs_geng
@pytest.mark.parametrize("max_degree", [1, 2, 3, 4])
def test_geng_lists_our_classes_in_our_order(max_degree):
    """Class by class (canonical certificate), order, labelling and automorphisms, n <= 8 (n = 8, D = 4: slow)."""
    assert PROGRAM is not None
    for n in range(1, 9 if max_degree < 4 else 8):
        assert from_geng(PROGRAM, n, max_degree) == classes(n, max_degree), (n, max_degree)


@needs_geng
@pytest.mark.slow
def test_geng_lists_our_classes_at_eight_vertices_degree_four():
    assert PROGRAM is not None
    theirs = from_geng(PROGRAM, 8, 4)
    assert len(theirs) == 1929 and theirs == classes(8, 4)


@needs_geng
def test_geng_gives_the_atlas_classes_below_eight_vertices():
    """n <= 7 keeps the atlas; geng finds exactly its classes (as a set of certificates: the order is the atlas's)."""
    assert PROGRAM is not None
    for n in range(2, 8):
        ours = _certificates(connected_graphs(n, 4))
        assert len(set(ours)) == len(ours)
        assert sorted(ours) == sorted(c.adjacency for c in from_geng(PROGRAM, n, 4)), n


@needs_geng
def test_geng_is_called_with_connected_and_the_degree_bound():
    assert PROGRAM is not None
    assert len(graph6_lines(PROGRAM, 6, 2)) == 2            # the path and the cycle
    assert graph6_lines(PROGRAM, 3, 1) == []                # no connected graph: geng is not asked
    assert source().startswith("geng")


def test_without_geng_our_generator_runs(monkeypatch):
    monkeypatch.setattr(geng.shutil, "which", lambda name: None)
    assert geng_program() is None and source() == "augmentation"
    graph_classes.cache_clear()
    try:
        assert graph_classes(6, 3) == classes(6, 3)
        assert [len(graph_classes(n, 3)) for n in range(1, 8)] == [1, 1, 2, 6, 10, 29, 64]
    finally:
        graph_classes.cache_clear()
    with pytest.raises(InvalidInput):
        graph_classes(0, 3)


# -- every check on geng's output, each with a fake geng that breaks only it --------------
def _fake(tmp_path: Path, body: str) -> str:
    """An executable that ignores its arguments and runs ``body`` (Python)."""
    path = tmp_path / "geng"
    path.write_text(f"#!{sys.executable}\nimport sys\n{body}\n")
    path.chmod(0o755)
    return str(path)


def test_a_fake_geng_giving_the_right_graphs_passes(tmp_path):
    lines = b"\n".join(nx.to_graph6_bytes(c.graph(), header=False).strip() for c in classes(5, 3))
    program = _fake(tmp_path, f"sys.stdout.buffer.write({lines!r} + b'\\n')")
    assert from_geng(program, 5, 3) == classes(5, 3)


@pytest.mark.parametrize("n,body,fault", [
    (3, "sys.stdout.write('Bw\\nBw\\n')", "twice"),                       # the triangle, twice
    (3, "sys.stdout.write('BO\\n')", "not a connected graph"),            # an edge and an isolated vertex
    (4, "sys.stdout.write('Cs\\n')", "not a connected graph"),            # the star K_{1,3}: degree 3 > 2
    (3, "sys.stdout.write('C~\\n')", "not a connected graph"),            # K4: 4 vertices where 3 were asked for
    (3, "sys.stdout.write('\\x01\\x02\\n')", "not graph6"),
    (3, "sys.stderr.write('broken'); sys.exit(1)", "exit code 1"),
])
def test_each_check_on_gengs_output_catches_its_fault(tmp_path, n, body, fault):
    program = _fake(tmp_path, body)
    with pytest.raises(TopomarkFault, match=fault):
        from_geng(program, n, 2)


def test_a_geng_that_cannot_run_is_a_fault(tmp_path):
    with pytest.raises(TopomarkFault, match="could not run"):
        graph6_lines(str(tmp_path / "missing-geng"), 5, 3)


def test_a_geng_that_drops_a_class_differs_from_ours(tmp_path):
    """The cross-check compares whole lists: a generator missing one class does not pass it."""
    lines = b"\n".join(nx.to_graph6_bytes(c.graph(), header=False).strip() for c in classes(5, 3)[1:])
    program = _fake(tmp_path, f"sys.stdout.buffer.write({lines!r} + b'\\n')")
    assert from_geng(program, 5, 3) != classes(5, 3)

"""Tests of topomark.proofs.burnside: embedded worlds per n counted by Burnside's lemma (§3.1.1, §3.1.3)."""

from __future__ import annotations

import itertools
import json
import math

import pytest

from topomark.proofs import burnside, enumerate as enum
from topomark.proofs.burnside import commuting_cyclic_orders, fixed_rotation_systems
from topomark.proofs.graphs import classes
from topomark.spec.errors import InvalidInput


def _cyclic_orders(points: list[int]):
    first, *rest = points
    for perm in itertools.permutations(rest):
        cycle = (first, *perm)
        yield {cycle[i]: cycle[(i + 1) % len(cycle)] for i in range(len(cycle))}


@pytest.mark.parametrize("d", [1, 2, 3, 4, 5, 6])
def test_commuting_cyclic_orders_against_every_cyclic_order(d):
    points = list(range(d))
    for image in itertools.permutations(points):
        tau = dict(zip(points, image))
        brute = sum(all(rho[tau[x]] == tau[rho[x]] for x in points) for rho in _cyclic_orders(points))
        assert commuting_cyclic_orders(tau) == brute, tau


def _cycle_type(sigma: tuple[int, ...]) -> tuple[int, ...]:
    seen, lengths = set(), []
    for v in range(len(sigma)):
        k, x = 0, v
        while x not in seen:
            seen.add(x)
            x = sigma[x]
            k += 1
        if k:
            lengths.append(k)
    return tuple(sorted(lengths))


def test_fixed_rotation_systems_against_every_rotation_system():
    """Fix(σ) by formula == by checking every rotation system; every graph with n ≤ 5 (D ≤ 4) and the
    symmetric ones with n = 6 (D ≤ 3); on large cases (K5, ...) one σ per cycle type."""
    symmetric = [c for n in (3, 4, 5) for c in classes(n, 4)] + [c for c in classes(6, 3) if len(c.automorphisms) > 2]
    for c in symmetric:
        rots = list(enum.rotation_systems(c.graph()))
        assert len(rots) == math.prod(math.factorial(c.degree(v) - 1) for v in range(c.n))
        sigmas = c.automorphisms
        if len(rots) * len(sigmas) > 20_000:
            sigmas = tuple({_cycle_type(s): s for s in sigmas}.values())
        for sigma in sigmas:
            mapping = dict(enumerate(sigma))
            brute = sum(enum._image(rot, mapping) == rot for rot in rots)
            assert fixed_rotation_systems(c, sigma) == brute, (c.adjacency, sigma)


def test_burnside_reproduces_the_issue_figures():
    assert burnside.count_by_size(7, 4) == {2: 1, 3: 2, 4: 9, 5: 275, 6: 7229, 7: 213986}


@pytest.mark.slow
@pytest.mark.parametrize("max_vertices,max_degree", [(6, 4), (8, 3), (6, 2)])
def test_burnside_equals_enumeration(max_vertices, max_degree):
    assert burnside.count_by_size(max_vertices, max_degree) == enum.count_by_size(max_vertices, max_degree)


@pytest.mark.parametrize("args", [(4, 0), (1, 3)])
def test_bad_input(args):
    with pytest.raises(InvalidInput):
        burnside.count_by_size(*args)


# -- topomark census-count -----------------------------------------------------------------
def test_cli_prints_both_counts(capsys):
    from topomark.reference.cli.main import main
    assert main(["census-count", "--max-vertices", "6", "--max-degree", "3", "--enumerate", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [(r["n"], r["graphs"], r["worlds"], r["enumerated"]) for r in data["rows"]] == \
        [(2, 1, 1, 1), (3, 2, 2, 2), (4, 6, 9, 9), (5, 10, 22, 22), (6, 29, 95, 95)]
    assert main(["census-count", "--max-vertices", "5", "--max-degree", "4", "--min-vertices", "5"]) == 0
    assert capsys.readouterr().out.splitlines()[-2].split() == ["5", "21", "275"]


@pytest.mark.parametrize("argv", [
    ["--max-vertices", "1", "--max-degree", "3"],
    ["--max-vertices", "13", "--max-degree", "3"],
    ["--max-vertices", "11", "--max-degree", "3", "--enumerate"],
    ["--max-vertices", "5", "--max-degree", "0"],
    ["--max-vertices", "5", "--max-degree", "3", "--min-vertices", "6"],
    ["--max-vertices", "five", "--max-degree", "3"],
    ["--max-degree", "3"],
])
def test_cli_rejects_bad_options(argv, capsys):
    from topomark.reference.cli.main import main
    assert main(["census-count", *argv]) == 2
    assert capsys.readouterr().err.startswith("topomark: error:")

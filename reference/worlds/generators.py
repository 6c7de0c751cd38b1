"""World generators: the graph classes of thesis §3.5.3 and the examples of §3.2.2 -- the registry.

Every generator returns a :class:`~topomark.spec.world.World` (a rotation
system, §3.1.1) with no markers and no start, except the Figure 3.4/3.6 wheel
pair, which carries the marker the thesis places on it, the Figure 6.10 and
6.15 worlds, which carry the start their figure needs, and the expensive
families, which carry the start that makes them expensive.  Generators are
deterministic: random choices come from ``random.Random(seed)`` only, never
from the global random state.  Impossible parameters raise
:class:`~topomark.spec.errors.InvalidInput` with a message naming the
parameter.

The generators live in one module per concept and are all importable from
here:

* :mod:`~topomark.reference.worlds.embedding` -- worlds from drawings and planar
  graphs (:func:`from_positions`, :func:`planar`, :func:`from_networkx`,
  :func:`circle_positions`, :func:`natural_key`), §3.1.1;
* :mod:`~topomark.reference.worlds.deterministic` -- :func:`cycle` (§3.2.1),
  :func:`chain`, :func:`lattice` and :func:`complete` (§3.5.3), and
  :func:`wheel_hub_last` (the wheel whose hub a closest-first robot finds last, §6.2.1);
* :mod:`~topomark.reference.worlds.holes` -- :func:`lattice_hole` and
  :func:`complete_hole` (§3.5.3);
* :mod:`~topomark.reference.worlds.random_worlds` -- :func:`small_world` and
  :func:`random_graph` (§3.5.3);
* :mod:`~topomark.proofs.wheels` -- the Figure 3.4/3.6 wheel pair (§3.2.2, §3.3);
* :mod:`~topomark.reference.worlds.figures` -- :func:`figure_6_10` and
  :func:`figure_6_15`, where §6.2's failing marker savings fail;
* :mod:`~topomark.reference.worlds.worst_cases` -- ``worst-case``: the worst
  worlds ``topomark worst-case`` found, with their starts (§7.2);
* :mod:`~topomark.reference.worlds.expensive` -- :func:`strip`, :func:`circulant`,
  :func:`k5e_chain` and :func:`cylinder`: families of maximum degree 4 that make
  Algorithm 3.1 expensive, with their starts (§3.5.2, §7.2);
* :mod:`~topomark.reference.worlds.rewired` -- :func:`rewired_strip`: the closed strip
  rewired as a search found at n = 100, moved to any even size (§7.2);
* :mod:`~topomark.reference.worlds.split_strip` -- :func:`split_strip`: the closed strip
  split so that §6.2.1's footprint searches walk far for every loop (§6.2.1, §7.2);
* :mod:`~topomark.reference.worlds.chorded_cycle` -- :func:`chorded_cycle`: a cycle walked
  first and a random second cycle of chords, expensive at small diameter (§7.2);
* :mod:`~topomark.reference.worlds.pendant` -- :func:`pendant_strip`: a closed strip hung at
  the end of a long stem, where the Chapter 4 enhancements cost m²n too (§4.1–4.3, §7.2).

This module holds the registry the CLI uses: :data:`GENERATORS`,
:data:`PARAMETERS`, :func:`generate` and :func:`DEFAULT_WORLD`.

Size: every generator computes n and m from its parameters and refuses, before
building anything, a world above :data:`~topomark.spec.world.MAX_VERTICES`
vertices or :data:`~topomark.spec.world.MAX_EDGES` edges (for ``lattice-hole``
and ``complete-hole`` the full graph they start from; for ``small-world`` the
most edges it can get), so ``lattice:rows=3000,cols=3000`` fails at once with
a message naming the limit instead of running into MemoryError.

Conventions
-----------
* Vertex names are strings: ``"0"``, ``"1"``, ... for numbered vertices and
  ``"r,c"`` for lattice cells (row ``r``, column ``c``).
* The rotation dict lists vertices in natural order (``"2" < "10"``,
  ``"1,2" < "1,10" < "2,0"``), see :func:`natural_key`.
* Geometric worlds are embedded by :func:`from_positions`: each vertex gets a
  point in the plane, and its neighbours are listed clockwise by the angle at
  which they are seen, starting from north.
* "round" below is Python's built-in :func:`round` (halves go to the even
  integer: ``round(2.5) == 2``).

Examples
--------
>>> lattice(3, 4).n, lattice(3, 4).m
(12, 17)
>>> lattice(2, 2).rotation["0,0"]
('0,1', '1,0')
>>> generate("complete", n=5).m
10
"""

from __future__ import annotations

import re
from numbers import Integral
from typing import Any, Callable

from topomark.spec.errors import InvalidInput, clip, unknown_name, did_you_mean
from topomark.spec.world import World

from topomark.reference.worlds.embedding import circle_positions, from_networkx, from_positions, natural_key, planar
from topomark.reference.worlds.deterministic import chain, complete, cycle, lattice, wheel_hub_last
from topomark.reference.worlds.figures import figure_6_10, figure_6_15
from topomark.reference.worlds.worst_cases import worst_case_world
from topomark.reference.worlds.expensive import circulant, cylinder, k5e_chain, strip
from topomark.reference.worlds.rewired import rewired_strip
from topomark.reference.worlds.split_strip import split_strip
from topomark.reference.worlds.chorded_cycle import chorded_cycle
from topomark.reference.worlds.pendant import pendant_strip
from topomark.reference.worlds.holes import complete_hole, lattice_hole
from topomark.reference.worlds.random_worlds import OtherPairs, random_graph, small_world  # noqa: F401 - OtherPairs: for tests
from topomark.proofs.wheels import (WHEEL_A_ROTATION, WHEEL_B_ROTATION, wheel_a, wheel_b, wheel_pair,
                     wheel_pair_directional)

__all__ = [
    "natural_key",
    "from_positions",
    "circle_positions",
    "cycle",
    "chain",
    "lattice",
    "wheel_hub_last",
    "figure_6_10",
    "figure_6_15",
    "lattice_hole",
    "complete",
    "complete_hole",
    "small_world",
    "random_graph",
    "wheel_pair",
    "wheel_pair_directional",
    "wheel_a",
    "wheel_b",
    "WHEEL_A_ROTATION",
    "WHEEL_B_ROTATION",
    "planar",
    "from_networkx",
    "strip",
    "circulant",
    "k5e_chain",
    "cylinder",
    "rewired_strip",
    "split_strip",
    "chorded_cycle",
    "pendant_strip",
    "GENERATORS",
    "PARAMETERS",
    "generate",
    "DEFAULT_WORLD",
]


# -- registry for the CLI ------------------------------------------------------
GENERATORS: dict[str, Callable[..., World]] = {
    "cycle": cycle,
    "chain": chain,
    "lattice": lattice,
    "lattice-hole": lattice_hole,
    "complete": complete,
    "complete-hole": complete_hole,
    "small-world": small_world,
    "random": random_graph,
    "wheel-a": wheel_a,
    "wheel-b": wheel_b,
    "wheel-hub-last": wheel_hub_last,
    "figure-6.10": figure_6_10,
    "figure-6.15": figure_6_15,
    "worst-case": worst_case_world,
    "strip": strip,
    "circulant": circulant,
    "k5e-chain": k5e_chain,
    "cylinder": cylinder,
    "rewired-strip": rewired_strip,
    "split-strip": split_strip,
    "chorded-cycle": chorded_cycle,
    "pendant-strip": pendant_strip,
}
"""CLI name -> generator function."""

PARAMETERS: dict[str, dict[str, Any]] = {
    "cycle": {"n": 8},
    "chain": {"n": 8},
    "lattice": {"rows": 5, "cols": 5},
    "lattice-hole": {"rows": 10, "cols": 10, "fraction": 0.1, "remove": "vertices", "seed": 0},
    "complete": {"n": 5},
    "complete-hole": {"n": 8, "fraction": 0.1, "seed": 0},
    "small-world": {"n": 20, "k": 4, "p": 0.1, "seed": 0},
    "random": {"n": 10, "fraction": 0.3, "seed": 0},
    # The wheels bare by default, as every command that takes a world accepts them (a lighthouse algorithm drops
    # its own marker); marker=undirected: Figure 3.4's centre marker; marker=directional: Figure 3.6.
    "wheel-a": {"marker": "none"},
    "wheel-b": {"marker": "none"},
    "wheel-hub-last": {"n": 9},
    # Figures 6.10 and 6.15: the worlds where the failing marker savings of §6.2 fail (worlds/figures.py).
    "figure-6.10": {},
    "figure-6.15": {},
    # The worst worlds topomark worst-case found, with their starts (worlds/worst_cases.py).
    "worst-case": {"case": "basic-n7-d4"},
    # Families of maximum degree 4 that make Algorithm 3.1 expensive, started at an end (worlds/expensive.py).
    "strip": {"n": 12, "cap": 0},
    "circulant": {"n": 12, "k": 2},
    "k5e-chain": {"gadgets": 3},
    "cylinder": {"rings": 4, "size": 4},
    # The closed strip rewired as the search found at n = 100, moved to n places (worlds/rewired.py).
    "rewired-strip": {"n": 100},
    # The closed strip split so that the footprint searches of §6.2.1 walk far (worlds/split_strip.py).
    "split-strip": {"n": 20},
    # A cycle walked first and a seeded random cycle of chords: small diameter (worlds/chorded_cycle.py).
    "chorded-cycle": {"n": 20, "seed": 0},
    # A closed strip hung at the end of a long stem: the enhancements' cost is cubic (worlds/pendant.py).
    "pendant-strip": {"n": 20},
}
"""CLI name -> {parameter name: default}.  The default's type is the parameter's type
(int, float or str); ``generate`` fills in missing parameters from here."""


_CLI_NUMBER = {int: re.compile(r"[+-]?[0-9]+"),
               float: re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")}
_CLI_DIGITS = 18  # as for JSON integers (topomark.spec.jsontext.MAX_INT_DIGITS)


def _shown(value: str, limit: int = 40) -> str:
    """``repr(value)`` cut to ``limit`` characters, for messages about hostile parameters."""
    return clip(value, limit, quote=True)


def _coerce(generator: str, param: str, value: Any, default: Any) -> Any:
    """A parameter value as the type of its default; a string (from the CLI) must be a plain ASCII
    number (no ``nan``, ``1_000`` or non-ASCII digits) of at most 18 digits before the point,
    so no conversion ever costs more than the text is long."""
    kind = type(default)
    if isinstance(value, str) and kind is not str:
        if not _CLI_NUMBER[kind].fullmatch(value):
            raise InvalidInput(f"{generator}: parameter {param} must be {kind.__name__}, got {_shown(value)}")
        mantissa = re.split(r"[.eE]", value.lstrip("+-"))[0]
        if len(mantissa) > _CLI_DIGITS:
            raise InvalidInput(f"{generator}: parameter {param} = {_shown(value)} is out of range "
                               f"(at most {_CLI_DIGITS} digits)")
        return kind(value)
    if kind is float and isinstance(value, Integral) and not isinstance(value, bool):
        return float(value)
    return value


def generate(name: str, **params: Any) -> World:
    """Build the world named ``name`` (a key of GENERATORS) with ``params``.

    Missing parameters take their PARAMETERS defaults; string values (as a CLI
    gives them) are converted to the parameter's type.  Raises InvalidInput
    naming an unknown generator or parameter.

    >>> generate("lattice", rows="3", cols=4).n
    12
    """
    if name not in GENERATORS:
        raise unknown_name("generator", name, GENERATORS)
    defaults = PARAMETERS[name]
    unknown = sorted(set(params) - set(defaults))
    if unknown:
        accepted = ", ".join(defaults) if defaults else "none"
        raise InvalidInput(
            f"generator {name!r} has no parameter {', '.join(map(repr, unknown))}{did_you_mean(unknown[0], defaults)} "
            f"(accepted: {accepted})"
        )
    args = {p: _coerce(name, p, params.get(p, d), d) for p, d in defaults.items()}
    return GENERATORS[name](**args)


def DEFAULT_WORLD() -> World:  # noqa: N802 - the name is part of the CLI contract
    """Quick-start world: a 5x5 lattice with round(0.1 * 25) = 2 cells removed (seed 1), 23 vertices."""
    return lattice_hole(5, 5, fraction=0.1, remove="vertices", seed=1)

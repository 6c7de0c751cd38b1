"""The algorithm registry: every explorer with its thesis reference, kit, bounds, options and checks.

Each :class:`AlgorithmSpec` records what the thesis says of one algorithm —
its section and listing, the marker kit it needs (:mod:`topomark.spec.kit`),
its cost bound and marker bound *as the thesis states them* (``None`` where
the thesis states none), whether it is deterministic, the options it takes,
the checks the checker applies to it — and a factory that builds its
explorer over the robot interface.  ``topomark algorithms [--json]`` lists
the registry.

Decision (the thesis is silent): Chapter 4 states no worst-case bound for
its enhancements (§4.1–4.3 report measured reductions only).  Enhancements
1–3 change only how hypotheses are validated and retraced, so the registry
gives them Algorithm 3.1's bound (3.1)+(3.2) as a stated *inheritance*, and
the checker measures it; Enhancements 4 and 5 add expansion traversals the
thesis does not bound, so their ``bound`` is ``None``.

Examples
--------
>>> spec = algorithm_spec("basic")
>>> spec.thesis
'§3.3, Algorithm 3.1'
>>> spec.bound_for(3, 3)  # a triangle: (3.1) + (3.2)
22
>>> algorithm_spec("nope")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: unknown algorithm 'nope' (choose from basic, enh1, enh2, enh3, enh4, enh5-d1, ...)
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import replace

from topomark.spec.errors import InvalidInput

from topomark.reference.algorithms import registrations
from topomark.reference.algorithms.algorithm_spec import CHECKS, AlgorithmSpec, Parameter
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.compositions import ENHANCEMENTS

__all__ = ["AlgorithmSpec", "Parameter", "REGISTRY", "algorithm_spec", "variant", "CHECKS", "parameters"]

_ALGORITHM_3_1_CHECKS = ("pose", "I-1", "I-2", "bound-function", "lemma-1", "marker", "iterations", "isomorphism")
_POLICY_OPTIONS = ("policy edge=nearest|fifo|lifo", "policy hypothesis=fifo|lifo|shortest", "policy path=shortest|dfs",
                   "lighthouse " + "|".join(LIGHTHOUSES),
                   *(f"lighthouse option {o.replace('_', '-')}=N (" + ", ".join(h.name for h in LIGHTHOUSES.values()
                                                                          if o in h.options) + ")"
                     for o in ("seed", "walk_limit", "neighbourhood", "threshold")))


_LIGHTHOUSE = LIGHTHOUSES["directional-vertex"].kit
_BOUND_3 = "(3.1)+(3.2) = O(m²n), §3.5.2"


def _enhancement(name: str) -> AlgorithmSpec:
    enh = ENHANCEMENTS[name]
    inherits = not (enh.prune or enh.expand_new or enh.expand_place)
    bound = f"{_BOUND_3}, inherited (§4.1 changes validation only)" if inherits else None
    return AlgorithmSpec(name, enh.section,
                         _LIGHTHOUSE, bound, "1", True, _POLICY_OPTIONS, _ALGORITHM_3_1_CHECKS,
                         upper_bound if inherits else None)


def _registered() -> dict[str, AlgorithmSpec]:
    """Every module of :mod:`topomark.reference.algorithms.registrations` (found by listing the folder, so a new algorithm
    family adds a module and edits nothing else) contributes its ``SPECS``, in module-name order."""
    found: dict[str, AlgorithmSpec] = {}
    for info in sorted(pkgutil.iter_modules(registrations.__path__), key=lambda i: i.name):
        module = importlib.import_module(f"{registrations.__name__}.{info.name}")
        for spec in getattr(module, "SPECS", ()):
            if spec.name in found:
                raise ValueError(f"algorithm {spec.name!r} is registered twice ({info.name})")
            found[spec.name] = spec
    return dict(sorted(found.items(), key=lambda item: _section(item[1].thesis)))


def _section(thesis: str) -> tuple[int, ...]:
    """``"§6.2.1 Case 3a, ..."`` ↦ (6, 2, 1): the listing follows the thesis (a stable sort keeps module order)."""
    head = thesis.lstrip("§").split()[0].rstrip(",")
    return tuple(int(part) for part in head.split(".") if part.isdigit())


REGISTRY: dict[str, AlgorithmSpec] = {
    "basic": AlgorithmSpec("basic", "§3.3, Algorithm 3.1", _LIGHTHOUSE, _BOUND_3, "1", True, _POLICY_OPTIONS,
                           _ALGORITHM_3_1_CHECKS, upper_bound),
    **{name: _enhancement(name) for name in ENHANCEMENTS},
}
for _name, _spec in _registered().items():
    if _name in REGISTRY:
        raise ValueError(f"algorithm {_name!r} is registered twice")
    REGISTRY[_name] = _spec


def parameters() -> dict[str, Parameter]:
    """Every option any registered algorithm takes, by name (the CLI offers each as ``--NAME``)."""
    out: dict[str, Parameter] = {}
    for spec in REGISTRY.values():
        for p in spec.parameters:
            out.setdefault(p.name, p)
    return out


def variant(name: str, explorer: type, like: str = "basic") -> AlgorithmSpec:
    """An explorer class of one's own, run and checked like the registered algorithm ``like``.

    For trying a modification of an algorithm under the full checker
    (``explore(world, variant("mine", MyExplorer))``) without registering it.
    """
    return replace(algorithm_spec(like), name=name, explorer=explorer, own=False)


def algorithm_spec(name: str) -> AlgorithmSpec:
    """The registered algorithm called ``name``; an unknown name is bad input listing the known ones."""
    if name not in REGISTRY:
        raise InvalidInput(f"unknown algorithm {name!r} (choose from {', '.join(REGISTRY)})")
    return REGISTRY[name]

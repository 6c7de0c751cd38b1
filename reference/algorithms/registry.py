"""The algorithm registry: every explorer with its thesis reference, kit, bounds, options and checks.

Each :class:`AlgorithmSpec` records what the thesis says of one algorithm —
its section and listing, the marker kit it needs (:mod:`topomark.spec.kit`),
its cost bound and marker bound *as the thesis states them* (``None`` where
the thesis states none), whether it is deterministic, the options it takes,
the checks the checker applies to it — and a factory that builds its
explorer over the robot interface.  ``topomark algorithms [--json]`` lists
the registry.

Every algorithm, Algorithm 3.1 (§3.3) and its Chapter 4 enhancements
included, is registered by a module of
:mod:`topomark.reference.algorithms.registrations` defining ``SPECS``; the
registry lists that folder, so a new algorithm adds a module there and edits
nothing here (``docs/adding-an-algorithm.md``).  :func:`register` adds a spec
from elsewhere — a program or a test that keeps its explorer outside the
package — and :func:`unregister` takes it out again.

A module may also define ``LISTED``: algorithms of the thesis that are not
implementable from it (:class:`~topomark.reference.algorithms.algorithm_spec.Listed`,
status "not implementable from the thesis", with the reason).  They are kept
in :data:`LISTED`, not :data:`REGISTRY` (nothing can run them), appear in
:func:`listing` and ``topomark algorithms``, and :func:`algorithm_spec`
refuses them as bad input giving the reason.

The listing's order: Algorithm 3.1's family first (``basic``, then Chapter 4),
then every other algorithm in thesis order (a stable sort on the section
number keeps registration order within a section).

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
topomark.spec.errors.InvalidInput: unknown algorithm 'nope' (choose from basic, enh1, enh2, enh3, enh3-listing, enh4, ...)
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import replace

from topomark.spec.errors import InvalidInput, unknown_name

from topomark.reference.algorithms import registrations
from topomark.reference.algorithms.algorithm_spec import CHECKS, STATUSES, AlgorithmSpec, Listed, Parameter

__all__ = ["AlgorithmSpec", "Listed", "Parameter", "REGISTRY", "LISTED", "STATUSES", "algorithm_spec", "variant",
           "CHECKS", "parameters", "register", "unregister", "in_family", "listing"]

REGISTRY: dict[str, AlgorithmSpec] = {}
"""Every registered algorithm by name, in listing order (module docstring)."""

LISTED: dict[str, Listed] = {}
"""Every algorithm of the thesis listed as not implementable from it, by name (module docstring)."""


def register(spec: AlgorithmSpec) -> AlgorithmSpec:
    """Add ``spec`` to :data:`REGISTRY`, in its place in the listing, and return it; a name already registered
    is refused.  ``topomark explore --algorithm NAME`` and :func:`~topomark.reference.run.explore.explore` then
    run it like any other (the CLI sees what was registered before its parser was built)."""
    if spec.name in REGISTRY:
        raise ValueError(f"algorithm {spec.name!r} is registered twice")
    if spec.name in LISTED:
        raise ValueError(f"algorithm {spec.name!r} is listed as not implementable from the thesis")
    REGISTRY[spec.name] = spec
    listed = sorted(REGISTRY.values(), key=_listing_key)
    REGISTRY.clear()
    REGISTRY.update((s.name, s) for s in listed)
    return spec


def unregister(name: str) -> AlgorithmSpec:
    """Take the algorithm ``name`` out of :data:`REGISTRY` (what :func:`register` added) and return its spec."""
    return REGISTRY.pop(algorithm_spec(name).name)


def listing() -> list[AlgorithmSpec | Listed]:
    """Every registered and every :data:`LISTED` algorithm, in listing order (``topomark algorithms``)."""
    return sorted([*REGISTRY.values(), *LISTED.values()], key=_listing_key)


def _listing_key(spec: AlgorithmSpec | Listed) -> tuple:
    """Algorithm 3.1's family first, then by section: ``"§6.2.1 Case 3a, ..."`` ↦ (True, (6, 2, 1))."""
    head = spec.thesis.lstrip("§").split()[0].rstrip(",")
    return spec.family != "algorithm-3.1", tuple(int(part) for part in head.split(".") if part.isdigit())


def _register_folder() -> None:
    """Every module of :mod:`topomark.reference.algorithms.registrations` (found by listing the folder, so an
    algorithm family adds a module and edits nothing else) registers its ``SPECS``, in module-name order."""
    for info in sorted(pkgutil.iter_modules(registrations.__path__), key=lambda i: i.name):
        module = importlib.import_module(f"{registrations.__name__}.{info.name}")
        for spec in getattr(module, "SPECS", ()):
            try:
                register(spec)
            except ValueError as exc:
                raise ValueError(f"{exc} ({info.name})") from None
        for entry in getattr(module, "LISTED", ()):
            if entry.name in LISTED:
                raise ValueError(f"algorithm {entry.name!r} is listed twice ({info.name})")
            LISTED[entry.name] = entry
    clash = sorted(set(LISTED) & set(REGISTRY))
    if clash:
        raise ValueError(f"algorithms {clash} are both registered and listed as not implementable")


_register_folder()


def in_family(family: str) -> dict[str, AlgorithmSpec]:
    """The registered algorithms whose traces are written in ``family`` (``"algorithm-3.1"``: ``basic`` and the
    Chapter 4 enhancements), by name, in listing order."""
    return {name: spec for name, spec in REGISTRY.items() if spec.family == family}


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
    """The registered algorithm called ``name``; an unknown name is bad input listing the known ones, and one
    listed as not implementable from the thesis is bad input giving the reason."""
    if name in LISTED:
        raise InvalidInput(LISTED[name].refusal())
    if name not in REGISTRY:
        raise unknown_name("algorithm", name, REGISTRY)
    return REGISTRY[name]

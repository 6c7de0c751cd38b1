"""topomark from Python: marker-based topological SLAM (*Exploring topological environments*, York University, 2014).

A world is an embedded graph (§3.1.1: each vertex's exits in clockwise order) with markers and a start; a robot
that senses only degree and markers explores it and must build a map extended-isomorphic to it (§3.1.3).  This
package is the face of topomark: the functions below wrap what the ``topomark`` command runs, so a program gets
the same checks, the same verdicts and the same errors (:class:`topomark.spec.errors.InvalidInput` for bad input,
:class:`topomark.spec.errors.CheckFailure` when topomark's own checks disagree).

=========================================  =====================================================================
:func:`load_world`, :func:`save_world`     read and write a world file (``spec/world.schema.json``)
:func:`generate`                           a named world family (``topomark world``): lattice, cycle, wheel-a...
:func:`explore`                            a checked exploration (``topomark explore``); ``.map``, ``.verified``
:func:`check_map`                          a map judged against a world (``topomark check-map``)
:func:`isomorphic`                         extended isomorphism (§3.1.3): the witness, or None
:func:`replay`                             a recorded trace re-checked against its world (``topomark replay``)
:func:`distinguish`                        the shortest motion sequence telling two worlds apart (§3.2), or None
:func:`search`, :func:`prove`              Z3: indistinguishable non-isomorphic pairs (``topomark search``)
:func:`census`                             every small world grouped by language (``topomark census``)
:func:`algorithms`                         the algorithm registry (``topomark algorithms``)
:func:`worst_case`                         the exact worst cost over every small world (``topomark worst-case``)
:func:`adversarial_search`                 bad worlds past those sizes, by search (``worst-case --search``)
:mod:`topomark.strategies`                 hypothesis strategies for random worlds and isomorphic copies
=========================================  =====================================================================

Everything is imported when first used (PEP 562), so ``import topomark`` stays fast.

Examples
--------
>>> import topomark
>>> world = topomark.generate("lattice", rows=3, cols=3)
>>> run = topomark.explore(world, algorithm="basic")
>>> assert run.verified and topomark.isomorphic(run.map, world, markers=False)
>>> pair = topomark.search("none", max_vertices=4, max_degree=3).worlds  # found by Z3, re-checked
>>> topomark.distinguish(*pair) is None  # no motion sequence tells them apart (Figure 3.4's point)
True
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # for type checkers only: at run time each name is imported when first used
    __version__: str
    from topomark import strategies
    from topomark.exploration import algorithms, check_map, explore, isomorphic, replay
    from topomark.indistinguishability import census, distinguish, prove, search
    from topomark.worlds import generate, load_world, save_world
    from topomark.worst import adversarial_search, worst_case

__all__ = ["__version__", "load_world", "save_world", "generate", "explore", "check_map", "isomorphic", "replay",
           "distinguish", "search", "prove", "census", "algorithms", "worst_case", "adversarial_search",
           "strategies"]

_LAZY = {
    "load_world": "topomark.worlds", "save_world": "topomark.worlds", "generate": "topomark.worlds",
    "explore": "topomark.exploration", "check_map": "topomark.exploration", "isomorphic": "topomark.exploration",
    "replay": "topomark.exploration", "algorithms": "topomark.exploration",
    "distinguish": "topomark.indistinguishability", "search": "topomark.indistinguishability",
    "prove": "topomark.indistinguishability", "census": "topomark.indistinguishability",
    "worst_case": "topomark.worst", "adversarial_search": "topomark.worst",
}


def __getattr__(name: str) -> Any:
    """The public names, imported on first use (PEP 562); ``strategies`` is the submodule itself."""
    if name == "strategies":
        return importlib.import_module("topomark.strategies")
    if name == "__version__":  # looked up when asked for: importlib.metadata alone costs as much as Python's start
        globals()[name] = _version()
        return globals()[name]
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value  # the next look-up is an ordinary attribute
        return value
    raise AttributeError(f"module 'topomark' has no attribute {name!r}")


def _version() -> str:
    """The installed package's version (its metadata)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("topomark")
    except PackageNotFoundError:  # pragma: no cover - a source tree nobody installed cannot import topomark at all
        return "0+unknown"


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))

"""topomark from Python: marker-based topological SLAM (*Exploring topological environments*, York University, 2014).

A world is an embedded graph (§3.1.1: each vertex's exits in clockwise order) with markers and a start; a robot
that senses only degree and markers explores it and must build a map extended-isomorphic to it (§3.1.3).  This
package is the face of topomark: the functions below wrap what the ``topomark`` command runs, so a program gets
the same checks, the same verdicts and the same errors (:class:`InvalidInput` for bad input, :class:`CheckFailure`
when topomark's own checks disagree).  When topomark itself fails during an exploration (:class:`TopomarkFault`, or
an unexpected exception), the exception carries the run in progress as ``exc.topomark_run``: its algorithm, its
world and its last trace records, as in the command's fault report (``docs/formats.md``).

=========================================  =====================================================================
:func:`load_world`, :func:`save_world`     read and write a world file (``spec/world.schema.json``)
:func:`generate`                           a world from a generator (``topomark world``), its text or a world file
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

The types a program annotates with are here too: :class:`World` and :data:`WorldLike` (what every function
takes as a world: a World, a world file, a generator text, a rotation or a networkx ``PlanarEmbedding``), the
results (:class:`Outcome`, :class:`MapVerdict`, :class:`Witness`, :class:`ReplayResult`, :class:`Distinction`,
:class:`SearchResult`, :class:`ProofReport`, :class:`CensusResult`, :class:`AdversarialResult`,
:class:`AlgorithmSpec`) and the errors.  Bad input raises :class:`InvalidInput`; a keyword a function does not
take raises :class:`InvalidKeyword`, which is both an InvalidInput and a ``TypeError`` (as Python raises for an
unexpected keyword), naming the closest keywords.  Each result's ``repr`` is one short line saying what it is;
its data are its attributes.

Everything is imported when first used (PEP 562), so ``import topomark`` stays fast; type checkers see every
name (a misspelt one is an error, as in any module).

Examples
--------
>>> import topomark
>>> world = topomark.generate("lattice", rows=3, cols=3)
>>> run = topomark.explore(world, algorithm="basic")
>>> assert run.verified and run.map is not None and topomark.isomorphic(run.map, world, markers=False)
>>> run  # doctest: +ELLIPSIS
Outcome(algorithm='basic', world n=9 m=12, cost=..., correct, verified, ... checks, ... trace records)
>>> pair = topomark.search("none", max_vertices=4, max_degree=3).worlds  # found by Z3, re-checked
>>> assert pair is not None
>>> topomark.distinguish(*pair) is None  # no motion sequence tells them apart (Figure 3.4's point)
True
"""

import importlib as _importlib
import typing as _typing

if _typing.TYPE_CHECKING:  # type checkers see every public name; at run time each is imported when first used
    __version__: str
    from topomark import strategies
    from topomark.exploration import (AlgorithmSpec, Listed, MapVerdict, Outcome, Policies, ReplayResult, Witness,
                                      algorithms, check_map, explore, isomorphic, replay)
    from topomark.indistinguishability import (CensusResult, Distinction, ProofReport, SearchResult, census,
                                               distinguish, prove, search)
    from topomark.spec.errors import (AlgorithmFailed, AlgorithmStopped, CheckFailure, ExplorerFault,
                                      InvalidInput, InvalidKeyword, InvalidWorld, LimitReached, OutOfMarkers,
                                      TopomarkError, TopomarkFault, Violation)
    from topomark.spec.world import Start
    from topomark.worlds import World, WorldLike, generate, load_world, save_world
    from topomark.worst import AdversarialResult, adversarial_search, worst_case

_LAZY = {
    "topomark.worlds": ("load_world", "save_world", "generate", "World", "WorldLike"),
    "topomark.spec.world": ("Start",),
    "topomark.exploration": ("explore", "check_map", "isomorphic", "replay", "algorithms", "Outcome", "MapVerdict",
                             "Witness", "ReplayResult", "AlgorithmSpec", "Listed", "Policies"),
    "topomark.indistinguishability": ("distinguish", "search", "prove", "census", "Distinction", "SearchResult",
                                      "ProofReport", "CensusResult"),
    "topomark.worst": ("worst_case", "adversarial_search", "AdversarialResult"),
    "topomark.spec.errors": ("TopomarkError", "InvalidInput", "InvalidKeyword", "InvalidWorld", "CheckFailure",
                             "Violation", "TopomarkFault", "ExplorerFault", "AlgorithmStopped", "AlgorithmFailed",
                             "LimitReached", "OutOfMarkers"),
}
_HOME = {name: module for module, names in _LAZY.items() for name in names}

__all__ = ["__version__", "load_world", "save_world", "generate", "explore", "check_map", "isomorphic", "replay",
           "distinguish", "search", "prove", "census", "algorithms", "worst_case", "adversarial_search",
           "strategies",
           "World", "WorldLike", "Start", "Policies", "Outcome", "MapVerdict", "Witness", "ReplayResult",
           "Distinction", "SearchResult", "ProofReport", "CensusResult", "AdversarialResult", "AlgorithmSpec",
           "Listed",
           "TopomarkError", "InvalidInput", "InvalidKeyword", "InvalidWorld", "CheckFailure", "Violation",
           "TopomarkFault", "ExplorerFault", "AlgorithmStopped", "AlgorithmFailed", "LimitReached", "OutOfMarkers"]

if not _typing.TYPE_CHECKING:  # hidden from type checkers, so that a misspelt name is an error there
    def __getattr__(name: str) -> object:
        """The public names, imported on first use (PEP 562); ``strategies`` is the submodule itself."""
        if name == "strategies":
            return _importlib.import_module("topomark.strategies")
        if name == "__version__":  # looked up when asked for: importlib.metadata costs as much as Python's start
            globals()[name] = _version()
            return globals()[name]
        if name in _HOME:
            value = getattr(_importlib.import_module(_HOME[name]), name)
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
    """The public names (``__all__``) and the module's own dunder attributes; nothing the module uses inside."""
    return sorted(set(__all__) | {name for name in globals() if name.startswith("__") and name.endswith("__")})

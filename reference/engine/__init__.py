"""The engine: compiled unchecked runs of Algorithm 3.1, agreeing exactly with the reference (thesis §3.3, §7.2).

The exhaustive worst case (§7.2, ``topomark worst-case``) runs Algorithm 3.1
unchecked from every start of every small world; the reference explorer is
written for checking, not speed.  The engine runs the same algorithm compiled
by numba — the robot (:mod:`.robot`: the world's arrays, the only engine code
that reads them), the explorer's map (:mod:`.mapstate`) and the loop
(:mod:`.algorithm31`), driven per world by :mod:`.runs` — and must agree with
the reference exactly: same claim, cost, split by purpose, marker operations,
counts and trace digest (:mod:`.digest`), which :mod:`.compare` establishes by
running both (the command: :mod:`.equality`).  It is not a second definition: where they differ, the
reference is right.

What it runs (:func:`supports`): ``basic`` and Chapter 4's algorithms —
Enhancements 1–3 (``enh1``, ``enh2``, ``enh3``, :mod:`.enhanced`), 4 and 5
(``enh4``, ``enh5-d1``, ``enh5-d2``, :mod:`.expansion`) and the combinations
of §4.3 (``enh3+4``, ``enh3+5``) — with the built-in policies and any deterministic lighthouse
recognised without probing (:mod:`.lighthouses`: ``directional-vertex``,
``directional-edge``, ``vertex-and-edge``, ``three-undirected-edge``,
``thread``); the footprint searches of §6.2.1 (:data:`FOOTPRINT_CASES`: Cases
1a, 1b, 2 and the two of Case 4, one compiled search with the case as a
parameter, :mod:`.footprints`) with the kits their registrations give and the
built-in edge policies.  :func:`available` says whether numba
imports; without it every run goes through the reference, with identical
results, and :func:`notice` is the one line said on stderr.

Examples
--------
>>> supports("basic", "thread", ("nearest", "fifo", "shortest")), supports("basic", "undirected-vertex", ("nearest", "fifo", "shortest"))
(True, False)
>>> supports("enh3+5", "thread", ("lifo", "shortest", "dfs")), supports("enh5-d2-listing", None, ("nearest", "fifo", "shortest"))
(True, False)
>>> supports("case-2", None, ("lifo", "fifo", "shortest")), supports("case-2-edgeinfo", None, ("nearest", "fifo", "shortest"))
(True, False)
"""

from __future__ import annotations

import importlib

from topomark.spec.errors import InvalidInput

from topomark.reference.explorers.policies import EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES

__all__ = ["available", "supports", "notice", "choose", "ENGINES", "ENGINE_ALGORITHMS", "ENGINE_LIGHTHOUSES",
           "FOOTPRINT_CASES"]

ENGINE_ALGORITHMS = ("basic", "enh1", "enh2", "enh3", "enh4", "enh5-d1", "enh5-d2", "enh3+4", "enh3+5")
"""The lighthouse algorithms the engine runs (their registered names)."""
ENGINE_LIGHTHOUSES = ("directional-vertex", "directional-edge", "vertex-and-edge", "three-undirected-edge", "thread")
"""The lighthouses the engine runs: the deterministic ones whose v0 is recognised without probing
(:mod:`.lighthouses`)."""

ENGINES = ("reference", "compiled", "auto")
"""The values of ``--engine``: the reference always; the compiled engine (numba); ``auto``, the compiled one when
it is available and runs the algorithm, else the reference."""


FOOTPRINT_CASES = ("case-1a", "case-1b", "case-2", "case-4", "case-4-mn")
"""The footprint searches of §6.2.1 the engine runs (:mod:`.footprints`), each with the kit its registration
gives (``worst-case`` takes no ``--markers``); §6.2.2's edgeINFO variants and the listings are not compiled."""


def available() -> bool:
    """Whether numba imports, so the engine's kernels are compiled (asked afresh each time)."""
    try:
        importlib.import_module("numba")
    except Exception:  # ImportError, or a numba that fails on import
        return False
    return True


def supports(algorithm: str, lighthouse: str | None, policies: tuple[str, str, str]) -> bool:
    """Whether the engine runs ``algorithm`` with ``lighthouse`` (None: its default) and ``policies``."""
    edge, hypothesis, path = policies
    if algorithm in FOOTPRINT_CASES:  # kit algorithms: no lighthouse; only the edge policy applies
        return lighthouse is None and edge in EDGE_POLICIES
    return (algorithm in ENGINE_ALGORITHMS and (lighthouse is None or lighthouse in ENGINE_LIGHTHOUSES)
            and edge in EDGE_POLICIES and hypothesis in HYPOTHESIS_POLICIES and path in PATH_POLICIES)


def notice(uncompiled: bool = False) -> str:
    """The one line said when numba is missing: the runs go through the reference (or, for the cross-check,
    through the uncompiled kernels)."""
    if uncompiled:
        return "topomark: numba is not installed; the engine's kernels run uncompiled (slower)"
    return "topomark: numba is not installed; the engine runs through the reference (slower)"


def choose(engine: str, algorithm: str, lighthouse: str | None, policies: tuple[str, str, str]) -> tuple[str, str | None]:
    """The engine a run of ``--engine engine`` uses, ``compiled`` or ``reference``, and the notice to say (or None).

    ``auto``: the compiled engine when it runs the algorithm (:func:`supports`) and numba imports; else the
    reference — with the notice when only numba is missing.  ``compiled`` for what the engine does not run is bad
    input; without numba it too falls back to the reference, with the notice."""
    if engine not in ENGINES:
        raise InvalidInput(f"--engine must be one of {', '.join(ENGINES)}, not {engine!r}")
    if engine == "reference":
        return "reference", None
    if not supports(algorithm, lighthouse, policies):
        if engine == "compiled":
            raise InvalidInput(f"--engine compiled runs {', '.join(ENGINE_ALGORITHMS)} with the "
                               f"{', '.join(ENGINE_LIGHTHOUSES)} lighthouses and the built-in policies, and "
                               f"{', '.join(FOOTPRINT_CASES)} with their edge policies, only, not {algorithm} with "
                               f"{lighthouse or 'its default lighthouse'} and policies {'/'.join(policies)}; "
                               "use --engine reference or auto")
        return "reference", None
    if not available():
        return "reference", notice()
    return "compiled", None

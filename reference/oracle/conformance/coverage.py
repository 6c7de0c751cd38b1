"""Which ways an algorithm's conformance cases go, and whether they cover every way its registration declares.

Each case of an algorithm's suite (:func:`~topomark.reference.oracle.conformance.cases.algorithm_cases`) is run
by topomark's own checked explorer (:func:`reference_runs`) and classified into the ways it went
(:func:`~topomark.reference.algorithms.ways.ways_of`: phases passed through, the outcome it ended with).  A case
with a smallest kit (``--markers``, ``--thread-length``) is kept only where its run goes a way no case with the
registered kit goes — out of markers (§6.2.1), out of thread (§6.3.2), Case 5's phase II (§6.2.1 Case 5) — so a
client is held to it for a reason.  :func:`uncovered` names every declared way no case reaches, except the ways
no client can be held to (``in_suite`` False: a wrong map, a cap).
"""

from __future__ import annotations

from typing import Any, Iterable, cast

from topomark.spec.errors import CheckFailure
from topomark.spec.world import World

from topomark.reference.algorithms.algorithm_spec import EXPECTED_TO_FAIL
from topomark.reference.algorithms.registry import AlgorithmSpec
from topomark.reference.algorithms.ways import WAYS, ways_of
from topomark.reference.oracle.conformance.cases import accepts, algorithm_cases, default_cases
from topomark.reference.run.explore import explore
from topomark.reference.run.outcome import Outcome

__all__ = ["Case", "reference_runs", "uncovered", "declared_json"]

Case = tuple[str, str, str, World, dict[str, Any]]  # (name, world name, description, world, options)


def reference_runs(spec: AlgorithmSpec, cases: Iterable[Case] | None = None) -> list[tuple[Case, Outcome, list[str]]]:
    """(case, topomark's checked run of it, the ways it went) for each case of ``spec``'s suite that is kept.

    Every run must end ``correct`` or ``failed``: a violation, or any other end, is topomark's own failure
    (:class:`CheckFailure`) — except a smallest-kit case of an entry expected to fail (a listing the thesis's own
    lines make fail), which is passed over where its run ends with a wrong map: no client is held to one."""
    runs = [run for case in (algorithm_cases(spec) if cases is None else cases)
            if (run := _run(spec, case, wrong_map_passed=bool(case[4]) and spec.status == EXPECTED_TO_FAIL))]
    registered = {way for case, _, ways in runs if not case[4] for way in ways}
    runs = [run for run in runs if not run[0][4] or set(run[2]) - registered]
    return runs + _filling(spec, runs)


def _run(spec: AlgorithmSpec, case: Case, strict: bool = True,
         wrong_map_passed: bool = False) -> tuple[Case, Outcome, list[str]] | None:
    """The case, topomark's checked run of it and the ways it went; a run that ends neither correct nor failed is
    topomark's own failure (``strict``) or, for a world only tried (:func:`_filling`), None — and None for a run
    ending with a wrong map where ``wrong_map_passed``."""
    name, _, _, world, options = case
    out = explore(world, spec, options=options, check_mode="incremental")
    if out.violation is not None or out.outcome not in ("correct", "failed"):
        if not strict or (wrong_map_passed and out.outcome == "wrong-map"):
            return None
        raise CheckFailure(f"the reference run of {spec.name} on {name} ended {out.outcome}: "
                           f"{out.violation or out.reason}")
    return case, out, ways_of(out, spec.ways)


def _filling(spec: AlgorithmSpec, runs: list[tuple[Case, Outcome, list[str]]]) -> list[tuple[Case, Outcome, list[str]]]:
    """Where ``runs`` leave a declared way uncovered, the first of Algorithm 3.1's worlds (in
    :func:`~.cases.default_cases`' order, with the registered kit; none that carries a marker already) whose run goes it, until none is left or the
    worlds are used up (Enhancement 5's sensing rejects no hypothesis on the small shared worlds, §4.3).  A world
    whose run ends with a wrong map is passed over: no client is held to one."""
    missing = set(uncovered(spec, [ways for _, _, ways in runs]))
    have = {case[0] for case, _, _ in runs}
    added: list[tuple[Case, Outcome, list[str]]] = []
    for name, text, world in default_cases() if missing else ():
        if name in have or world.markers or not accepts(spec, world):  # a kit algorithm drops its own markers
            continue
        run = _run(spec, (name, name, f"{text}, with the kit {spec.name} is given on it: the first world where its "
                                      "run goes a way the shared worlds do not", world, {}), strict=False)
        if run is not None and missing & set(run[2]):
            added.append(run)
            missing -= set(run[2])
        if not missing:
            break
    return added


def uncovered(spec: AlgorithmSpec, went: Iterable[Iterable[str]]) -> list[str]:
    """The ways ``spec`` declares that a suite can hold and none of ``went`` (each case's ways) reaches."""
    reached = {way for ways in went for way in ways}
    return [way for way in spec.ways if WAYS[way].in_suite and way not in reached]


def declared_json(spec: AlgorithmSpec) -> dict[str, Any]:
    """A suite's ``ways``: each way ``spec`` declares, what it is, its thesis section, whether a suite holds it."""
    return {way: {**WAYS[way].to_json(), "in_suite": WAYS[way].in_suite} for way in spec.ways}

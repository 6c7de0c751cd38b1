"""What ``worst-case --summarise`` trusts of a run directory: nothing it has not checked or recomputed (§7.2).

A directory given to ``--summarise`` is input, and may have been edited.  The rules:

* it must hold ``worst-case.json`` (an exhaustive run) or ``worst-case-search.json`` (a ``--search`` run), or
  both; a directory with neither is bad input;
* each file is read back as a regular file of bounded size and strict JSON
  (:func:`~topomark.reference.worstcase.readback.read_json`), then checked against the schema of what its
  writer writes (:data:`EXHAUSTIVE`: :func:`topomark.reference.worstcase.result.write_outputs`;
  :data:`SEARCH`: ``topomark worst-case --search``), every field by type and range; the algorithm must be a
  registered one, and its name so can never make a path;
* what can be recomputed is recomputed and must agree: each exhaustive row's argmax world is the enumeration's
  world at its witness, and re-running the witnesses of the largest cost, cost/m and cost / bound gives the
  stored cost, ``(cost, m)`` and ``(counted cost, bound)``; the rounded values are those fractions rounded; a
  search's best worlds are re-run and must give their stored cost, m, n, diameter, degree and ratio.

Every disagreement is bad input (exit 2) naming the file and the field.  So a ratio above 1 in the report comes
from a re-run, not from the file: the summary then says the bound does not hold and ``--summarise`` exits 1
(a negative verdict), as ``worst-case`` itself does for a run that does not map its world.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import networkx as nx
from jsonschema import Draft202012Validator

from topomark.proofs.census_map import _graphs, rotation_count, world_at
from topomark.spec.errors import InvalidInput
from topomark.spec.world import MAX_DEGREE, World
from topomark.spec.worldfile import world_from_json, world_to_json

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import explore
from topomark.reference.worstcase.exhaustive import Setup, run_start
from topomark.reference.worstcase.limits import MAX_EXHAUSTIVE, MAX_SEARCH_VERTICES, exhaustive_refusal
from topomark.reference.worstcase.readback import read_json
from topomark.reference.worstcase.structural import RESTART_FAMILIES

__all__ = ["EXHAUSTIVE", "SEARCH", "load_runs"]

_NAME = {"type": "string", "pattern": "^[a-z0-9][a-z0-9_-]{0,63}$"}
_COUNT = {"type": "integer", "minimum": 0, "maximum": 2**62}
_FRACTION = {"oneOf": [{"type": "null"}, {"type": "array", "prefixItems": [_COUNT, {**_COUNT, "minimum": 1}],
                                          "minItems": 2, "maxItems": 2}]}
_WHERE = {"oneOf": [{"type": "null"}, {"type": "object", "required": ["graph", "rotation", "start", "exit"],
                                       "properties": {"graph": _COUNT, "rotation": _COUNT, "exit": _COUNT,
                                                      "start": {"type": "string", "pattern": "^v[0-9]{1,2}$"}}}]}
_NUMBER = {"type": "number", "minimum": 0, "maximum": 1e12}
_SETUP = {"type": "object", "required": ["algorithm", "lighthouse", "policies", "sample", "seed"],
          "properties": {"algorithm": _NAME, "lighthouse": {"oneOf": [{"type": "null"}, _NAME]},
                         "policies": {"type": "array", "items": _NAME, "minItems": 3, "maxItems": 3},
                         "sample": {"type": "number", "minimum": 0, "maximum": 1}, "seed": _COUNT}}
_ROW = {"type": "object",
        "required": ["n", "worlds", "runs", "outcomes", "max_cost", "max_cost_per_m", "max_ratio_to_bound",
                     "cost_per_m_exact", "ratio_exact", "argmax", "argmax_at", "argmax_cost_per_m_at",
                     "argmax_ratio_at"],
        "properties": {"n": {"type": "integer", "minimum": 2, "maximum": MAX_EXHAUSTIVE}, "worlds": _COUNT,
                       "runs": _COUNT, "outcomes": {"type": "object", "additionalProperties": _COUNT,
                                                    "propertyNames": _NAME, "maxProperties": 16},
                       "max_cost": {"oneOf": [{"type": "null"}, _COUNT]},
                       "max_cost_per_m": {"oneOf": [{"type": "null"}, _NUMBER]},
                       "max_ratio_to_bound": {"oneOf": [{"type": "null"}, _NUMBER]},
                       "cost_per_m_exact": _FRACTION, "ratio_exact": _FRACTION,
                       "argmax": {"oneOf": [{"type": "null"}, {"type": "object"}]},
                       "argmax_at": _WHERE, "argmax_cost_per_m_at": _WHERE, "argmax_ratio_at": _WHERE,
                       "bound_at_argmax": {"oneOf": [{"type": "null"}, _COUNT]}}}
EXHAUSTIVE = {"type": "object", "required": ["algorithm", "setup", "max_vertices", "max_degree", "per_n"],
              "properties": {"algorithm": _NAME, "setup": _SETUP,
                             "max_vertices": {"type": "integer", "minimum": 2, "maximum": MAX_EXHAUSTIVE},
                             "max_degree": {"type": "integer", "minimum": 1, "maximum": MAX_DEGREE},
                             "per_n": {"type": "array", "items": _ROW, "maxItems": MAX_EXHAUSTIVE}}}
"""The schema of ``worst-case.json`` as :func:`~topomark.reference.worstcase.result.write_outputs` writes it."""

_BEST = {"oneOf": [{"type": "null"}, {
    "type": "object", "required": ["cost", "m", "n", "diameter", "max_degree", "cost_per_m", "ratio_to_bound", "world"],
    "properties": {"cost": _COUNT, "m": _COUNT, "n": _COUNT, "diameter": _COUNT, "max_degree": _COUNT,
                   "cost_per_m": _NUMBER, "ratio_to_bound": {"oneOf": [{"type": "null"}, _NUMBER]},
                   "world": {"type": "object"}, "holes": {"type": "array", "items": {"type": "string",
                                                                                      "maxLength": 64}}}}]}
SEARCH = {"type": "object", "required": ["algorithm", "setup", "max_degree", "objective", "evaluations", "per_n"],
          "properties": {"algorithm": _NAME, "setup": _SETUP, "objective": _NAME,
                         "family": {"oneOf": [{"type": "null"}, {"enum": ["lattice-hole"]}]},
                         "restart": {"oneOf": [{"type": "null"}, {"enum": list(RESTART_FAMILIES)},  # or one world's text
                                                {"type": "string", "minLength": 1, "maxLength": 300,
                                                 "not": {"enum": list(RESTART_FAMILIES)}}]},
                         "max_degree": {"type": "integer", "minimum": 2, "maximum": MAX_DEGREE},
                         "evaluations": {"type": "integer", "minimum": 1, "maximum": 2**62},
                         "per_n": {"type": "array", "maxItems": 64, "items": {
                             "type": "object", "required": ["n", "search", "random"],
                             "properties": {"n": {"type": "integer", "minimum": 3, "maximum": MAX_SEARCH_VERTICES},
                                            "search": {"type": "object", "required": ["best"],
                                                       "properties": {"best": _BEST}},
                                            "random": {"type": "object", "required": ["best"],
                                                       "properties": {"best": _BEST}}}}}}}
"""The schema of ``worst-case-search.json`` as ``topomark worst-case --search -o DIR`` writes it."""


def _field(path) -> str:
    return "/".join(str(p) for p in path) or "(the whole file)"


def _checked(path: Path, schema: dict[str, Any]) -> dict[str, Any]:
    data = read_json(path, "--summarise")
    error = next(iter(sorted(Draft202012Validator(schema).iter_errors(data), key=lambda e: list(e.absolute_path))),
                 None)
    if error is not None:
        raise InvalidInput(f"--summarise {path}: field {_field(error.absolute_path)}: {str(error.message)[:160]}")
    return data


def _setup(path: Path, data: dict[str, Any]) -> Setup:
    """The run's setup, every name checked against the registries."""
    s = data["setup"]
    if s["algorithm"] != data["algorithm"]:
        raise InvalidInput(f"--summarise {path}: field setup/algorithm: {s['algorithm']!r} is not the run's "
                           f"algorithm {data['algorithm']!r}")
    try:
        spec = algorithm_spec(data["algorithm"])
        spec.lighthouse_for(s["lighthouse"])
        Policies(*s["policies"])
    except InvalidInput as e:
        raise InvalidInput(f"--summarise {path}: field setup: {e}") from None
    return Setup(data["algorithm"], s["lighthouse"], tuple(s["policies"]), s["sample"], s["seed"])


def _bad(path: Path, field: str, why: str) -> InvalidInput:
    return InvalidInput(f"--summarise {path}: field {field}: {why}")


def _witness_world(path: Path, field: str, n: int, degree: int, at: dict[str, Any]) -> tuple[World, tuple[str, int]]:
    """The enumeration's world and start dart at witness ``at`` (every index checked against the enumeration)."""
    gi, rank, v, i = at["graph"], at["rotation"], at["start"], at["exit"]
    if gi >= len(_graphs(n, degree)) or rank >= rotation_count(n, degree, gi):
        raise _bad(path, field, f"graph {gi}, rotation {rank} is no world with {n} vertices and degrees <= {degree}")
    world = world_at(n, degree, gi, rank)
    if v not in world.rotation or i >= world.degree(v):
        raise _bad(path, field, f"start {v} exit {i} is no dart of that world")
    return world, (v, i)


def _rerun(path: Path, field: str, setup: Setup, world: World, dart: tuple[str, int]) -> tuple[int, int]:
    """(cost, counted cost) of the run from ``dart``; a run that does not map its world cannot be a maximum."""
    try:
        out = run_start(setup, world, dart)
    except InvalidInput as e:
        raise _bad(path, field, f"its run is refused: {e}") from None
    if out.claimed != "correct":
        raise _bad(path, field, f"its run ends {out.claimed}, so it is no maximum")
    return out.cost, setup.spec.counted_cost(out.cost, out.by_purpose)


def _check_row(path: Path, data: dict[str, Any], setup: Setup, j: int) -> None:
    """Row ``j`` of an exhaustive run, recomputed from its witnesses (see the module docstring)."""
    r, at = data["per_n"][j], f"per_n/{j}"
    n, degree, spec = r["n"], min(data["max_degree"], data["max_vertices"] - 1), setup.spec
    if n > data["max_vertices"]:
        raise _bad(path, f"{at}/n", f"{n} is more than max_vertices {data['max_vertices']}")
    if sum(r["outcomes"].values()) != r["runs"]:
        raise _bad(path, f"{at}/outcomes", f"they add up to {sum(r['outcomes'].values())}, not runs {r['runs']}")
    for key, exact, digits in (("max_cost_per_m", "cost_per_m_exact", 3), ("max_ratio_to_bound", "ratio_exact", 4)):
        want = None if r[exact] is None else round(r[exact][0] / r[exact][1], digits)
        if r[key] != want:
            raise _bad(path, f"{at}/{key}", f"{r[key]} is not {exact} {r[exact]} rounded ({want})")
    witnesses = (("argmax_at", "max_cost"), ("argmax_cost_per_m_at", "cost_per_m_exact"),
                 ("argmax_ratio_at", "ratio_exact"))
    for where, value in witnesses:
        if (r[where] is None) != (r[value] is None):
            raise _bad(path, f"{at}/{where}", f"a witness is given without {value}, or {value} without one")
        if r[where] is None or r[value] is None:
            continue
        world, dart = _witness_world(path, f"{at}/{where}", n, degree, r[where])
        cost, counted = _rerun(path, f"{at}/{where}", setup, world, dart)
        found = {"max_cost": cost, "cost_per_m_exact": [cost, world.m],
                 "ratio_exact": [counted, spec.bound_for(n, world.m)]}[value]
        if r[value] != found:
            raise _bad(path, f"{at}/{value}", f"{r[value]}, but the run at {where} gives {found}")
        if where == "argmax_at":
            started = world_to_json(world.with_start(_start(world, dart)))
            if r["argmax"] != started or r.get("bound_at_argmax") != spec.bound_for(n, world.m):
                raise _bad(path, f"{at}/argmax", "it is not the world and bound at argmax_at")
    if r["argmax"] is not None and r["argmax_at"] is None:
        raise _bad(path, f"{at}/argmax", "an argmax world without argmax_at")


def _start(world: World, dart: tuple[str, int]):
    from topomark.spec.world import Start
    return Start(dart[0], world.neighbour(*dart))


def exhaustive_run(path: Path) -> dict[str, Any]:
    """``worst-case.json`` at ``path``, checked and recomputed (InvalidInput naming the field otherwise)."""
    data = _checked(path, EXHAUSTIVE)
    setup = _setup(path, data)
    refusal = exhaustive_refusal(data["max_vertices"], data["max_degree"])
    if refusal:
        raise _bad(path, "max_degree", refusal)
    ns = [r["n"] for r in data["per_n"]]
    if len(set(ns)) != len(ns):
        raise _bad(path, "per_n", f"a size is listed twice ({ns})")
    for j in range(len(data["per_n"])):
        _check_row(path, data, setup, j)
    return data


def _check_best(path: Path, data: dict[str, Any], setup: Setup, field: str, n: int, best: dict[str, Any]) -> None:
    """A search's best world, re-run: its stored cost, sizes and ratio must be what the run gives."""
    try:
        world = world_from_json(best["world"])
    except (InvalidInput, ValueError, TypeError, KeyError) as e:
        raise _bad(path, f"{field}/world", f"not a world file's object ({str(e)[:120]})") from None
    if world.n != n or world.start is None:
        raise _bad(path, f"{field}/world", f"a world of {world.n} vertices (with a start), not of n = {n}")
    if max(world.degree(v) for v in world.vertices) > data["max_degree"]:
        raise _bad(path, f"{field}/world", f"a vertex of degree above max_degree {data['max_degree']}")
    try:
        out = explore(world, setup.spec, setup.policy(), check=False, record=False, lighthouse=setup.lighthouse)
    except InvalidInput as e:
        raise _bad(path, f"{field}/world", f"its run is refused: {e}") from None
    bound = setup.spec.bound_for(world.n, world.m)
    counted = setup.spec.counted_cost(out.cost, out.by_purpose)
    found = {"cost": out.cost, "m": world.m, "n": world.n, "cost_per_m": round(out.cost / world.m, 3),
             "max_degree": max(world.degree(v) for v in world.vertices),
             "diameter": nx.diameter(nx.Graph(world.edges())),
             "ratio_to_bound": None if bound is None else round(counted / bound, 6)}
    for key, value in found.items():
        if best[key] != value:
            raise _bad(path, f"{field}/{key}", f"{best[key]}, but its world's run gives {value}")
    if out.claimed != "correct":
        raise _bad(path, f"{field}/world", f"its run ends {out.claimed}, so it is no best")


def search_run(path: Path) -> dict[str, Any]:
    """``worst-case-search.json`` at ``path``, checked and its best worlds re-run (InvalidInput otherwise)."""
    data = _checked(path, SEARCH)
    setup = _setup(path, data)
    for j, r in enumerate(data["per_n"]):
        for kind in ("search", "random"):
            if r[kind]["best"] is not None:
                _check_best(path, data, setup, f"per_n/{j}/{kind}/best", r["n"], r[kind]["best"])
    return data


def load_runs(dirs: list[Path]) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """The exhaustive and search runs of ``dirs``, each checked; a directory holding neither is bad input."""
    exhaustive: list[dict[str, Any]] = []
    searched: list[dict[str, Any]] = []
    for d in dirs:
        found = False
        for name, check, into in (("worst-case.json", exhaustive_run, exhaustive),
                                  ("worst-case-search.json", search_run, searched)):
            path = d / name
            if path.exists() or path.is_symlink():
                data = check(path)
                into.append({**data, "dir": str(d)} if into is exhaustive else data)
                found = True
        if not found:
            raise InvalidInput(f"--summarise {d}: it holds no worst-case.json nor worst-case-search.json "
                               "(give the -o directories of worst-case runs)")
    return exhaustive, searched


def bound_broken(exhaustive: list[dict[str, Any]]) -> bool:
    """Whether some summarised (and recomputed) exhaustive run costs more than its exact bound."""
    return any(r["ratio_exact"] is not None and r["ratio_exact"][0] > r["ratio_exact"][1]
               for data in exhaustive for r in data["per_n"])


__all__ += ["bound_broken", "exhaustive_run", "search_run"]

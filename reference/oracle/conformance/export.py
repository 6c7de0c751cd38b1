"""Writing a conformance suite ``topomark/conformance@2`` (thesis §3.3–3.5, §2.3.1, Chapter 6).

In the spirit of JSON-Schema-Test-Suite, Bowtie and the Ethereum consensus
test vectors, :func:`export` writes a self-describing, versioned directory
(:data:`LAYOUT`): the manifest; the published world schema; every world; for
Algorithm 3.1, topomark's checked run under each named policy (trace and
map; the cost in edge traversals, §3.1.2); and for every algorithm chosen
(:func:`~topomark.reference.oracle.conformance.cases.suite_algorithms`), each
case's kit, bound (with ``bound_source``: whose it is and what it bounds, the thesis's listing or topomark's
variant, :mod:`~topomark.reference.oracle.conformance.judgement`), expected outcome and topomark's own run of
that algorithm (``variant``: the listing as written, or topomark's variant of it, and what that changes)
(:func:`~topomark.reference.run.explore.explore` with its trace): its cost,
its marker operations by kind, its trace, the ways it went (``ways``: phases and outcome,
:mod:`~topomark.reference.algorithms.ways`) and — when it ends with one — its
map, markers included.  The suite is linted before :func:`export` returns.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Sequence

from topomark.spec.errors import CheckFailure, InvalidInput, TopomarkFault
from topomark.spec.world import World
from topomark.spec.worldfile import FORMAT as WORLD_FORMAT
from topomark.spec.worldfile import dumps_world, schema

from topomark.reference.algorithms.registry import AlgorithmSpec
from topomark.reference.oracle.conformance.cases import POLICIES, default_cases, family_of, suite_algorithms
from topomark.reference.oracle.conformance.coverage import declared_json, reference_runs
from topomark.reference.oracle.conformance.judgement import spec_bound_source
from topomark.reference.oracle.conformance.lint import lint
from topomark.reference.oracle.conformance.manifest import SUITE_FORMAT, SUITE_VERSION
from topomark.reference.oracle.protocol import PROTOCOL, PROTOCOL2
from topomark.reference.run.explore import explore
from topomark.reference.run.outcome import Outcome
from topomark.reference.trace.records import TRACE_FORMAT, dump_trace

__all__ = ["export", "LAYOUT"]

LAYOUT = {
    "manifest.json": "this file",
    "schema/world.schema.json": "JSON Schema of topomark/world@1; every worlds/ and reference/*.map.json file is "
                                "valid against it",
    "worlds/{case}.json": "the world, with its start (the robot drops its own directional marker there)",
    "reference/{case}/{policy}.trace.jsonl": "topomark's checked Algorithm 3.1 run, format topomark/trace@1",
    "reference/{case}/{policy}.map.json": "the map of that run (topomark/world@1, marker included)",
    "algorithms/{algorithm}/{case}.trace.jsonl": "topomark's checked run of that algorithm on that case's world "
                                                 "with that case's kit, format topomark/trace@2",
    "algorithms/{algorithm}/{case}.map.json": "the map of that run, every marker it left included (none when the "
                                              "run ends without a map)",
}


def export(directory: str | Path, cases: Sequence[tuple[str, str, World]] | None = None,
           algorithms: Sequence[AlgorithmSpec] | None = None) -> dict[str, Any]:
    """Write the suite to ``directory`` (created; must be new or empty) and lint it; returns the manifest.

    ``cases``: Algorithm 3.1's (default :func:`default_cases`); ``algorithms``: the algorithms with a suite
    (default every deterministic one; ``()`` for none)."""
    root = Path(directory)
    if root.exists() and (not root.is_dir() or any(root.iterdir())):
        raise InvalidInput(f"{root}: the suite directory must be new or empty")
    cases = default_cases() if cases is None else cases
    algorithms = suite_algorithms() if algorithms is None else algorithms
    (root / "schema").mkdir(parents=True, exist_ok=True)
    (root / "worlds").mkdir(exist_ok=True)
    (root / "schema" / "world.schema.json").write_text(json.dumps(schema(), indent=2) + "\n", encoding="utf-8")
    entries = [_export_case(root, name, text, world) for name, text, world in cases]
    manifest = {
        "format": SUITE_FORMAT, "version": SUITE_VERSION, "world_format": WORLD_FORMAT,
        "trace_format": TRACE_FORMAT, "protocol": PROTOCOL, "algorithm": "Algorithm 3.1 (basic)",
        "marker_class": {"directional-vertex": 1}, "layout": LAYOUT,
        "policies": {k: p.to_json() for k, p in POLICIES.items()}, "cases": entries,
        "suites_protocol": PROTOCOL2, "suites": [_export_suite(root, spec) for spec in algorithms],
    }
    (root / "manifest.json").write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    lint(root)
    return manifest


def _write_world(root: Path, name: str, world: World) -> str:
    """``worlds/<name>.json``, shared by every case of that name: a second, different world of one name is a fault."""
    rel, text = f"worlds/{name}.json", dumps_world(world)
    target = root / rel
    if target.exists() and target.read_text(encoding="utf-8") != text:
        raise TopomarkFault(f"two different worlds are both called {name!r} in the suite")
    target.write_text(text, encoding="utf-8")
    return rel


def _export_case(root: Path, name: str, text: str, world: World) -> dict[str, Any]:
    if (root / "reference" / name).exists():
        raise InvalidInput(f"duplicate case name {name!r}")
    rel = _write_world(root, name, world)
    refdir = root / "reference" / name
    refdir.mkdir(parents=True, exist_ok=True)
    reference = {}
    for label, policies in POLICIES.items():
        out = explore(world, policies=policies, check_mode="incremental")
        if out.violation is not None:
            raise CheckFailure(f"the reference explorer failed on {name} ({label}): {out.violation}")
        (refdir / f"{label}.trace.jsonl").write_text(dump_trace(out.trace), encoding="utf-8")
        (refdir / f"{label}.map.json").write_text(dumps_world(out.explorer.S.to_world()), encoding="utf-8")
        reference[label] = {"cost": out.cost, "trace": f"reference/{name}/{label}.trace.jsonl",
                            "map": f"reference/{name}/{label}.map.json"}
    return {"name": name, "description": text, "world": rel, "n": world.n, "m": world.m, "reference": reference}


def _export_suite(root: Path, spec: AlgorithmSpec) -> dict[str, Any]:
    """One algorithm's suite: the ways its runs can go (``ways``), its cases, each with topomark's checked run of
    it and the ways that run went (:mod:`~topomark.reference.oracle.conformance.coverage`)."""
    (root / "algorithms" / spec.name).mkdir(parents=True, exist_ok=True)
    return {"algorithm": spec.name, "family": family_of(spec), "thesis": spec.thesis, "bound": spec.bound,
            "bound_note": spec.bound_note, "bound_source": spec_bound_source(spec), "variant": spec.variant_json(),
            "markers": spec.markers, "protocol": PROTOCOL2, "ways": declared_json(spec),
            "cases": [_export_algorithm_case(root, spec, *case, out, ways) for case, out, ways in reference_runs(spec)]}


def _export_algorithm_case(root: Path, spec: AlgorithmSpec, name: str, world_name: str, text: str, world: World,
                           options: dict[str, Any], out: Outcome, ways: list[str]) -> dict[str, Any]:
    """The case: world, kit, bound, the reference run ``out`` (correct, or failed: the kit runs out) and the ways
    it went."""
    base = f"algorithms/{spec.name}/{name}"
    (root / f"{base}.trace.jsonl").write_text(dump_trace(out.trace), encoding="utf-8")
    map_rel = None
    if out.outcome == "correct":
        map_rel = f"{base}.map.json"
        (root / map_rel).write_text(dumps_world(out.explorer.S.to_world()), encoding="utf-8")
    opts = spec.parse_options(options)
    return {"name": name, "description": text, "world": _write_world(root, world_name, world),
            "n": world.n, "m": world.m, "options": options, "kit": spec.kit_for(world.n, world.m, opts).to_json(),
            "bound": spec.bound_for(world.n, world.m), "bound_source": spec_bound_source(spec),
            "variant": spec.variant_json(), "expected": out.outcome, "reason": out.reason, "ways": ways,
            "reference": {"cost": out.cost, "marker_operations": dict(out.marker_operations), "trace":
                          f"{base}.trace.jsonl", "map": map_rel}}

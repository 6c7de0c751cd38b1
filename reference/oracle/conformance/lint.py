"""Checking a conformance suite, ``topomark/conformance@2`` or ``@1`` (thesis §3.1.3, §3.3).

:func:`lint` checks a suite: the manifest's shape and version, field by
field and before anything else
(:func:`~topomark.reference.oracle.conformance.manifest.check_manifest`),
the suite's schema being the published one, every world and map file valid
against the published schema and the strict loader, every file listed and
every listed file present, every reference trace verified by
:func:`topomark.reference.replay.replay.replay` with the cost the manifest
claims, every Algorithm 3.1 reference map isomorphic to its world.  For an
algorithm's suite (``@2``) also: the algorithm is registered, the case's kit
is the one the registry gives it on that world with those options, its bound,
whose the bound is and the variant its run was made with the registry's (when the suite records them), the trace's kit that kit and its end the expected outcome, and
a map (where the run ends with one) the world's embedded graph.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from topomark.spec.errors import TopomarkFault
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.jsontext import parse_json, read_text_file
from topomark.spec.world import World
from topomark.spec.worldfile import FORMAT as WORLD_FORMAT
from topomark.spec.worldfile import MAX_WORLD_BYTES, loads_world, schema

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.oracle.conformance.judgement import spec_bound_source
from topomark.reference.oracle.conformance.manifest import bad, load_manifest
from topomark.reference.replay.replay import load_trace, replay
from topomark.reference.run.map_check import check_map

__all__ = ["lint"]

_SCHEMA_BYTES = 1 << 20
_LINE_BYTES = 4 << 20


def _validator(root: Path) -> Callable[[Any, str], None]:
    """Validation against the published world schema, which the suite's copy must equal.

    The suite's ``schema/world.schema.json`` is compared with topomark's own
    (a tampered schema could make anything valid, or make validation itself
    expensive); validation then uses topomark's.  ``jsonschema`` is a
    dependency of topomark: without it lint cannot do its job, which is a
    fault of the installation (exit 3), not of the suite.
    """
    rel = "schema/world.schema.json"
    if not (root / rel).is_file():
        bad(root, f"{rel} is missing")
    published = parse_json(read_text_file(root / rel, max_bytes=_SCHEMA_BYTES), str(root / rel))
    if published != schema():
        bad(root, f"{rel} is not the published schema of {WORLD_FORMAT}")
    try:
        import jsonschema
    except ImportError:
        raise TopomarkFault("conformance lint needs the jsonschema package, a dependency of topomark; "
                            "reinstall topomark (python3 -m pip install . from a checkout)") from None
    validator = jsonschema.Draft202012Validator(published)

    def check(obj: Any, where: str) -> None:
        error = next(iter(validator.iter_errors(obj)), None)
        if error is not None:
            bad(root, f"{where} is not valid against {rel}: {error.message}")
    return check


def lint(directory: str | Path, replay_traces: bool = True) -> dict[str, Any]:
    """Check the suite; any defect is one :class:`~topomark.spec.errors.InvalidInput`.  Returns the manifest."""
    root = Path(directory)
    manifest = load_manifest(root)
    validate = _validator(root)
    listed = {"manifest.json", "schema/world.schema.json"}
    for case in manifest["cases"]:
        _lint_case(root, case, validate, listed, replay_traces)
    for suite in manifest.get("suites", ()):
        for case in suite["cases"]:
            _lint_algorithm_case(root, suite["algorithm"], case, validate, listed, replay_traces)
    present = {p.relative_to(root).as_posix() for p in root.rglob("*") if p.is_file()}
    for path in sorted(present - listed):
        bad(root, f"{path} is not listed in the manifest")
    return manifest


def _load_checked(root: Path, rel: str, validate, listed: set[str], what: str) -> World:
    """The world or map file ``rel``: valid against the schema, then loaded by the strict loader."""
    if not (root / rel).exists():
        bad(root, f"{what}: file {rel!r} is missing")
    listed.add(rel)
    text = read_text_file(root / rel, max_bytes=MAX_WORLD_BYTES)
    validate(parse_json(text, str(root / rel)), rel)
    return loads_world(text, str(root / rel))


def _case_world(root: Path, case: dict, validate, listed: set[str], where: str) -> World:
    world = _load_checked(root, case["world"], validate, listed, where)
    if (case["n"], case["m"]) != (world.n, world.m):
        bad(root, f"{where}: manifest says n={case['n']}, m={case['m']}; the world has n={world.n}, m={world.m}")
    return world


def _replayed(root: Path, world: World, rel: str, cost: int, where: str, listed: set[str], check: bool) -> None:
    """The trace ``rel`` is present, and (``check``) replays on ``world`` with the claimed cost."""
    if not (root / rel).exists():
        bad(root, f"{where}: trace file {rel!r} is missing")
    listed.add(rel)
    if check:
        result = replay(world, load_trace(root / rel), rel)
        if not result.ok and not result.recorded_failure:
            bad(root, f"{where}: the reference trace does not replay: {result.message}")
        if result.cost != cost:
            bad(root, f"{where}: manifest cost {cost} but the trace has {result.cost} traversals")


def _lint_case(root: Path, case: dict, validate, listed: set[str], replay_traces: bool) -> None:
    """Check one Algorithm 3.1 case whose shape the manifest check has checked: its files and their agreement."""
    name = case["name"]
    world = _case_world(root, case, validate, listed, f"case {name}")
    for label, ref in case["reference"].items():
        where = f"case {name}, policy {label}"
        map_ = _load_checked(root, ref["map"], validate, listed, where)
        if not check_map(world, map_).isomorphic:
            bad(root, f"{where}: the reference map is not isomorphic to the world")
        _replayed(root, world, ref["trace"], ref["cost"], where, listed, replay_traces)


def _lint_algorithm_case(root: Path, algorithm: str, case: dict, validate, listed: set[str],
                         replay_traces: bool) -> None:
    """Check one case of an algorithm's suite: kit and bound as the registry gives them, the run's files."""
    where = f"algorithm {algorithm}, case {case['name']}"
    spec = algorithm_spec(algorithm)
    world = _case_world(root, case, validate, listed, where)
    options = spec.parse_options(case["options"])
    kit = spec.kit_for(world.n, world.m, options).to_json()
    if case["kit"] != kit:
        bad(root, f"{where}: manifest kit {case['kit']} but {algorithm} is given {kit} on this world")
    if case["bound"] != spec.bound_for(world.n, world.m):
        bad(root, f"{where}: manifest bound {case['bound']} but {algorithm}'s bound here is "
                  f"{spec.bound_for(world.n, world.m)}")
    _check_provenance(root, where, case, spec)
    ref = case["reference"]
    if ref["map"] is not None:
        map_ = _load_checked(root, ref["map"], validate, listed, where)
        if not find_isomorphism(world, map_, markers=False).isomorphic:  # its markers are the run's (the trace's)
            bad(root, f"{where}: the reference map is not isomorphic to the world")
    _replayed(root, world, ref["trace"], ref["cost"], where, listed, replay_traces)
    if replay_traces:
        _check_ends(root, ref["trace"], case, kit, where, algorithm)


def _check_provenance(root: Path, where: str, case: dict, spec: Any) -> None:
    """Whose the bound is (``bound_source.source``) and which explorer made the run (``variant.follows``), where
    the suite records them, are the registry's (their prose may differ between versions)."""
    source, want = case.get("bound_source"), spec_bound_source(spec)
    if "bound_source" in case and (source and source["source"]) != (want and want["source"]):
        bad(root, f"{where}: manifest bound_source {source and source['source']!r} but {spec.name}'s bound is "
                  f"{spec.bound_whose or 'none'}")
    variant = case.get("variant")
    if variant is not None and variant["follows"] != spec.variant_json()["follows"]:
        bad(root, f"{where}: manifest variant follows {variant['follows']} but {spec.name}'s run is made with "
                  f"{spec.variant_json()['follows']}")


def _check_ends(root: Path, rel: str, case: dict, kit: dict, where: str, case_algorithm: str) -> None:
    """The trace's header carries the case's kit (trace@2; trace@1 is Algorithm 3.1's lighthouse, whose kit is
    the case's when the registry's is), its algorithm the suite's, and its end record the expected outcome."""
    lines = [line for line in read_text_file(root / rel, max_bytes=64 << 20).splitlines() if line.strip()]
    head, end = parse_json(lines[0], rel), parse_json(lines[-1], rel)
    if head.get("algorithm") != case_algorithm:
        bad(root, f"{where}: the trace is a run of {head.get('algorithm')!r}, not of {case_algorithm!r}")
    if head.get("kit", kit) != kit:
        bad(root, f"{where}: the trace's kit {head.get('kit')} is not the case's {kit}")
    outcome = end.get("outcome") or ("correct" if end.get("verified") else "unverified")
    if outcome != case["expected"]:
        bad(root, f"{where}: the manifest expects {case['expected']}, the reference trace ends {outcome}")

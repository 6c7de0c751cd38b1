"""The conformance suite ``topomark/conformance@1``: worlds, reference runs, and a runner (thesis §3.3–3.5).

In the spirit of JSON-Schema-Test-Suite, Bowtie and the Ethereum consensus
test vectors, :func:`export` writes a self-describing, versioned directory:

``manifest.json``
    format, version, the formats it uses (world, trace, protocol), the layout,
    the named policies and one entry per case;
``schema/world.schema.json``
    the published schema every world and map file of the suite is valid against;
``worlds/<case>.json``
    each world (``topomark/world@1``, with its start): the thesis's figures
    (the Figure 3.4/3.6 wheel pair, the trace.md triangle, the Figure 3.3
    cycles, chains) and generated world families of §3.5.3 across sizes;
``reference/<case>/<policy>.trace.jsonl`` and ``.map.json``
    topomark's checked Algorithm 3.1 run under each named policy (§3.3 leaves
    the edge, hypothesis and path choices open): its trace (``spec/trace.md``),
    its map, and in the manifest its cost in edge traversals (§3.1.2).

:func:`lint` checks a suite: the manifest's shape and version, field by field
and before anything else (:func:`check_manifest`: every path relative and
inside the suite, every count and cost a positive integer), unique case
names, the suite's schema being the published one, every world and map file valid against the published schema and the
strict loader, every file listed and every listed file present, every
reference trace verified by :func:`topomark.reference.replay.replay.replay` with
the cost the manifest claims, every reference map isomorphic to its world.

:func:`run` plays every world to an external implementation through
``topomark/protocol@1`` or ``@2`` with any kit (:func:`topomark.reference.oracle.run_external.run_external`): a
crash, a hang or garbage is a failure like a wrong map.  Each row reports the
implementation's cost and its ratio to the reference costs.

A suite is input like any other: every file is read through
:mod:`topomark.spec.jsontext` (regular files only, bounded size, UTF-8,
bounded nesting and integers), and any defect of a tampered suite is one
:class:`~topomark.spec.errors.InvalidInput` naming the file and field.
"""

from __future__ import annotations

import json
import re
import time
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Any, Callable, Sequence

from topomark.spec.errors import CheckFailure, InvalidInput, TopomarkFault, clip
from topomark.spec.jsontext import parse_json, read_text_file
from topomark.spec.kit import Kit
from topomark.spec.world import Start, World
from topomark.spec.worldfile import FORMAT as WORLD_FORMAT
from topomark.spec.worldfile import MAX_WORLD_BYTES, dumps_world, load_world, loads_world, schema

from topomark.reference.worlds import generators as g
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import TRACE_FORMAT, dump_trace
from topomark.reference.oracle.run_external import ExternalResult, Limits, run_external
from topomark.reference.run.map_check import check_map
from topomark.reference.explorers.policies import Policies
from topomark.reference.oracle.protocol import PROTOCOL
from topomark.reference.replay.replay import load_trace, replay

__all__ = ["SUITE_FORMAT", "SUITE_VERSION", "POLICIES", "default_cases", "export", "lint", "run", "Row",
           "render_table", "load_manifest", "check_manifest"]

SUITE_FORMAT = "topomark/conformance@1"
SUITE_VERSION = "1.0.0"
POLICIES: dict[str, Policies] = {  # the default, and each other named policy of policies.py alone
    "default": Policies(),
    "edge-fifo": Policies(edge="fifo"),
    "edge-lifo": Policies(edge="lifo"),
    "hypothesis-lifo": Policies(hypothesis="lifo"),
    "hypothesis-shortest": Policies(hypothesis="shortest"),
    "path-dfs": Policies(path="dfs"),
}
_NAME = re.compile(r"[a-z0-9][a-z0-9.-]*")
_PATH_PART = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]*")  # no "..", no hidden files, nothing the OS reinterprets
_MANIFEST_BYTES = 64 << 20  # the default suite's manifest is about 20 kB
LAYOUT = {
    "manifest.json": "this file",
    "schema/world.schema.json": "JSON Schema of topomark/world@1; every worlds/ and reference/*.map.json file is "
                                "valid against it",
    "worlds/{case}.json": "the world, with its start (the robot drops its own directional marker there)",
    "reference/{case}/{policy}.trace.jsonl": "topomark's checked Algorithm 3.1 run, format topomark/trace@1",
    "reference/{case}/{policy}.map.json": "the map of that run (topomark/world@1, marker included)",
}


def _started(world: World) -> World:
    """The world with an explicit start: its own, or its first vertex facing exit 0."""
    if world.start is not None:
        return world
    v = world.vertices[0]
    return world.with_start(Start(v, world.rotation[v][0]))


def default_cases() -> list[tuple[str, str, World]]:
    """(name, description, world) of the default suite: thesis figures, then world families across sizes."""
    wa, wb = g.wheel_pair_directional()
    cases = [
        ("figure-3.6-wheel-a", "Figure 3.4/3.6(a): planar wheel W4, directional marker at the centre", wa),
        ("figure-3.6-wheel-b", "Figure 3.4/3.6(b): twisted wheel W4 (genus 1)", wb),
        ("triangle", "the spec/trace.md example: C3 at 0 facing 1", g.cycle(3)),
    ]
    for n in (4, 7, 12):
        cases.append((f"cycle-{n}", f"Figure 3.3: the cycle C{n}", g.cycle(n)))
    for n in (2, 6):
        cases.append((f"chain-{n}", f"a chain of {n} vertices", g.chain(n)))
    for r, c in ((2, 3), (3, 3), (4, 4)):
        cases.append((f"lattice-{r}x{c}", f"§3.5.3: the {r}x{c} lattice", g.lattice(r, c)))
    cases.append(("lattice-hole-5x5-s1", "§3.5.3: 5x5 lattice, 10% of cells removed, seed 1",
                  g.lattice_hole(5, 5, 0.1, "vertices", 1)))
    cases.append(("lattice-hole-6x6-edges-s2", "§3.5.3: 6x6 lattice, 10% of edges removed, seed 2",
                  g.lattice_hole(6, 6, 0.1, "edges", 2)))
    for n in (4, 6):
        cases.append((f"complete-{n}", f"§3.5.3: the complete graph K{n} (non-planar rotation)", g.complete(n)))
    cases.append(("complete-hole-7-s3", "§3.5.3: K7 with 10% of edges removed, seed 3", g.complete_hole(7, 0.1, 3)))
    cases.append(("small-world-12-s4", "§3.5.3: small-world n=12 k=4 p=0.2, seed 4", g.small_world(12, 4, 0.2, 4)))
    for seed in (5, 6):
        cases.append((f"random-9-s{seed}", f"§3.5.3: random graph n=9, 40% density, seed {seed}",
                      g.random_graph(9, 0.4, seed)))
    return [(name, text, _started(w)) for name, text, w in cases]


# -- export ---------------------------------------------------------------------
def export(directory: str | Path, cases: Sequence[tuple[str, str, World]] | None = None) -> dict[str, Any]:
    """Write the suite to ``directory`` (created; must be empty or absent) and lint it; returns the manifest."""
    root = Path(directory)
    if root.exists() and (not root.is_dir() or any(root.iterdir())):
        raise InvalidInput(f"{root}: the suite directory must be new or empty")
    cases = default_cases() if cases is None else cases
    (root / "schema").mkdir(parents=True, exist_ok=True)
    (root / "worlds").mkdir(exist_ok=True)
    (root / "schema" / "world.schema.json").write_text(json.dumps(schema(), indent=2) + "\n", encoding="utf-8")
    entries = [_export_case(root, name, text, world) for name, text, world in cases]
    manifest = {
        "format": SUITE_FORMAT, "version": SUITE_VERSION, "world_format": WORLD_FORMAT,
        "trace_format": TRACE_FORMAT, "protocol": PROTOCOL, "algorithm": "Algorithm 3.1 (basic)",
        "marker_class": {"directional-vertex": 1}, "layout": LAYOUT,
        "policies": {k: p.to_json() for k, p in POLICIES.items()}, "cases": entries,
    }
    (root / "manifest.json").write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    lint(root)
    return manifest


def _export_case(root: Path, name: str, text: str, world: World) -> dict[str, Any]:
    (root / "worlds" / f"{name}.json").write_text(dumps_world(world), encoding="utf-8")
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
    return {"name": name, "description": text, "world": f"worlds/{name}.json", "n": world.n, "m": world.m,
            "reference": reference}


# -- lint -----------------------------------------------------------------------
def _bad(root: Path, message: str) -> None:
    raise InvalidInput(f"suite {root}: {message}")


def load_manifest(root: Path) -> dict[str, Any]:
    """The parsed ``manifest.json`` of the suite at ``root``, its shape checked by :func:`check_manifest`."""
    path = root / "manifest.json"
    if not path.exists():
        _bad(root, "no readable manifest.json (is this a conformance suite directory?)")
    manifest = parse_json(read_text_file(path, max_bytes=_MANIFEST_BYTES), str(path))
    check_manifest(root, manifest)
    return manifest


def _field(root: Path, where: str, value: Any, ok: bool, want: str) -> None:
    if not ok:
        _bad(root, f"manifest.json: {where} must be {want}, got {clip(json.dumps(value), 60, note='')}")


def _count(root: Path, where: str, value: Any) -> None:
    _field(root, where, value, isinstance(value, int) and not isinstance(value, bool) and value >= 1,
           "a positive integer")


def _path(root: Path, where: str, value: Any) -> None:
    ok = isinstance(value, str) and all(_PATH_PART.fullmatch(p) for p in value.split("/"))
    _field(root, where, value, ok and not PurePosixPath(value).is_absolute(),
           "a relative path inside the suite (letters, digits, '_', '.', '-' and '/')")


def check_manifest(root: Path, manifest: Any) -> None:
    """Check the shape of a parsed manifest, field by field, before any of it is used.

    Format, version (same major version), protocol; ``policies`` a non-empty
    object; each case an object with a valid unique ``name``, a string
    ``description``, a ``world`` path, positive integers ``n`` and ``m``, and a
    ``reference`` with one object per policy holding a positive integer
    ``cost`` (costs are divided by) and ``trace`` and ``map`` paths.  Paths
    are relative and cannot leave the suite (no ``..``, no absolute path).
    Any defect is one :class:`InvalidInput` naming ``manifest.json`` and the field.
    """
    _field(root, "the manifest", manifest, isinstance(manifest, dict), "a JSON object")
    fmt = manifest.get("format")
    if fmt != SUITE_FORMAT:
        _bad(root, f"manifest format {fmt!r} is not {SUITE_FORMAT}")
    version = manifest.get("version")
    _field(root, "version", version, isinstance(version, str), "a version string")
    if version.split(".")[0] != SUITE_VERSION.split(".")[0]:
        _bad(root, f"suite version {version!r} is not compatible with {SUITE_VERSION}")
    for key, want in (("cases", list), ("policies", dict), ("protocol", str)):
        if not isinstance(manifest.get(key), want):
            _bad(root, f"manifest.{key} is missing or not a {want.__name__}")
    if manifest["protocol"] != PROTOCOL:
        _bad(root, f"the suite speaks {manifest['protocol']!r}, this topomark speaks {PROTOCOL}")
    policies = manifest["policies"]
    _field(root, "policies", policies, bool(policies), "a non-empty object")
    names: set[str] = set()
    for k, case in enumerate(manifest["cases"]):
        _field(root, f"cases[{k}]", case, isinstance(case, dict), "an object")
        name = case.get("name")
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            _bad(root, f"cases[{k}] has no valid name (lowercase letters, digits, '.', '-')")
        if name in names:
            _bad(root, f"duplicate case name {name!r}")
        names.add(name)
        _check_case(root, f"cases[{k}] ({name})", case, policies)


def _check_case(root: Path, where: str, case: dict, policies: dict) -> None:
    _field(root, f"{where}.description", case.get("description"), isinstance(case.get("description"), str),
           "a string")
    _path(root, f"{where}.world", case.get("world"))
    _count(root, f"{where}.n", case.get("n"))
    _count(root, f"{where}.m", case.get("m"))
    reference = case.get("reference")
    if not isinstance(reference, dict) or set(reference) != set(policies):
        _bad(root, f"manifest.json: {where}.reference must have one entry per named policy "
                   f"({', '.join(policies)})")
    for label, ref in reference.items():
        _field(root, f"{where}.reference.{label}", ref, isinstance(ref, dict), "an object {cost, trace, map}")
        _count(root, f"{where}.reference.{label}.cost", ref.get("cost"))
        _path(root, f"{where}.reference.{label}.trace", ref.get("trace"))
        _path(root, f"{where}.reference.{label}.map", ref.get("map"))


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
        _bad(root, f"{rel} is missing")
    published = parse_json(read_text_file(root / rel, max_bytes=_MANIFEST_BYTES), str(root / rel))
    if published != schema():
        _bad(root, f"{rel} is not the published schema of {WORLD_FORMAT}")
    try:
        import jsonschema
    except ImportError:
        raise TopomarkFault("conformance lint needs the jsonschema package, a dependency of topomark; "
                            "reinstall topomark (pip install topomark)") from None
    validator = jsonschema.Draft202012Validator(published)

    def check(obj: Any, where: str) -> None:
        error = next(iter(validator.iter_errors(obj)), None)
        if error is not None:
            _bad(root, f"{where} is not valid against {rel}: {error.message}")
    return check


def lint(directory: str | Path, replay_traces: bool = True) -> dict[str, Any]:
    """Check the suite; any defect is one :class:`InvalidInput`.  Returns the manifest."""
    root = Path(directory)
    manifest = load_manifest(root)
    validate = _validator(root)
    listed = {"manifest.json", "schema/world.schema.json"}
    for case in manifest["cases"]:
        _lint_case(root, case, validate, listed, manifest["policies"], replay_traces)
    present = {p.relative_to(root).as_posix() for p in root.rglob("*") if p.is_file()}
    for path in sorted(present - listed):
        _bad(root, f"{path} is not listed in the manifest")
    return manifest


def _load_checked(root: Path, rel: str, validate, listed: set[str], what: str) -> World:
    """The world or map file ``rel``: valid against the schema, then loaded by the strict loader."""
    if not (root / rel).exists():
        _bad(root, f"{what}: file {rel!r} is missing")
    listed.add(rel)
    text = read_text_file(root / rel, max_bytes=MAX_WORLD_BYTES)
    validate(parse_json(text, str(root / rel)), rel)
    return loads_world(text, str(root / rel))


def _lint_case(root: Path, case: dict, validate, listed: set[str], policies: dict, replay_traces: bool) -> None:
    """Check one case whose shape :func:`check_manifest` has checked: its files and their agreement."""
    name = case["name"]
    world = _load_checked(root, case["world"], validate, listed, f"case {name}")
    if (case["n"], case["m"]) != (world.n, world.m):
        _bad(root, f"case {name}: manifest says n={case['n']}, m={case['m']}; the world has "
                   f"n={world.n}, m={world.m}")
    for label, ref in case["reference"].items():
        where = f"case {name}, policy {label}"
        map_ = _load_checked(root, ref["map"], validate, listed, where)
        if not check_map(world, map_).isomorphic:
            _bad(root, f"{where}: the reference map is not isomorphic to the world")
        trace = ref["trace"]
        if not (root / trace).exists():
            _bad(root, f"{where}: trace file {trace!r} is missing")
        listed.add(trace)
        if replay_traces:
            result = replay(world, load_trace(root / trace), trace)
            if not result.ok:
                _bad(root, f"{where}: the reference trace does not replay: {result.message}")
            if result.cost != ref["cost"]:
                _bad(root, f"{where}: manifest cost {ref['cost']} but the trace has {result.cost} traversals")


# -- run ------------------------------------------------------------------------
@dataclass
class Row:
    name: str
    n: int
    m: int
    result: ExternalResult
    reference: int  # the default policy's cost
    best: int  # the cheapest named policy's cost

    def to_json(self) -> dict[str, Any]:
        r = self.result
        return {"case": self.name, "n": self.n, "m": self.m, "verdict": r.verdict, "reason": r.reason,
                "message": r.message, "cost": r.cost, "reference_cost": self.reference, "best_reference_cost":
                self.best, "ratio": round(r.cost / self.reference, 3) if r.passed else None,
                "ratio_best": round(r.cost / self.best, 3) if r.passed else None, "wall_seconds": round(r.wall, 3)}


def run(directory: str | Path, command: Sequence[str], limits: Limits | None = None,
        select: str | None = None, progress: Callable[[Row], None] | None = None, version: int = 1,
        kit: Kit | None = None) -> list[Row]:
    """Run ``command`` on every case (or those whose name contains ``select``), speaking protocol ``version``
    with ``kit`` (:func:`topomark.reference.oracle.run_external.run_external`)."""
    root = Path(directory)
    manifest = lint(root, replay_traces=False)
    rows = []
    for case in manifest["cases"]:
        if select and select not in case["name"]:
            continue
        world = load_world(root / case["world"])
        costs = {k: v["cost"] for k, v in case["reference"].items()}
        row = Row(case["name"], world.n, world.m, run_external(world, command, limits, version=version, kit=kit),
                  costs.get("default", min(costs.values())), min(costs.values()))
        rows.append(row)
        if progress is not None:
            progress(row)
    if not rows:
        raise InvalidInput(f"no case of {root} matches {select!r}")
    return rows


def render_table(rows: list[Row], wall: float) -> str:
    head = ("case", "n", "m", "verdict", "cost", "ref", "ratio", "best", "ratio", "reason")
    body = []
    for row in rows:
        j = row.to_json()
        body.append((row.name, str(row.n), str(row.m), j["verdict"].upper(), str(j["cost"]), str(row.reference),
                     "-" if j["ratio"] is None else f"{j['ratio']:.2f}", str(row.best),
                     "-" if j["ratio_best"] is None else f"{j['ratio_best']:.2f}",
                     "" if row.result.passed else f"{row.result.reason}: {row.result.message}"[:100]))
    widths = [max(len(r[k]) for r in [head] + body) for k in range(len(head) - 1)]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r[:-1], widths)) + "  " + r[-1] for r in [head] + body]
    passed = sum(r.result.passed for r in rows)
    lines.append(f"{passed}/{len(rows)} passed in {wall:.1f} s "
                 "(ref: topomark's cost under the default policy; best: the cheapest named policy)")
    return "\n".join(line.rstrip() for line in lines)


def timed_run(directory, command, limits=None, select=None, progress=None, version: int = 1,
              kit: Kit | None = None) -> tuple[list[Row], float]:
    started = time.monotonic()
    rows = run(directory, command, limits, select, progress, version, kit)
    return rows, time.monotonic() - started

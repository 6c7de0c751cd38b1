"""The manifest of a conformance suite: ``topomark/conformance@2`` (and ``@1``), its shape checked field by field.

A suite is input like any other: :func:`load_manifest` reads ``manifest.json``
through :mod:`topomark.spec.jsontext` and :func:`check_manifest` checks every
field before any of it is used — every path relative and inside the suite,
every count and cost a positive integer — so a tampered suite is one
:class:`~topomark.spec.errors.InvalidInput` naming the file and the field.

``@1`` (version 1.x) holds Algorithm 3.1's cases only (``cases``: one world,
one reference run per named policy, §3.3).  ``@2`` (version 2.x) holds the same
``cases`` and, in ``suites``, one suite per algorithm of the registry: each case
a world, the kit that algorithm is given on it (the registry's
``kit_for(n, m, options)``, §6.2.1), the bound, the expected outcome
(``correct``, or ``failed`` where the kit runs out), and topomark's reference run
(cost, marker operations by kind, trace, map).  From version 2.1 each such case also names whose its bound is
(``bound_source``: the thesis's, or topomark's for the listing or for its own variant) and the variant its
reference run was made with (``variant``); from version 2.2 each suite declares the ways its algorithm's runs can
go (``ways``: name ↦ kind, text, thesis section) and each case the ways its reference run went (``ways``: a list of
those names).  A 2.0 or 2.1 suite without them stays readable.  Both formats stay readable.
"""

from __future__ import annotations

import json
import re
from pathlib import Path, PurePosixPath
from typing import Any

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.jsontext import parse_json, read_text_file

from topomark.reference.oracle.protocol import PROTOCOL

__all__ = ["SUITE_FORMAT", "SUITE_VERSION", "SUITE_FORMAT_1", "SUITE_VERSION_1", "VERSIONS", "OUTCOMES",
           "load_manifest", "check_manifest", "bad"]

SUITE_FORMAT = "topomark/conformance@2"
SUITE_VERSION = "2.2.0"  # 2.1: each algorithm case says whose its bound is and which variant made its run;
# 2.2: each algorithm suite declares the ways its runs can go, each case the ways its reference run went
SUITE_FORMAT_1 = "topomark/conformance@1"
SUITE_VERSION_1 = "1.0.0"
VERSIONS = {SUITE_FORMAT_1: SUITE_VERSION_1, SUITE_FORMAT: SUITE_VERSION}
OUTCOMES = ("correct", "failed")  # what an algorithm suite's case expects (spec.errors.OUTCOMES, the two a run ends in)
NAME = re.compile(r"[a-z0-9][a-z0-9.+-]*")
_PATH_PART = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.+-]*")  # no "..", no hidden files, nothing the OS reinterprets
_MANIFEST_BYTES = 64 << 20  # the default suite's manifest is about 200 kB


def bad(root: Path, message: str) -> None:
    raise InvalidInput(f"suite {root}: {message}")


def load_manifest(root: Path) -> dict[str, Any]:
    """The parsed ``manifest.json`` of the suite at ``root``, its shape checked by :func:`check_manifest`."""
    path = root / "manifest.json"
    if not path.exists():
        bad(root, "no readable manifest.json (is this a conformance suite directory?)")
    manifest = parse_json(read_text_file(path, max_bytes=_MANIFEST_BYTES), str(path))
    check_manifest(root, manifest)
    return manifest


def field(root: Path, where: str, value: Any, ok: bool, want: str) -> None:
    if not ok:
        bad(root, f"manifest.json: {where} must be {want}, got {clip(json.dumps(value), 60, note='')}")


def count(root: Path, where: str, value: Any, minimum: int = 1) -> None:
    field(root, where, value, isinstance(value, int) and not isinstance(value, bool) and value >= minimum,
          "a positive integer" if minimum == 1 else f"an integer >= {minimum}")


def path(root: Path, where: str, value: Any) -> None:
    ok = isinstance(value, str) and all(_PATH_PART.fullmatch(p) for p in value.split("/"))
    field(root, where, value, ok and not PurePosixPath(value).is_absolute(),
          "a relative path inside the suite (letters, digits, '_', '.', '+', '-' and '/')")


def check_manifest(root: Path, manifest: Any) -> None:
    """Check the shape of a parsed manifest, field by field, before any of it is used.

    Format (``@1`` or ``@2``), version (the same major version as the
    format's), protocol; ``policies`` a non-empty object; each case an
    object with a valid unique ``name``, a string ``description``, a
    ``world`` path, positive integers ``n`` and ``m``, and a ``reference``
    with one object per policy holding a positive integer ``cost`` (costs are
    divided by) and ``trace`` and ``map`` paths.  ``@2`` adds ``suites``
    (:func:`_check_suite`).  Paths are relative and cannot leave the suite (no
    ``..``, no absolute path).  Any defect is one :class:`InvalidInput`
    naming ``manifest.json`` and the field.
    """
    field(root, "the manifest", manifest, isinstance(manifest, dict), "a JSON object")
    fmt = manifest.get("format")
    if fmt not in VERSIONS:
        bad(root, f"manifest format {clip(repr(fmt), 60)} is not {SUITE_FORMAT} (nor {SUITE_FORMAT_1})")
    version = manifest.get("version")
    field(root, "version", version, isinstance(version, str), "a version string")
    if version.split(".")[0] != VERSIONS[fmt].split(".")[0]:
        bad(root, f"suite version {version!r} is not compatible with {VERSIONS[fmt]} ({fmt})")
    for key, want in (("cases", list), ("policies", dict), ("protocol", str)):
        if not isinstance(manifest.get(key), want):
            bad(root, f"manifest.{key} is missing or not a {want.__name__}")
    if manifest["protocol"] != PROTOCOL:
        bad(root, f"the suite speaks {manifest['protocol']!r}, this topomark speaks {PROTOCOL}")
    policies = manifest["policies"]
    field(root, "policies", policies, bool(policies), "a non-empty object")
    names: set[str] = set()
    for k, case in enumerate(manifest["cases"]):
        _check_name(root, f"cases[{k}]", case, names)
        _check_case(root, f"cases[{k}] ({case['name']})", case, policies)
    if fmt == SUITE_FORMAT_1:
        if "suites" in manifest:
            bad(root, f"manifest.suites is new in {SUITE_FORMAT}: a {SUITE_FORMAT_1} suite has none")
        return
    suites = manifest.get("suites")
    field(root, "suites", suites, isinstance(suites, list), "a list")
    algorithms: set[str] = set()
    for k, suite in enumerate(suites):
        field(root, f"suites[{k}]", suite, isinstance(suite, dict), "an object")
        name = suite.get("algorithm")
        field(root, f"suites[{k}].algorithm", name, isinstance(name, str) and bool(NAME.fullmatch(name)),
              "an algorithm name")
        if name in algorithms:
            bad(root, f"manifest.json: suites[{k}]: a second suite of the algorithm {name!r}")
        algorithms.add(name)
        _check_suite(root, f"suites[{k}] ({name})", suite)


def _check_name(root: Path, where: str, case: Any, names: set[str]) -> None:
    field(root, where, case, isinstance(case, dict), "an object")
    name = case.get("name")
    if not isinstance(name, str) or not NAME.fullmatch(name):
        bad(root, f"{where} has no valid name (lowercase letters, digits, '.', '+', '-')")
    if name in names:
        bad(root, f"duplicate case name {name!r}")
    names.add(name)


def _check_world_fields(root: Path, where: str, case: dict) -> None:
    field(root, f"{where}.description", case.get("description"), isinstance(case.get("description"), str),
          "a string")
    path(root, f"{where}.world", case.get("world"))
    count(root, f"{where}.n", case.get("n"))
    count(root, f"{where}.m", case.get("m"))


def _check_case(root: Path, where: str, case: dict, policies: dict) -> None:
    _check_world_fields(root, where, case)
    reference: Any = case.get("reference")  # JSON, checked here
    if not isinstance(reference, dict) or set(reference) != set(policies):
        bad(root, f"manifest.json: {where}.reference must have one entry per named policy "
                  f"({', '.join(policies)})")
    for label, ref in reference.items():
        field(root, f"{where}.reference.{label}", ref, isinstance(ref, dict), "an object {cost, trace, map}")
        count(root, f"{where}.reference.{label}.cost", ref.get("cost"))
        path(root, f"{where}.reference.{label}.trace", ref.get("trace"))
        path(root, f"{where}.reference.{label}.map", ref.get("map"))


def _check_suite(root: Path, where: str, suite: dict) -> None:
    """One algorithm's suite: ``family`` and ``thesis`` strings, a non-empty list of ``cases``."""
    for key in ("family", "thesis"):
        field(root, f"{where}.{key}", suite.get(key), isinstance(suite.get(key), str), "a string")
    cases: Any = suite.get("cases")  # JSON, checked next
    field(root, f"{where}.cases", cases, isinstance(cases, list) and bool(cases), "a non-empty list")
    names: set[str] = set()
    for k, case in enumerate(cases):
        _check_name(root, f"{where}.cases[{k}]", case, names)
        _check_algorithm_case(root, f"{where}.cases[{k}] ({case['name']})", case)
    _check_ways(root, where, suite)


def _check_ways(root: Path, where: str, suite: dict) -> None:
    """Version 2.2's ``ways``: the suite's an object (name ↦ {kind, text, thesis}), each case's a list of names it
    declares; a 2.0 or 2.1 suite has neither."""
    declared: Any = suite.get("ways")  # JSON, checked here
    if declared is None:
        for k, case in enumerate(suite["cases"]):
            field(root, f"{where}.cases[{k}].ways", case.get("ways"), "ways" not in case, "absent (the suite "
                                                                                          "declares no ways)")
        return
    field(root, f"{where}.ways", declared, isinstance(declared, dict) and all(
        isinstance(v, dict) and v.get("kind") in ("phase", "outcome") and isinstance(v.get("thesis"), str)
        for v in declared.values()), "an object: way ↦ {kind: phase|outcome, text, thesis}")
    for k, case in enumerate(suite["cases"]):
        ways = case.get("ways")
        field(root, f"{where}.cases[{k}].ways", ways, isinstance(ways, list) and all(
            isinstance(w, str) and w in declared for w in ways), "a list of the ways the suite declares")


def _check_algorithm_case(root: Path, where: str, case: dict) -> None:
    """A case of an algorithm's suite: the world fields, ``options`` and ``kit`` objects, ``bound`` (a positive
    integer or null), ``expected`` (an outcome) and ``reason`` (a string where it is ``failed``), and a
    ``reference`` run: ``cost`` (>= 0), ``marker_operations`` (kind ↦ count), ``trace``, ``map`` (null when the
    run ends without one)."""
    _check_world_fields(root, where, case)
    for key in ("options", "kit"):
        field(root, f"{where}.{key}", case.get(key), isinstance(case.get(key), dict), "an object")
    if case.get("bound") is not None:
        count(root, f"{where}.bound", case.get("bound"))
    _check_provenance(root, where, case)
    expected = case.get("expected")
    field(root, f"{where}.expected", expected, expected in OUTCOMES, f"one of {', '.join(OUTCOMES)}")
    reason = case.get("reason")
    field(root, f"{where}.reason", reason, isinstance(reason, str) if expected == "failed" else reason is None,
          "a string (why the run fails)" if expected == "failed" else "null (the run ends with a map)")
    ref: Any = case.get("reference")  # JSON, checked next
    field(root, f"{where}.reference", ref, isinstance(ref, dict), "an object {cost, marker_operations, trace, map}")
    count(root, f"{where}.reference.cost", ref.get("cost"), minimum=0)
    ops = ref.get("marker_operations")
    field(root, f"{where}.reference.marker_operations", ops, isinstance(ops, dict), "an object")
    for kind, number in ops.items():
        count(root, f"{where}.reference.marker_operations.{clip(kind, 30)}", number)
    path(root, f"{where}.reference.trace", ref.get("trace"))
    if expected == "correct":
        path(root, f"{where}.reference.map", ref.get("map"))
    else:
        field(root, f"{where}.reference.map", ref.get("map"), ref.get("map") is None,
              "null (a run that fails has no map)")


def _check_provenance(root: Path, where: str, case: dict) -> None:
    """Version 2.1's ``bound_source`` (an object naming its ``source``, null exactly when ``bound`` is) and
    ``variant`` (an object whose ``follows`` is the listing or topomark's variant); a 2.0 case has neither."""
    if "bound_source" in case:
        source = case["bound_source"]
        ok = source is None if case.get("bound") is None else (
            isinstance(source, dict) and source.get("source") in ("thesis", "listing", "variant")
            and isinstance(source.get("binds"), bool) and isinstance(source.get("whose"), str))
        field(root, f"{where}.bound_source", source, ok, "null without a bound, else an object {source: thesis|"
                                                         "listing|variant, author, bounds, binds, whose, formula}")
    if "variant" in case:
        variant = case["variant"]
        field(root, f"{where}.variant", variant, isinstance(variant, dict) and variant.get("follows") in
              ("the thesis's listing", "topomark's variant"), "an object {algorithm, follows: \"the thesis's "
              "listing\" or \"topomark's variant\", changes, listing_entry}")

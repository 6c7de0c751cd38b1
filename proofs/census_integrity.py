"""What a resumed census trusts: every shard file verified before it is used (thesis §3.2, §6.1).

The census is a proof object — its exit 0 says that no two non-isomorphic
marked worlds are indistinguishable — so a resume must never give an answer
the same census run from an empty directory would not give.  The rules:

* **manifest** (``manifest.json``): its checksum must hold, its format must be
  this one, its code version must be this topomark's (:func:`code_version`),
  its parameters those asked for, and its task list the plan those parameters
  give.  Anything else stops the census with exit 2 naming the file: without
  the manifest nothing else can be checked.  A directory of the older format
  ``topomark/census-shards@1`` (no checksums) is refused the same way, with a
  message saying why: its shards cannot be verified, and the census does not
  overwrite a directory it did not write.
* **map task** (``map-T.done.json`` and ``map-T.bin``): the record's checksum,
  census (the manifest's checksum), task number and code version; its offsets
  (``S + 1`` non-decreasing integers from 0 to its record count), sizes (one
  entry per n of the census) and byte count; the data file's size and its
  BLAKE2b.  A task failing any check is mapped again, saying so on stderr.
* **reduce record** (``reduce-S.json``): checksum, census, shard number and the
  digest of the map data it summarised (:func:`inputs_digest`: every task's
  data checksum and slice); failing any, the shard is reduced again, saying so.

Every JSON file is read back as a regular file of at most :data:`MAX_RECORD_BYTES` (:func:`read_capped`),
checked on the open descriptor.  A record whose checks all hold may still have been edited and resealed: what a
resume computes again to find that is :mod:`topomark.proofs.census_recheck`.

A file that changes after it was verified (a map file shorter than its slice
when a shard is reduced, a task record that fails its check right after the
task ran) stops the census with exit 2 naming the file.

Examples
--------
>>> _check_offsets([0, 2, 2, 5], 3, 5)
>>> _check_offsets([0, -1, 5], 2, 5)
'offsets [0, -1, 5] are not 3 non-decreasing integers from 0 to 5'
>>> read_record_text('{"a": 1, "checksum": "00"}')
Traceback (most recent call last):
...
topomark.proofs.census_integrity.Damaged: its checksum does not match its content
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
from functools import lru_cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from topomark.proofs.census_shards import RECORD, checksum, digest, done_path, map_path, reduce_path
from topomark.spec.errors import InvalidInput
from topomark.spec.jsontext import open_regular_file

__all__ = ["Damaged", "MAX_RECORD_BYTES", "code_version", "package_version", "source_digest", "read_capped", "read_record",
           "read_record_text", "check_done", "check_reduce",
           "inputs_digest", "file_digest", "CODE_MODULES"]

MAX_RECORD_BYTES = 64 << 20
"""The largest manifest or record read back (64 MiB): a larger file is no record this format writes."""

CODE_MODULES = ("topomark.proofs.census", "topomark.proofs.census_map", "topomark.proofs.census_language",
                "topomark.proofs.census_kernel", "topomark.proofs.census_moore", "topomark.proofs.census_compiled",
                "topomark.proofs.blake2b_compiled",
                "topomark.proofs.census_shards", "topomark.proofs.enumerate", "topomark.proofs.world_batches",
                "topomark.proofs.orbit_kernel", "topomark.proofs.census_integrity", "topomark.spec.world",
                "topomark.spec.markerclass", "topomark.spec.robot")
"""The modules whose code decides what a map task writes: a change to any makes earlier shards another code's."""


class Damaged(Exception):
    """A shard file that fails its check; the message says which check."""


@lru_cache(maxsize=1)
def package_version() -> str:
    """The installed topomark's version (``unknown`` when it runs from a source tree that is not installed)."""
    try:
        return version("topomark")
    except PackageNotFoundError:  # pragma: no cover - the test environment installs it
        return "unknown"


def code_version() -> str:
    """``topomark VERSION, census code DIGEST``: the package version and a digest of :data:`CODE_MODULES`."""
    package = package_version()
    h = hashlib.blake2b(digest_size=8)
    for name in CODE_MODULES:
        spec = importlib.util.find_spec(name)
        assert spec is not None and spec.origin is not None, f"{name} is one of this package's modules"
        h.update(name.encode() + b"\0" + Path(spec.origin).read_bytes() + b"\0")
    return f"topomark {package}, census code {h.hexdigest()}"


def source_digest(packages: tuple[str, ...], modules: tuple[str, ...] = ()) -> str:
    """A BLAKE2b-64 digest of the source of every module in ``packages`` (recursively) and of ``modules``: what a
    resumable run writes into its manifest, so that files written by other code are never resumed."""
    h = hashlib.blake2b(digest_size=8)
    files: list[Path] = []
    for name in packages:
        spec = importlib.util.find_spec(name)
        assert spec is not None and spec.submodule_search_locations, f"{name} is one of this package's packages"
        for root in spec.submodule_search_locations:
            files += sorted(Path(root).rglob("*.py"))
    for name in modules:
        spec = importlib.util.find_spec(name)
        assert spec is not None and spec.origin, f"{name} is one of this package's modules"
        files.append(Path(spec.origin))
    for path in files:
        h.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def file_digest(path: Path) -> str:
    """The BLAKE2b-256 of a file's content, read in 1 MiB blocks."""
    h = hashlib.blake2b(digest_size=32)
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def read_record_text(text: str) -> dict[str, Any]:
    """A record from its JSON text, if it is an object whose checksum holds; else :class:`Damaged`."""
    try:
        record = json.loads(text)
    except (ValueError, RecursionError):  # RecursionError: nested too deeply to be a record
        raise Damaged("it is not JSON") from None
    if not isinstance(record, dict) or not isinstance(record.get("checksum"), str):
        raise Damaged("it is not a checksummed record")
    if record["checksum"] != checksum(record):
        raise Damaged("its checksum does not match its content")
    return record


def read_capped(path: Path, cap: int = MAX_RECORD_BYTES) -> bytes:
    """The bytes of the regular file ``path`` if it holds at most ``cap``; a file that is not a regular file (a
    FIFO, a device, a directory) is InvalidInput (exit 2), a larger or unreadable one :class:`Damaged`."""
    try:
        fh = open_regular_file(path, max_bytes=None)  # opened without blocking, checked on the descriptor
    except InvalidInput as e:
        if os.path.lexists(path) and not path.is_file():
            raise
        raise Damaged(f"it cannot be read ({e})") from None
    try:
        with fh:
            data = fh.read(cap + 1)
    except OSError as e:
        raise Damaged(f"it cannot be read ({e.strerror or e})") from None
    if len(data) > cap:
        raise Damaged(f"it holds more than {cap:,} bytes, more than any record of the format")
    return data


def read_record(path: Path) -> dict[str, Any]:
    """The record in ``path`` (see :func:`read_record_text`, :func:`read_capped`); an unreadable or oversized file
    is :class:`Damaged`."""
    try:
        text = read_capped(path).decode("utf-8")
    except UnicodeDecodeError:
        raise Damaged("it is not UTF-8 text") from None
    return read_record_text(text)


def _is_count(x: Any) -> bool:
    return type(x) is int and x >= 0


def _check_offsets(offsets: Any, shards: int, count: Any) -> str | None:
    good = (isinstance(offsets, list) and len(offsets) == shards + 1 and all(_is_count(x) for x in offsets)
            and _is_count(count) and offsets[0] == 0 and offsets[-1] == count
            and all(a <= b for a, b in zip(offsets, offsets[1:])))
    return None if good else f"offsets {str(offsets)[:80]} are not {shards + 1} non-decreasing integers from 0 to {count}"


def _expect(record: dict[str, Any], key: str, value: Any) -> None:
    if record.get(key) != value:
        raise Damaged(f"its {key} is {str(record.get(key))[:80]!r}, not {str(value)[:80]!r}")


def check_done(root: Path, task: int, census: str, manifest: dict[str, Any]) -> dict[str, Any]:
    """Map task ``task``'s record, if it and its data file pass every check; else :class:`Damaged`."""
    record = read_record(done_path(root, task))
    _expect(record, "census", census)
    _expect(record, "task", task)
    _expect(record, "code", code_version())
    reason = _check_offsets(record.get("offsets"), manifest["shards"], record.get("records"))
    if reason:
        raise Damaged(reason)
    if record.get("bytes") != record["records"] * RECORD.itemsize:
        raise Damaged(f"its byte count {record.get('bytes')!r} is not {record['records']} records")
    p = manifest["params"]
    ns = {str(unit[0]) for unit, _ in manifest["tasks"][task]}
    sizes = record.get("sizes")
    if (not isinstance(sizes, dict) or set(sizes) != ns
            or not all(isinstance(v, list) and len(v) == 2 and all(map(_is_count, v)) for v in sizes.values())):
        raise Damaged(f"its sizes {str(sizes)[:80]} are not [worlds, placements] for n in {sorted(ns)}")
    if not all(p["min_n"] <= int(n) <= p["max_vertices"] for n in sizes):
        raise Damaged("its sizes name an n outside the census")
    data = map_path(root, task)
    try:
        size = data.stat().st_size
        if size != record["bytes"]:
            raise Damaged(f"{data.name} holds {size} bytes, not the {record['bytes']} its record names")
        if file_digest(data) != record.get("data"):
            raise Damaged(f"{data.name} does not match the checksum its record names")
    except OSError as e:
        raise Damaged(f"{data.name} cannot be read ({e.strerror or e})") from None
    return record


def inputs_digest(done: list[dict[str, Any]], shard: int) -> str:
    """The digest of what shard ``shard`` summarises: every task's data checksum and its slice of the shard."""
    return digest(json.dumps([[d["data"], d["offsets"][shard], d["offsets"][shard + 1]] for d in done]).encode())


def check_reduce(root: Path, shard: int, census: str, inputs: str, sizes: int) -> dict[str, Any]:
    """Shard ``shard``'s summary, if it passes every check; else :class:`Damaged`."""
    record = read_record(reduce_path(root, shard))
    _expect(record, "census", census)
    _expect(record, "shard", shard)
    _expect(record, "inputs", inputs)
    for key in ("languages", "languages_upto", "ambiguous_upto"):
        v = record.get(key)
        if not (isinstance(v, list) and len(v) == sizes and all(map(_is_count, v))):
            raise Damaged(f"its {key} is not {sizes} counts")
    pair = record.get("pair")
    if pair is not None and not (isinstance(pair, list) and len(pair) == 2 and all(
            isinstance(m, list) and len(m) == 5 and all(map(_is_count, m)) for m in pair)):
        raise Damaged("its pair is not two members of five counts")
    return record

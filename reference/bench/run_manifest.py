"""The run store's manifest ``DIR/runs.json`` and its row checksums: what makes ``runs.csv`` verifiable.

A bench directory's ``runs.csv`` (:mod:`~topomark.reference.bench.run_store`)
is trusted only after it is verified, like the census's shard directory.
Next to it, ``runs.json`` (format :data:`FORMAT`) records

* ``store`` — a random identifier made when the store is created;
* ``topomark`` — the version of topomark that last wrote the store;
* ``sweeps`` — the parameters of every distinct sweep that wrote to it
  (experiment, graphs, sizes, heavy rows, checked or not, the number of runs
  planned, and the topomark version), oldest first, at most :data:`MAX_SWEEPS`;
* ``rows`` — how many rows the file held when the last sweep finished (a
  file with fewer lost a row).

Every row carries a ``checksum`` column: the first 16 hex digits of the
SHA-256 of the store identifier and the row's other values
(:func:`row_checksum`).  An edited value, a row cut short and then completed
by hand, or a row copied from another directory's ``runs.csv`` (another
store identifier) no longer matches.

Caps: ``runs.json`` is at most :data:`MAX_MANIFEST_BYTES` bytes.

>>> row = {"experiment": "lattice", "size": "9", "seed": "0", "cost": "12"}
>>> row_checksum("0" * 32, row) == row_checksum("0" * 32, dict(row))
True
>>> row_checksum("0" * 32, row) == row_checksum("0" * 32, {**row, "cost": "13"})
False
>>> row_checksum("0" * 32, row) == row_checksum("1" * 32, row)
False
"""

from __future__ import annotations

import hashlib
import json
import re
import secrets
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.jsontext import parse_json, read_text_file

from topomark.proofs.census_integrity import package_version

__all__ = ["FORMAT", "MANIFEST_NAME", "MAX_MANIFEST_BYTES", "MAX_SWEEPS", "Manifest", "code_version",
           "read_manifest", "row_checksum"]

FORMAT = "topomark/bench-runs@1"
MANIFEST_NAME = "runs.json"
MAX_MANIFEST_BYTES = 1 << 20
MAX_SWEEPS = 1000
_STORE = re.compile(r"[0-9a-f]{32}")


def code_version() -> str:
    """The installed topomark's version (``unknown`` when it runs from a source tree that is not installed)."""
    return package_version()


def row_checksum(store: str, row: dict, fields: Iterable[str] | None = None) -> str:
    """16 hex digits of SHA-256 over ``store`` and the row's values (``fields``, default every key but
    ``checksum``, in sorted order), each as the text ``runs.csv`` holds (a missing value is empty)."""
    names = sorted(k for k in (row if fields is None else fields) if k != "checksum")
    text = "\x1e".join([store, *(f"{k}\x1f{'' if row.get(k) is None else row[k]}" for k in names)])
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


@dataclass
class Manifest:
    """What ``runs.json`` says (see the module docstring)."""

    store: str = field(default_factory=lambda: secrets.token_hex(16))
    topomark: str = field(default_factory=code_version)
    sweeps: list[dict] = field(default_factory=list)
    rows: int = 0

    def add_sweep(self, parameters: dict[str, Any]) -> None:
        """Record a sweep's parameters (once: a resumed sweep with the same parameters is not listed again)."""
        self.topomark = code_version()
        entry = {**parameters, "topomark": self.topomark}
        if entry not in self.sweeps:
            self.sweeps = (self.sweeps + [entry])[-MAX_SWEEPS:]

    def to_text(self) -> str:
        return json.dumps({"format": FORMAT, "store": self.store, "topomark": self.topomark, "rows": self.rows,
                           "sweeps": self.sweeps}, indent=1, sort_keys=True) + "\n"


def read_manifest(directory: str | Path) -> Manifest | None:
    """``directory/runs.json`` verified (None if there is none); anything malformed is InvalidInput naming it."""
    path = Path(directory) / MANIFEST_NAME
    if not path.exists() and not path.is_symlink():
        return None
    obj = parse_json(read_text_file(path, max_bytes=MAX_MANIFEST_BYTES), str(path))

    def bad(what: str) -> InvalidInput:
        return InvalidInput(f"{path}: not a topomark bench run-store manifest: {what}")

    if not isinstance(obj, dict) or obj.get("format") != FORMAT:
        found = clip(str(obj.get("format")), 60) if isinstance(obj, dict) else "not a JSON object"
        raise bad(f"format {found} (expected {FORMAT})")
    store, version, sweeps, rows = obj.get("store"), obj.get("topomark"), obj.get("sweeps"), obj.get("rows")
    if not isinstance(store, str) or not _STORE.fullmatch(store):
        raise bad("store is not 32 lowercase hex digits")
    if not isinstance(version, str) or not 0 < len(version) <= 64:
        raise bad("topomark is not a version string")
    if not isinstance(sweeps, list) or len(sweeps) > MAX_SWEEPS or not all(isinstance(s, dict) for s in sweeps):
        raise bad(f"sweeps is not a list of at most {MAX_SWEEPS} objects")
    if not isinstance(rows, int) or isinstance(rows, bool) or rows < 0:
        raise bad("rows is not a non-negative integer")
    return Manifest(store, version, sweeps, rows)

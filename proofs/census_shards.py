"""The census's shards on disk and the reduce over one shard (thesis §3.2, §3.3, §3.7, §6.1).

The census (:mod:`topomark.proofs.census`) groups placements by language
digest.  Run as map and reduce (:mod:`topomark.proofs.census_run`), every map
task writes its (digest, member) records split by digest into ``S`` shards,
and every shard is reduced on its own, so memory is set by the shard size,
not by the number of worlds.

On-disk format (``topomark/census-shards@2``), all in one directory::

    manifest.json          the census parameters, the code version, S and the task list (written once, atomically)
    map-T.bin              records of map task T (little-endian, RECORD dtype), ordered by shard
    map-T.done.json        task T finished: {"sizes": {n: [worlds, placements]}, "offsets": [S + 1 ints],
                           "records", "bytes", "data": BLAKE2b of map-T.bin, "census", "task", "code"}
                           (shard S's records are records offsets[S] .. offsets[S+1]-1); written last
    reduce-S.json          the summary of shard S (see :func:`summary`), with "census", "shard" and
                           "inputs" (a digest of the map data it summarised)

Every JSON file is a *record* carrying ``"checksum"``, the BLAKE2b of the
rest of it (:func:`seal`); ``"census"`` is the manifest's checksum, so a file
of another census is recognised.  What a resume checks before it trusts a
file is :mod:`topomark.proofs.census_integrity`.

One data file per task (not per task and shard) keeps the file count at 2 per
task when S is in the hundreds.  Every file is written to ``NAME.tmp-PID`` and
renamed, so a file that exists is complete; a task without its ``done`` file
is redone from scratch (its data file is overwritten) and a shard without its
``reduce`` file is reduced again.  That is what makes a killed census resumable.

A record is one member of a language class: ``d0, d1`` the 128-bit language
digest, ``mask`` a bit per world size n seen in the class, ``n, m`` the
world's size, ``gi`` the graph's index in
:func:`topomark.proofs.enumerate.connected_graphs` (n, D), ``ri`` the rank of
the world's rotation system in the product order of
:func:`topomark.proofs.enumerate.rotation_systems` (see
:mod:`topomark.proofs.census_map`), ``k``
the placement index (:meth:`MarkerClass.placements` order) and ``i0, i1`` a
128-bit key equal for two members iff their marked worlds are
extended-isomorphic (markers preserved, start ignored).  Members are ordered
by ``(n, m, gi, ri, k)`` — the order of today's in-memory census, where the
enumeration index grows with ``(gi, ri)`` at fixed n.

:func:`combine` keeps, per digest, the OR of the masks and the two smallest
members with different iso keys (the rule of ``census._insert``); it is
associative, so map tasks combine their own records before writing and the
reduce combines the shard.

Examples
--------
>>> recs = records([(b"a" * 16, 3, (4, 6, 0, 2, 5), b"x" * 16), (b"a" * 16, 3, (4, 6, 0, 1, 0), b"x" * 16),
...                 (b"a" * 16, 4, (5, 7, 1, 0, 0), b"y" * 16)])
>>> [(int(r["n"]), int(r["ri"])) for r in combine(recs)]
[(4, 1), (5, 0)]
>>> summary(combine(recs), 3, 5)["ambiguous_upto"]
[0, 0, 1]
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path
from typing import Any, Iterable

import numpy as np

from topomark.spec.errors import InvalidInput

__all__ = ["FORMAT", "RECORD", "records", "combine", "summary", "merge_summaries", "shard_of", "write_atomic",
           "write_json", "read_json", "map_path", "done_path", "reduce_path", "read_shard", "checksum", "seal",
           "digest"]

FORMAT = "topomark/census-shards@2"
RECORD = np.dtype([("d0", "<u8"), ("d1", "<u8"), ("mask", "<u4"), ("n", "u1"), ("m", "u1"), ("gi", "<u4"),
                   ("ri", "<u4"), ("k", "<u4"), ("i0", "<u8"), ("i1", "<u8")])
_MEMBER = ("n", "m", "gi", "ri", "k")


def records(rows: Iterable[tuple[bytes, int, tuple[int, int, int, int, int], bytes]]) -> np.ndarray:
    """Records from ``(digest, mask, (n, m, gi, ri, k), iso)`` rows (16-byte digest and iso)."""
    rows = list(rows)
    out = np.zeros(len(rows), RECORD)
    if rows:
        dig = np.frombuffer(b"".join(r[0] for r in rows), "<u8").reshape(-1, 2)
        iso = np.frombuffer(b"".join(r[3] for r in rows), "<u8").reshape(-1, 2)
        out["d0"], out["d1"], out["i0"], out["i1"] = dig[:, 0], dig[:, 1], iso[:, 0], iso[:, 1]
        out["mask"] = [r[1] for r in rows]
        members = np.array([r[2] for r in rows], dtype=np.int64)
        for j, name in enumerate(_MEMBER):
            out[name] = members[:, j]
    return out


def shard_of(recs: np.ndarray, shards: int) -> np.ndarray:
    """The shard of every record: the digest's low word modulo ``shards``."""
    return (recs["d0"] % np.uint64(shards)).astype(np.int64)


def _groups(recs: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Sort by digest then member; (sorted records, group starts, group id of every record)."""
    order = np.lexsort([recs[f] for f in reversed(("d0", "d1") + _MEMBER)])
    recs = recs[order]
    new = np.ones(len(recs), bool)
    new[1:] = (recs["d0"][1:] != recs["d0"][:-1]) | (recs["d1"][1:] != recs["d1"][:-1])
    starts = np.flatnonzero(new)
    return recs, starts, np.cumsum(new) - 1


def _best_two(recs: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(sorted records, group starts, OR of masks per group, index of the second member or -1)."""
    recs, starts, gid = _groups(recs)
    if not len(recs):
        return recs, starts, np.zeros(0, np.uint32), np.zeros(0, np.int64)
    masks = np.bitwise_or.reduceat(recs["mask"], starts)
    first = starts[gid]
    other = (recs["i0"] != recs["i0"][first]) | (recs["i1"] != recs["i1"][first])
    big = len(recs)
    second = np.minimum.reduceat(np.where(other, np.arange(big), big), starts)
    return recs, starts, masks, np.where(second < big, second, -1)


def combine(recs: np.ndarray) -> np.ndarray:
    """Per digest: the smallest member (carrying the OR of the masks) and the smallest with another iso key."""
    recs, starts, masks, second = _best_two(recs)
    firsts = recs[starts]
    firsts["mask"] = masks
    seconds = recs[second[second >= 0]]
    seconds["mask"] = 0
    return np.concatenate([firsts, seconds])


def _member(rec) -> list[int]:
    return [int(rec[f]) for f in _MEMBER]


def _pair_key(pair: list[list[int]]) -> tuple:
    """The order of ``census._smallest``: larger member's (n, m), smaller's (n, m), then indices."""
    a, b = pair
    return (b[0], b[1], a[0], a[1], a[2:], b[2:])


def summary(recs: np.ndarray, min_n: int, max_n: int, all_pairs: bool = False) -> dict[str, Any]:
    """Counts per n (``min_n..max_n``) of a set of records, and its smallest ambiguous pair.

    ``languages[j]``: digests seen on worlds of n = min_n + j; ``languages_upto``:
    on worlds of ≤ n; ``ambiguous_upto``: digests whose two smallest
    non-isomorphic members both have ≤ n vertices; ``pair``: the two members
    of the smallest ambiguous digest (or None); with ``all_pairs`` every one.
    """
    recs, starts, masks, second = _best_two(recs)
    ns = range(min_n, max_n + 1)
    amb = second >= 0
    second_n = recs["n"][second[amb]]
    out: dict[str, Any] = {
        "languages": [int(np.count_nonzero(masks >> np.uint32(n) & 1)) for n in ns],
        "languages_upto": [int(np.count_nonzero(masks & np.uint32((1 << (n + 1)) - 1))) for n in ns],
        "ambiguous_upto": [int(np.count_nonzero(second_n <= n)) for n in ns]}
    firsts, seconds = recs[starts[amb]], recs[second[amb]]
    out["pair"] = None
    if len(firsts):  # the least by _pair_key; np.lexsort's last key is the primary one
        keys = [seconds[f] for f in ("k", "ri", "gi")] + [firsts[f] for f in ("k", "ri", "gi", "m", "n")]
        best = np.lexsort(keys + [seconds["m"], seconds["n"]])[0]
        out["pair"] = [_member(firsts[best]), _member(seconds[best])]
    if all_pairs:
        out["pairs"] = [[_member(a), _member(b)] for a, b in zip(firsts, seconds)]
    return out


def merge_summaries(parts: Iterable[dict[str, Any]]) -> dict[str, Any]:
    """Sum the counts of shard summaries (digests are disjoint across shards); keep the smallest pair."""
    total: dict[str, Any] = {"pair": None, "pairs": []}
    for part in parts:
        for key in ("languages", "languages_upto", "ambiguous_upto"):
            total[key] = [a + b for a, b in zip(total[key], part[key])] if key in total else list(part[key])
        if part["pair"] is not None and (total["pair"] is None or _pair_key(part["pair"]) < _pair_key(total["pair"])):
            total["pair"] = part["pair"]
        total["pairs"].extend(part.get("pairs", []))
    return total


# -- files ------------------------------------------------------------------------------
def map_path(root: Path, task: int) -> Path:
    return root / f"map-{task}.bin"


def done_path(root: Path, task: int) -> Path:
    return root / f"map-{task}.done.json"


def reduce_path(root: Path, shard: int) -> Path:
    return root / f"reduce-{shard}.json"


def digest(data: bytes) -> str:
    """The BLAKE2b-256 of ``data``, in hex: the checksum of every file of the format.

    >>> digest(b"")[:16]
    '0e5751c026e543b2'
    """
    return hashlib.blake2b(data, digest_size=32).hexdigest()


def checksum(record: dict[str, Any]) -> str:
    """The digest of a record's canonical JSON, leaving out its own ``"checksum"``."""
    rest = {k: v for k, v in record.items() if k != "checksum"}
    return digest(json.dumps(rest, sort_keys=True, separators=(",", ":")).encode())


def seal(record: dict[str, Any]) -> dict[str, Any]:
    """``record`` with its ``"checksum"``.

    >>> r = seal({"a": 1}); r["checksum"] == checksum({"a": 1}) and checksum(r) == r["checksum"]
    True
    """
    return {**record, "checksum": checksum(record)}


def write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to a temporary name, then rename: a file that exists is complete."""
    tmp = path.with_name(f"{path.name}.tmp-{os.getpid()}")
    try:
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError as e:
        raise InvalidInput(f"cannot write {path}: {e.strerror or e}") from None


def write_json(path: Path, data: Any) -> None:
    write_atomic(path, json.dumps(data, sort_keys=True).encode())


def read_json(path: Path) -> Any:
    return json.loads(path.read_text(encoding="utf-8"))


def read_shard(root: Path, slices: list[tuple[int, int, int]]) -> np.ndarray:
    """One shard's records: ``(task, first record, count)`` per map task (all tasks done).

    ``np.fromfile`` returns a short read without complaint, so the file's
    size is checked first: a file too short for its slice is refused, naming it.
    """
    parts = []
    for t, first, count in slices:
        if count:
            path = map_path(root, t)
            size = path.stat().st_size if path.is_file() else -1
            if size < (first + count) * RECORD.itemsize:
                raise InvalidInput(f"{path}: holds {max(size, 0)} bytes, too few for records {first}..{first + count - 1}"
                                   f" (the file changed after it was verified)")
            parts.append(np.fromfile(path, RECORD, count=count, offset=first * RECORD.itemsize))
    return np.concatenate(parts) if parts else np.zeros(0, RECORD)

"""The census as map and reduce over shards on disk (thesis §3.2, §3.3, §3.7, §6.1).

:func:`sharded_census` gives the same :class:`~topomark.proofs.census.CensusResult`
as the in-memory :func:`~topomark.proofs.census.census` (``tests/test_census_shards.py``
compares them), but its memory is set by the shard size, not by the number of
worlds, and a killed run resumes:

1. plan the map tasks (:func:`topomark.proofs.census_map.plan`) and write the
   manifest — or, if the directory already holds one, verify it describes the
   same census, written by the same code, and keep its plan;
2. run every map task without a ``done`` file, or whose files fail their
   checks (:func:`~topomark.proofs.census_map.run_map`;
   :mod:`~topomark.proofs.census_integrity` says what is checked);
   (every file under a shard file's name must be a regular file: a FIFO or a
   device is exit 2 naming it, checked once before anything is read);
3. reduce every shard without a ``reduce`` file, or whose file fails its
   checks (:func:`reduce_shard`);
4. merge the shard summaries; on a resume, compute again a seeded sample of
   the kept records and those the verdict rests on, and refuse the directory
   (exit 2 naming the file) if one differs (:mod:`~topomark.proofs.census_recheck`);
5. rebuild the smallest counterexample from its record and re-check it with
   bisimulation and ``find_isomorphism``.

Tasks run on an executor (:mod:`topomark.proofs.census_exec`): inline,
local processes (``jobs``) or a Dask cluster (``scheduler``).  The on-disk
format is described in :mod:`topomark.proofs.census_shards`.

Examples
--------
>>> import tempfile
>>> with tempfile.TemporaryDirectory() as d:
...     r = sharded_census("none", 4, 3, d)
>>> [(row.n, row.worlds, row.languages_upto, row.ambiguous_upto) for row in r.rows]
[(2, 1, 1, 0), (3, 2, 4, 0), (4, 9, 28, 2)]
"""

from __future__ import annotations

import json
import os
import secrets
import stat
import time
from pathlib import Path
from typing import Any, Callable

from topomark.proofs.census import CensusResult, SizeRow, recheck_pair, stderr_progress
from topomark.proofs.census_compiled import resolve_engine
from topomark.proofs.census_exec import Executor, Progress, executor
from topomark.proofs.census_map import plan, run_map, world_at
from topomark.proofs.census_recheck import recheck_resumed
from topomark.proofs.census_integrity import (Damaged, check_done, check_reduce, code_version, inputs_digest,
                                              read_capped, read_record_text)
from topomark.proofs.census_shards import (FORMAT, done_path, merge_summaries, read_shard, reduce_path, seal, summary,
                                           write_json)
from topomark.spec.errors import InvalidInput, clip
from topomark.spec.markerclass import marker_class

__all__ = ["sharded_census", "reduce_shard", "default_shards", "prepare"]

PLACEMENTS_PER_WORLD = 100  # a generous average, to size shards
RECORDS_PER_SHARD = 2_000_000  # ~100 MB of records per shard at most


def default_shards(estimated_worlds: int) -> int:
    """A power of two keeping a shard under RECORDS_PER_SHARD records."""
    need = estimated_worlds * PLACEMENTS_PER_WORLD / RECORDS_PER_SHARD
    shards = 1
    while shards < need and shards < 4096:
        shards *= 2
    return shards


def _regular_only(root: Path) -> None:
    """Exit 2 naming the first entry of the shard directory under a census file's name that is not a regular
    file (a FIFO would block the reader, a link to a device would never end): shard files are regular files."""
    for entry in sorted(root.iterdir()):
        if entry.name == "manifest.json" or entry.name.startswith(("map-", "reduce-")):
            try:
                mode = os.stat(entry).st_mode
            except OSError as e:
                raise InvalidInput(f"{entry}: cannot be read ({e.strerror or e})") from None
            if not stat.S_ISREG(mode):
                raise InvalidInput(f"{entry}: not a regular file; a census reads only regular shard files: remove it")


def _writable(root: Path) -> None:
    try:
        root.mkdir(parents=True, exist_ok=True)
        probe = root / f".probe-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as e:
        raise InvalidInput(f"shard directory {str(root)!r} is not writable: {e.strerror or e}") from None


def _read_manifest(path: Path, params: dict[str, Any]) -> dict[str, Any]:
    """The manifest in ``path`` if every check of :mod:`~topomark.proofs.census_integrity` holds; else exit 2."""
    try:
        text = read_capped(path).decode("utf-8")
        raw = json.loads(text)
    except (Damaged, UnicodeDecodeError, ValueError, RecursionError) as e:
        raise InvalidInput(f"{path}: not a census manifest ({clip(str(e), 120)})") from None
    if isinstance(raw, dict) and raw.get("format") == "topomark/census-shards@1":
        raise InvalidInput(f"{path}: written by an older topomark in format topomark/census-shards@1, whose shards "
                           f"carry no checksums and cannot be verified; remove {path.parent} or choose an empty "
                           f"directory (the census starts over)")
    if not isinstance(raw, dict) or raw.get("format") != FORMAT:
        raise InvalidInput(f"{path}: not a {FORMAT} manifest")
    try:
        manifest = read_record_text(text)
    except Damaged as e:
        raise InvalidInput(f"{path}: damaged: {e}; remove {path.parent} or choose an empty directory") from None
    if manifest.get("code") != code_version():
        raise InvalidInput(f"{path}: written by {manifest.get('code')!r}, not by this {code_version()!r}; its shards "
                           f"may differ from what this code writes: remove {path.parent} or choose an empty directory")
    if manifest.get("params") != params:
        raise InvalidInput(f"{path.parent} holds the shards of another census ({manifest.get('params')}); "
                           f"use an empty directory or the same options")
    tw = manifest.get("task_worlds")
    if type(tw) is not int or tw < 1 or type(manifest.get("shards")) is not int or not 1 <= manifest["shards"] <= 4096 \
            or manifest.get("tasks") != _plan(params, tw):
        raise InvalidInput(f"{path}: damaged: its task list or shard count is not the plan of its parameters")
    return manifest


def _plan(params: dict[str, Any], task_worlds: int) -> list:
    tasks = plan(params["max_vertices"], params["max_degree"], params["min_vertices"], task_worlds)
    return [[[list(unit), est] for unit, est in task] for task in tasks]


def prepare(root: Path, params: dict[str, Any], task_worlds: int, shards: int | None) -> dict[str, Any]:
    """The manifest of ``root``: read and verified (resume) if present, else planned and written."""
    _writable(root)
    _regular_only(root)
    path = root / "manifest.json"
    if path.exists():
        return _read_manifest(path, params)
    tasks = _plan(params, task_worlds)
    estimated = sum(est for task in tasks for _, est in task)
    manifest = seal({"format": FORMAT, "code": code_version(), "params": params, "task_worlds": task_worlds,
                     "shards": shards or default_shards(estimated), "estimated_worlds": estimated, "tasks": tasks})
    write_json(path, manifest)
    return manifest


def reduce_shard(root: str, shard: int, slices: list[tuple[int, int, int]], min_n: int, max_n: int,
                 all_pairs: bool, census: str = "", inputs: str = "") -> dict[str, Any]:
    """Reduce one shard from its ``(task, first record, count)`` slices: write and return its summary
    (a record of census ``census`` over map data of digest ``inputs``)."""
    result = seal({**summary(read_shard(Path(root), slices), min_n, max_n, all_pairs), "census": census,
                   "shard": shard, "inputs": inputs})
    write_json(reduce_path(Path(root), shard), result)
    return result


def _verified_done(root: Path, manifest: dict[str, Any], note: Callable[[str], None]) -> dict[int, dict[str, Any]]:
    """The map tasks whose records and data pass every check; a damaged one is reported and left to be redone."""
    good = {}
    for t in range(len(manifest["tasks"])):
        if done_path(root, t).exists():
            try:
                good[t] = check_done(root, t, manifest["checksum"], manifest)
            except Damaged as e:
                note(f"census: {done_path(root, t)}: {e}; mapping task {t} again")
    return good


def _map_phase(ex: Executor, root: Path, manifest: dict[str, Any], progress: Progress,
               note: Callable[[str], None], engine: str) -> tuple[list[dict[str, Any]], set[int]]:
    """Every map task's record, and the tasks kept from an earlier run (not computed now)."""
    p = manifest["params"]
    done = _verified_done(root, manifest, note)
    kept = set(done)
    todo = []
    for t, task in enumerate(manifest["tasks"]):
        est = sum(e for _, e in task)
        if t in done:
            progress.skip(est, sum(w for w, _ in done[t]["sizes"].values()))
        else:
            todo.append((t, est, [tuple(u) for u, _ in task]))
    calls = [(run_map, (str(root), t, p["marker"], p["max_degree"], units, manifest["shards"], manifest["checksum"],
                        engine)) for t, _, units in todo]
    for i, result in ex.run(calls):
        t = todo[i][0]
        try:  # what a worker wrote, checked as a resume would check it
            done[t] = check_done(root, t, manifest["checksum"], manifest)
        except Damaged as e:
            raise InvalidInput(f"{done_path(root, t)}: {e}, just after task {t} ran (another process or another "
                               f"topomark version wrote it)") from None
        progress.done(todo[i][1], sum(w for w, _ in result["sizes"].values()))
    return [done[t] for t in range(len(manifest["tasks"]))], kept


def _reduce_phase(ex: Executor, root: Path, manifest: dict[str, Any], done: list[dict[str, Any]],
                  all_pairs: bool, note: Callable[[str], None]) -> tuple[list[dict[str, Any]], set[int]]:
    """Every shard's summary, and the shards kept from an earlier run (not reduced now)."""
    p = manifest["params"]
    sizes = p["max_vertices"] - p["min_n"] + 1
    out: dict[int, dict[str, Any]] = {}
    calls, which = [], []
    for s in range(manifest["shards"]):
        inputs = inputs_digest(done, s)
        if reduce_path(root, s).exists():
            try:
                part = check_reduce(root, s, manifest["checksum"], inputs, sizes)
                if not all_pairs or "pairs" in part:
                    out[s] = part
                    continue
            except Damaged as e:
                note(f"census: {reduce_path(root, s)}: {e}; reducing shard {s} again")
        slices = [(t, d["offsets"][s], d["offsets"][s + 1] - d["offsets"][s]) for t, d in enumerate(done)]
        calls.append((reduce_shard, (str(root), s, slices, p["min_n"], p["max_vertices"], all_pairs,
                                     manifest["checksum"], inputs)))
        which.append(s)
    kept = set(out)
    for i, result in ex.run(calls):
        out[which[i]] = result
    return [out[s] for s in sorted(out)], kept


def _rows(manifest: dict[str, Any], total: dict[str, Any], done: list[dict[str, Any]]) -> tuple[SizeRow, ...]:
    p = manifest["params"]
    sizes: dict[int, list[int]] = {}
    for d in done:
        for n, (w, pl) in d["sizes"].items():
            tally = sizes.setdefault(int(n), [0, 0])
            tally[0] += w
            tally[1] += pl
    rows = []
    for j, n in enumerate(range(p["min_n"], p["max_vertices"] + 1)):
        worlds, placements = sizes.get(n, [0, 0])
        rows.append(SizeRow(n, worlds, placements, total["languages"][j], total["languages_upto"][j],
                            total["ambiguous_upto"][j]))
    return tuple(rows)


def sharded_census(class_name: str, max_vertices: int, max_degree: int, root: str | os.PathLike,
                   jobs: int = 1, scheduler: str | None = None, min_vertices: int = 2,
                   progress: Callable[[str], None] | None = None, task_worlds: int = 2000,
                   shards: int | None = None, verify_all: bool = False,
                   note: Callable[[str], None] = stderr_progress, recheck_seed: int | None = None,
                   engine: str = "auto") -> CensusResult:
    """The census of ``class_name`` as map and reduce over shards in directory ``root`` (resumed if present).

    ``jobs`` local worker processes (1: inline), or ``scheduler``: a Dask
    scheduler address or ``"local"``.  ``verify_all`` re-checks the two
    smallest members of every ambiguous class, as :func:`census` does.
    A resume verifies every file before it trusts it
    (:mod:`~topomark.proofs.census_integrity`); a damaged task or shard is
    computed again and reported through ``note`` (standard error); a sample of the kept records, and those the
    verdict rests on, are computed again and compared (:mod:`~topomark.proofs.census_recheck`, seeded by
    ``recheck_seed``, drawn afresh if None).
    ``task_worlds`` and ``shards`` apply to a new directory; a resume keeps
    the manifest's.  ``engine`` (``reference``, ``compiled`` or ``auto``,
    :func:`~topomark.proofs.census_compiled.resolve_engine`) computes the map
    tasks; the engines write the same records, so it is not a census
    parameter: a census resumes on either.
    """
    marker_class(class_name)
    engine = resolve_engine(engine, class_name, note)
    t0 = time.perf_counter()
    min_n = max(min_vertices, 2)
    params = {"marker": class_name, "max_vertices": max_vertices, "max_degree": max_degree,
              "min_vertices": min_vertices, "min_n": min_n}
    path = Path(root).absolute()  # workers elsewhere (a Dask cluster) may run in another directory
    manifest = prepare(path, params, task_worlds, shards)
    with executor(jobs, scheduler, tasks=max(len(manifest["tasks"]), manifest["shards"])) as ex:
        bar = Progress(manifest["estimated_worlds"], progress)
        done, kept_tasks = _map_phase(ex, path, manifest, bar, note, engine)
        bar.finish()
        parts, kept_shards = _reduce_phase(ex, path, manifest, done, verify_all, note)
    total = merge_summaries(parts)
    seed = secrets.randbits(32) if recheck_seed is None else recheck_seed
    recheck_resumed(path, manifest, done, kept_tasks, parts, kept_shards, total, seed, note)
    rows = _rows(manifest, total, done)

    def rebuild(member: list[int]):
        n, _, gi, ri, k = member
        return world_at(n, max_degree, gi, ri), k

    if verify_all:
        for pair in total["pairs"]:
            recheck_pair([rebuild(m) for m in pair], class_name)
    pair = None if total["pair"] is None else recheck_pair([rebuild(m) for m in total["pair"]], class_name)
    return CensusResult(class_name, max_vertices, max_degree, rows, pair, time.perf_counter() - t0)

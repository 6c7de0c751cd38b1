"""What a resumed census computes again before it answers: kept records re-checked by recomputation (§3.2, §6.1).

A record's checksum (:func:`topomark.proofs.census_shards.seal`) finds damage, not an edit: anyone can change a
kept ``map-T.done.json`` and its ``map-T.bin``, or a ``reduce-S.json``, and seal it again, and every check of
:mod:`topomark.proofs.census_integrity` then holds.  So a resume trusts no kept record by its seal alone; the rule
is:

* **the kept records the census's verdict rests on are computed again**: the shard whose summary reports the
  counterexample the census answers (its smallest ambiguous pair) and the map tasks holding its two members.  The
  pair itself is also re-checked independently, by bisimulation and ``find_isomorphism``
  (:func:`topomark.proofs.census.recheck_pair`), and with ``verify_all`` so is every ambiguous class's pair;
* **so is a seeded sample of the others**: :data:`RECHECK_FRACTION` of the kept map tasks and of the kept shards,
  at least one of each (:func:`recheck_sample`).  The seed is drawn afresh at every resume (and reported through
  ``note`` with what is re-checked, so a run can be repeated): a record edited to hide a counterexample cannot
  know whether it will be drawn;
* a kept record that its recomputation does not reproduce (data, offsets, sizes; or a shard's counts and pair)
  stops the census with **exit 2 naming the task or shard and its file**.  The manifest names this topomark's
  code, which computes the same record every time from the same task, so a record it does not reproduce was
  changed after it was written: the directory is bad input (as a resealed worst-case task file is), not
  topomark's own failure.  The census does not repair it: other records may have been changed too; remove the
  directory (or the file named) and run again.

What was computed in the same run is not re-checked: it was just computed.  A resume so costs the unfinished
work plus about 1 % (and at least one task and one shard) of what it kept.

Examples
--------
>>> recheck_sample(range(10), 7) == recheck_sample(range(10), 7), len(recheck_sample(range(1000), 1))
(True, 10)
>>> recheck_sample([], 3)
[]
"""

from __future__ import annotations

import math
import random
from pathlib import Path
from typing import Any, Callable, Iterable

from topomark.proofs.census_map import map_task
from topomark.proofs.census_shards import done_path, read_shard, reduce_path, summary
from topomark.spec.errors import InvalidInput

__all__ = ["RECHECK_FRACTION", "recheck_sample", "task_of", "recheck_map", "recheck_reduce", "recheck_resumed"]

RECHECK_FRACTION = 0.01
"""The share of the kept records (map tasks, shards; at least one of each) a resume computes again."""

_SUMMARY = ("languages", "languages_upto", "ambiguous_upto", "pair", "pairs")


def recheck_sample(kept: Iterable[int], seed: int, fraction: float = RECHECK_FRACTION) -> list[int]:
    """A seeded sample of ``kept``: ``ceil(fraction × len)`` of them, at least one (none of none), sorted."""
    pool = sorted(kept)
    if not pool:
        return []
    return sorted(random.Random(seed).sample(pool, min(len(pool), max(1, math.ceil(fraction * len(pool))))))


def task_of(manifest: dict[str, Any], member: list[int]) -> int:
    """The map task whose units hold ``member`` ``(n, m, gi, ri, k)``: the unit ``(n, gi, c, C)`` with
    ``ri ≡ c (mod C)`` (:mod:`topomark.proofs.census_map`)."""
    n, _, gi, ri, _ = member
    for t, task in enumerate(manifest["tasks"]):
        for (un, ugi, c, step), _ in task:
            if (un, ugi) == (n, gi) and ri % step == c:
                return t
    raise InvalidInput(f"the member {member} of a kept record is on no world of the census's plan "
                       "(edited and resealed?); remove the shard directory and run again")


def _refuse(path: Path, what: str, field: str) -> InvalidInput:
    return InvalidInput(f"{path}: {what} computed again does not give the {field} its record says (edited and "
                        f"resealed?); a census does not answer from a changed directory: remove "
                        f"{path.parent} (or this file) and run again")


def recheck_map(root: Path, manifest: dict[str, Any], task: int, record: dict[str, Any]) -> None:
    """Compute map task ``task`` again (nothing written) and compare it with its kept ``record``; exit 2 if not
    the same."""
    p = manifest["params"]
    units = [tuple(u) for u, _ in manifest["tasks"][task]]
    _, fresh = map_task(task, p["marker"], p["max_degree"], units, manifest["shards"], manifest["checksum"])
    for field in ("data", "offsets", "records", "sizes"):
        if record.get(field) != fresh[field]:
            raise _refuse(done_path(root, task), f"map task {task}", field)


def recheck_reduce(root: Path, manifest: dict[str, Any], done: list[dict[str, Any]], shard: int,
                   record: dict[str, Any]) -> None:
    """Reduce shard ``shard`` again (nothing written) and compare it with its kept ``record``; exit 2 if not
    the same."""
    p = manifest["params"]
    slices = [(t, d["offsets"][shard], d["offsets"][shard + 1] - d["offsets"][shard]) for t, d in enumerate(done)]
    fresh = summary(read_shard(root, slices), p["min_n"], p["max_vertices"], "pairs" in record)
    for field in _SUMMARY:
        if record.get(field) != fresh.get(field):
            raise _refuse(reduce_path(root, shard), f"shard {shard}", field)


def recheck_resumed(root: Path, manifest: dict[str, Any], done: list[dict[str, Any]], kept_tasks: set[int],
                    parts: list[dict[str, Any]], kept_shards: set[int], total: dict[str, Any], seed: int,
                    note: Callable[[str], None]) -> None:
    """The rule of this module over one resumed census: what is re-checked, reported through ``note``."""
    if not kept_tasks and not kept_shards:
        return
    pair = total["pair"] or []
    tasks = sorted((set(recheck_sample(kept_tasks, seed)) | {task_of(manifest, m) for m in pair}) & kept_tasks)
    verdict = {s for s in kept_shards if pair and parts[s]["pair"] == pair}
    shards = sorted(set(recheck_sample(kept_shards, seed + 1)) | verdict)
    note(f"census: resumed {len(kept_tasks)} map task(s) and {len(kept_shards)} shard(s); computing again map "
         f"task(s) {_listed(tasks)} and shard(s) {_listed(shards)} to check them (seed {seed})")
    for t in tasks:
        recheck_map(root, manifest, t, done[t])
    for s in shards:
        recheck_reduce(root, manifest, done, s, parts[s])


def _listed(xs: list[int]) -> str:
    shown = ", ".join(map(str, xs[:20]))
    return (shown + f" and {len(xs) - 20} more" if len(xs) > 20 else shown) or "none"

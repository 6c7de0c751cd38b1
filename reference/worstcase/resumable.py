"""The exhaustive worst case as resumable tasks on disk, on local processes or a Dask cluster (thesis §7.2).

:func:`worst_case` plans the census's map tasks
(:func:`topomark.proofs.census_map.plan`: every embedded world up to
isomorphism, split into tasks of about ``task_worlds`` worlds), runs each
task's worlds and starts (:func:`~topomark.reference.worstcase.exhaustive.run_task`)
and merges their tallies.  Memory is set by the task size, never by the
number of worlds: a task keeps only its tallies.

On disk (``topomark/worst-case@1``), in one directory::

    manifest.json     the parameters, the code version and the task list (written once)
    task-T.json       task T's tallies, refused starts and checked sample (written last, atomically)

Every file is a record sealed with its BLAKE2b checksum
(:func:`topomark.proofs.census_shards.seal`), and a task file names the
manifest's checksum, so a resume trusts only files of this search written by
this code; a task whose file is missing or fails its checksum runs again.  A
killed search so resumes where it stopped.  A checksum is no signature, so a
resume trusts no more than it can check (:mod:`.task_record`): the manifest's
task list must be the plan of its parameters; a task file whose seal holds but
whose tallies are not consistent is bad input (exit 2) naming the file.  A
record edited consistently and resealed passes those checks, so a resume also
runs again (:func:`_recheck_kept`) a seeded sample of the kept tasks
(:data:`topomark.proofs.census_recheck.RECHECK_FRACTION`, at least one; the
seed drawn afresh each time and reported) and every kept task whose file holds
a witness of a tallied maximum or reports a problem; one that does not give
what its file says is bad input (exit 2) naming the file, as in the census
(:mod:`topomark.proofs.census_recheck`); every file is read
back as a regular file of bounded size (a FIFO or a device is refused).
The directory is used by its absolute path, so workers elsewhere (a Dask
cluster) find it.

At the end every argmax run is re-run checked and must reproduce its cost
with a verified map (exit 3 otherwise: topomark's two runs disagree).
"""

from __future__ import annotations

import json
import secrets
import time
from pathlib import Path
from typing import Any, Callable

from topomark.proofs.census_exec import Progress, executor
from topomark.proofs.census_integrity import Damaged, package_version, read_record_text, source_digest
from topomark.proofs.census_map import plan, world_at
from topomark.proofs.census_recheck import recheck_sample
from topomark.proofs.census_shards import seal, write_json
from topomark.spec.errors import InvalidInput, TopomarkFault

from topomark.reference.worstcase.exhaustive import Setup, run_start, run_task
from topomark.reference.worstcase.readback import read_regular
from topomark.reference.worstcase.tally import SizeTally, Witness, merge_tallies
from topomark.reference.worstcase.task_record import check_record

__all__ = ["FORMAT", "Search", "worst_case", "code_version", "task_path", "CODE_MODULES", "INFRASTRUCTURE"]

FORMAT = "topomark/worst-case@1"
CODE_PACKAGES = ("topomark.spec", "topomark.reference.explorers", "topomark.reference.algorithms",
                 "topomark.reference.run", "topomark.reference.worstcase")
CODE_MODULES = ("topomark.proofs.census_map", "topomark.proofs.enumerate", "topomark.proofs.world_batches",
                "topomark.proofs.orbit_kernel", "topomark.proofs.start_orbits", "topomark.proofs.world_arrays")
"""The modules of proofs/ that decide which worlds and starts a task runs and what it hands the explorer."""
INFRASTRUCTURE = ("topomark.proofs.census_exec", "topomark.proofs.census_integrity", "topomark.proofs.census_recheck",
                  "topomark.proofs.census_shards")
"""The modules of proofs/ a run uses to schedule, seal and re-check tasks: they decide no cost."""


def code_version() -> str:
    """``topomark VERSION, worst-case code DIGEST``: a digest of every source file a run's cost depends on."""
    return f"topomark {package_version()}, worst-case code {source_digest(CODE_PACKAGES, CODE_MODULES)}"


def task_path(root: Path, task: int) -> Path:
    return root / f"task-{task}.json"


def _read(path: Path) -> dict[str, Any]:
    """The sealed record in ``path``: a regular file of bounded size (else exit 2) whose checksum holds
    (else :class:`Damaged`)."""
    data = read_regular(path, "worst-case shards")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise Damaged("it is not UTF-8 text") from None
    try:
        return read_record_text(text)
    except RecursionError:
        raise Damaged("it is nested too deeply") from None


def _plan(params: dict[str, Any], task_worlds: int) -> tuple[list, list]:
    planned = plan(params["max_vertices"], params["max_degree"], params["min_vertices"], task_worlds)
    return [[list(u) for u, _ in task] for task in planned], [sum(e for _, e in task) for task in planned]


class Search:
    """One exhaustive search: its parameters, directory and manifest (read on resume, else written)."""

    def __init__(self, setup: Setup, max_vertices: int, max_degree: int, min_vertices: int, root: Path,
                 task_worlds: int = 2000):
        self.setup, self.root = setup, root
        self.max_degree = max_degree
        self.params = {**setup.to_json(), "max_vertices": max_vertices, "max_degree": max_degree,
                       "min_vertices": min_vertices}
        self.manifest = self._prepare(task_worlds)
        self.resumed: set[int] = set()

    def _prepare(self, task_worlds: int) -> dict[str, Any]:
        try:
            self.root.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise InvalidInput(f"worst-case directory {str(self.root)!r} cannot be made: {e.strerror or e}") from None
        path = self.root / "manifest.json"
        p = self.params
        if not (path.exists() or path.is_symlink()):
            tasks, estimated = _plan(p, task_worlds)
            manifest = seal({"format": FORMAT, "code": code_version(), "params": p, "task_worlds": task_worlds,
                             "tasks": tasks, "estimated": estimated})
            write_json(path, manifest)
            return manifest
        try:
            manifest = _read(path)
        except Damaged as e:
            raise InvalidInput(f"{path}: damaged: {e}; remove {self.root} or choose an empty directory") from None
        if manifest.get("format") != FORMAT:
            raise InvalidInput(f"{path}: not a {FORMAT} manifest; choose an empty directory")
        if manifest.get("params") != p or manifest.get("code") != code_version():
            raise InvalidInput(f"{self.root} holds another worst-case search ({manifest.get('params')}, "
                               f"{manifest.get('code')}); use an empty directory or the same options and code")
        tw = manifest.get("task_worlds", task_worlds)  # a manifest of an earlier topomark has none: the default
        if type(tw) is not int or tw < 1 or [manifest.get("tasks"), manifest.get("estimated")] != list(_plan(p, tw)):
            raise InvalidInput(f"{path}: its task list is not the plan of its parameters (edited?); remove "
                               f"{self.root} or choose an empty directory")
        return manifest

    def finished(self, note: Callable[[str], None]) -> dict[int, dict[str, Any]]:
        """The tasks whose files pass their checks; a damaged one is reported and will run again."""
        good = {}
        for t, units in enumerate(self.manifest["tasks"]):
            path = task_path(self.root, t)
            if not (path.exists() or path.is_symlink()):
                continue
            try:
                record = _read(path)
                if record.get("search") != self.manifest["checksum"] or record.get("task") != t:
                    raise Damaged("it belongs to another search or task")
            except Damaged as e:
                note(f"worst-case: {path}: {e}; running task {t} again")
                continue
            check_record(path, record, units)  # sealed but inconsistent: edited and resealed, exit 2
            good[t] = record
        self.resumed = set(good)
        return good

    def run(self, jobs: int, scheduler: str | None, progress: Callable[[str], None] | None) -> dict[int, dict]:
        """Run every unfinished task; every task's record."""
        tasks, est = self.manifest["tasks"], self.manifest["estimated"]
        done = self.finished(progress or (lambda _: None))
        bar = Progress(sum(est), progress, label="worst-case")
        for t in done:
            bar.skip(est[t], _worlds(done[t]))
        todo = [t for t in range(len(tasks)) if t not in done]
        calls = [(_task, (str(self.root), t, self.manifest["checksum"], self.setup, self.max_degree,
                          [tuple(u) for u in tasks[t]])) for t in todo]
        with executor(jobs, scheduler, len(calls)) as ex:
            for i, record in ex.run(calls):
                done[todo[i]] = record
                bar.done(est[todo[i]], _worlds(record))
        if progress is not None:
            progress(f"worst-case: {bar.count()} run in {time.perf_counter() - bar.t0:.1f} s")
        return done


def _worlds(record: dict[str, Any]) -> int:
    return sum(t["worlds"] for t in record["tallies"])


def _task(root: str, task: int, search: str, setup: Setup, max_degree: int, units: list) -> dict[str, Any]:
    """A worker's task: run it, write its sealed record, return it."""
    record = seal({"search": search, "task": task, **run_task(setup, max_degree, units)})
    write_json(task_path(Path(root), task), record)
    return record


def recheck_argmax(setup: Setup, max_degree: int, tally: SizeTally) -> tuple[list[Witness], list[dict]]:
    """Re-run every argmax of ``tally`` checked: it must reproduce the tallied cost (else exit 3: topomark's two
    runs disagree) with a verified map (else a problem: the algorithm's map or an invariant is wrong)."""
    seen: list[Witness] = []
    problems: list[dict] = []
    for witness, want in ((tally.argmax_cost, tally.max_cost), (tally.argmax_cost_m, None), (tally.argmax_ratio, None)):
        if witness is None or witness in seen:
            continue
        seen.append(witness)
        world = world_at(tally.n, max_degree, witness[0], witness[1])
        out = run_start(setup, world, (witness[2], witness[3]), check=True)
        if want is not None and out.cost != want:
            raise TopomarkFault(f"the worst run at n = {tally.n} (graph {witness[0]}, rotation {witness[1]}, start "
                                f"{witness[2]} exit {witness[3]}) cost {want} unchecked but {out.cost} checked: "
                                "the checked and unchecked runs disagree", check="checked and unchecked runs agree")
        if not out.verified:
            detail = out.violation.to_json() if out.violation is not None else out.outcome
            problems.append({"n": tally.n, "witness": list(witness), "kind": "violation", "detail": detail})
    return seen, problems


def _verify_resumed(search: Search, record: dict[str, Any]) -> None:
    """Run a resumed task again: if it does not give what its file says, the file is bad input (exit 2)."""
    t = record["task"]
    if t not in search.resumed:
        return
    fresh = json.loads(json.dumps(run_task(search.setup, search.max_degree,
                                           [tuple(u) for u in search.manifest["tasks"][t]])))
    if any(record.get(k) != v for k, v in fresh.items()):
        raise InvalidInput(f"{task_path(search.root, t)}: task {t} run again does not give what the file says "
                           "(edited and resealed?); remove the file to run the task again")


def _recheck_kept(search: Search, records: dict[int, dict[str, Any]], tallies: dict[int, SizeTally], seed: int,
                  progress: Callable[[str], None] | None) -> None:
    """Run again the kept tasks a resume must not take on trust (the rule of the module's docstring): a seeded
    sample, every task holding a tallied maximum's witness and every task reporting a problem."""
    if not search.resumed:
        return
    witnesses = {(n, tuple(w)) for n, t in tallies.items()
                 for w in (t.argmax_cost, t.argmax_cost_m, t.argmax_ratio) if w is not None}
    verdicts = {t for t in search.resumed if records[t]["problems"] or records[t]["problem_count"] or any(
        (x["n"], tuple(x[k])) in witnesses for x in records[t]["tallies"]
        for k in ("argmax_cost", "argmax_cost_m", "argmax_ratio") if x[k] is not None)}
    again = sorted(set(recheck_sample(search.resumed, seed)) | verdicts)
    if progress is not None:
        progress(f"worst-case: resumed {len(search.resumed)} task(s); running task(s) "
                 f"{', '.join(map(str, again[:20]))}{' ...' if len(again) > 20 else ''} again to check them "
                 f"(seed {seed})")
    for t in again:
        _verify_resumed(search, records[t])


def worst_case(setup: Setup, max_vertices: int, max_degree: int, root: Path, min_vertices: int = 2,
               jobs: int = 1, scheduler: str | None = None, progress: Callable[[str], None] | None = None,
               task_worlds: int = 2000, recheck_seed: int | None = None) -> dict[str, Any]:
    """Run (or resume) the exhaustive search in ``root``; the merged tallies and what the checks found
    (a resume runs kept tasks again as the module says, seeded by ``recheck_seed``, drawn afresh if None)."""
    search = Search(setup, max_vertices, max_degree, min_vertices, Path(root).absolute(), task_worlds)
    records = search.run(jobs, scheduler, progress)
    parts = [{t["n"]: SizeTally.from_json(t) for t in r["tallies"]} for r in records.values()]
    tallies = merge_tallies(parts)
    _recheck_kept(search, records, tallies, secrets.randbits(32) if recheck_seed is None else recheck_seed, progress)
    problems = [p for r in records.values() for p in r["problems"]]
    for r in records.values():
        if any(p["kind"] == "disagree" for p in r["problems"]):
            _verify_resumed(search, r)
            raise TopomarkFault(f"a checked re-run disagrees with its unchecked run: "
                                f"{next(p for p in r['problems'] if p['kind'] == 'disagree')}",
                                check="checked and unchecked runs agree")
    count, checked = sum(r["problem_count"] for r in records.values()), sum(r["checked"] for r in records.values())
    for tally in tallies.values():
        try:
            seen, found = recheck_argmax(setup, max_degree, tally)
        except TopomarkFault:
            for r in records.values():  # the task whose file holds the maximum: does it give it when run again?
                if any(t["n"] == tally.n and t["max_cost"] == tally.max_cost for t in r["tallies"]):
                    _verify_resumed(search, r)
            raise
        checked, count, problems = checked + len(seen), count + len(found), problems + found
    return {"tallies": tallies, "refused": sum(r["refused"] for r in records.values()), "checked": checked,
            "problem_count": count, "problems": problems[:20], "manifest": search.manifest}

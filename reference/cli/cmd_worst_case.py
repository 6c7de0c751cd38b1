"""``topomark worst-case``: the worst cost of an algorithm, exhaustive over small worlds (thesis §7.2).

``topomark worst-case --algorithm basic --max-vertices 5 --max-degree 4``
runs the algorithm unchecked from every start of every embedded world with
n ≤ 5 vertices and degrees ≤ 4 (one world per isomorphism class, one start per
orbit of its automorphisms), re-runs a seeded sample and every argmax checked,
and prints per n the worlds, runs, largest cost, largest cost/m and largest
ratio of the cost to the algorithm's exact bound (for Algorithm 3.1, (3.1) +
(3.2), §3.5.2), with the world that reaches it.  ``--shards DIR`` keeps the
tasks on disk so a killed run resumes; ``--jobs``/``--scheduler`` spread them
(:mod:`topomark.reference.worstcase.resumable`); ``--out DIR`` writes the JSON,
the argmax worlds as world files, the report and its plot;
``--cross-check`` also runs the independent brute force over labelled rotation
systems (n ≤ 5) and requires the same maxima.

``--search`` looks past exhaustive sizes by seeded local search
(:mod:`topomark.reference.worstcase.search`): a lower bound on the worst case.

Exit 0 when every run mapped its world (and the checked runs agree), 1 when a
run did not (a failure, a wrong map, a violated invariant), 2 on bad input, 3
when topomark's checked and unchecked runs, or the two exhaustive searches,
disagree.  The options are :mod:`topomark.reference.cli.options.worst_case`'s; this module is imported
when the command runs.

Every size is bounded before work (:mod:`topomark.reference.worstcase.limits`), and so is everything the command
is handed: ``--summarise`` directories are read back and recomputed
(:mod:`topomark.reference.worstcase.summary_input`; exit 1 if a recomputed cost exceeds its exact bound),
``-o DIR`` must be a directory a file can be written in (a device, a FIFO or a read-only place is refused before
work), ``--search`` refuses the options of the exhaustive search.  Without ``--shards``, the search keeps its
tasks in a temporary folder ``topomark-worst-case-PID-*``: SIGTERM ends the command through Python's exit, so
the folder is removed; after a SIGKILL it stays, and the next ``worst-case`` removes every such folder whose
process is gone.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import shutil
import signal
import sys
import tempfile
from pathlib import Path
from typing import Any

from topomark.reference.files.outputs import guarded
from topomark.reference.files.overwrite import named_path
from topomark.spec.errors import InvalidInput

from topomark.reference.cli.args import check_jobs, check_max_degree, check_min_vertices
from topomark.reference.cli.cmd_worst_search import claim_out, search_command, setup_of
from topomark.reference.worstcase.limits import MAX_EXHAUSTIVE, exhaustive_refusal, search_refusal

__all__ = ["worst_case_command"]


def _validate(args: argparse.Namespace) -> None:
    if args.max_vertices is None:
        raise InvalidInput("--max-vertices is required (the largest world size of the exhaustive search)")
    if not 2 <= args.max_vertices <= MAX_EXHAUSTIVE:
        raise InvalidInput(f"--max-vertices must be between 2 and {MAX_EXHAUSTIVE} for the exhaustive search "
                           f"(use --search past it), not {args.max_vertices}")
    check_min_vertices(args.min_vertices, args.max_vertices)
    check_max_degree(args.max_degree)
    check_jobs(args.jobs)
    refusal = exhaustive_refusal(args.max_vertices, args.max_degree)
    if refusal:
        raise InvalidInput(refusal)
    if args.cross_check and args.max_vertices > 5:
        raise InvalidInput(f"--cross-check runs the brute force for n <= 5 only, not --max-vertices {args.max_vertices}")


EXHAUSTIVE_ONLY = {"max_vertices": ("--max-vertices", None), "min_vertices": ("--min-vertices", 2),
                   "jobs": ("--jobs", 1), "scheduler": ("--scheduler", None), "shards": ("--shards", None),
                   "sample": ("--sample", 0.001), "cross_check": ("--cross-check", False)}
"""The options of the exhaustive search, with their defaults: ``--search`` refuses any given another value."""


def _check_search(args: argparse.Namespace) -> None:
    for key, (flag, default) in EXHAUSTIVE_ONLY.items():
        if getattr(args, key) != default:
            raise InvalidInput(f"{flag} is an option of the exhaustive search; --search does not use it")
    if args.vertices is None:  # the default size: the restart world's own, else 20
        args.vertices = [_restart_world_size(args.restart_world) if args.restart_world else 20]
    for n in args.vertices:
        refusal = search_refusal(n, args.evaluations)
        if refusal:
            raise InvalidInput(refusal)


def _restart_world_size(text: str) -> int:
    from topomark.reference.worlds.argument import resolve_world
    return resolve_world(text).n


def worst_case_command(args: argparse.Namespace) -> int:
    if args.summarise:
        return _summarise(args)
    named_path(args.shards, "--shards")  # resumed, not claimed: an earlier run's shards are reused
    if args.search:
        _check_search(args)
        return search_command(args)
    _validate(args)
    claim_out(args.out, args.force)
    setup = _with_engine(args, setup_of(args))
    progress = None if args.quiet else (lambda line: print(line, file=sys.stderr, flush=True))
    degree = min(args.max_degree, args.max_vertices - 1)
    if args.shards is not None:
        return _finish(args, setup, degree, _run(args, setup, degree, Path(args.shards).absolute(), progress))
    with _terminated_exits(), scratch_dir() as root:
        return _finish(args, setup, degree, _run(args, setup, degree, root, progress))


def _with_engine(args: argparse.Namespace, setup):
    """``setup`` with the engine ``--engine`` resolves to (:func:`topomark.reference.engine.choose`), its notice
    said on stderr."""
    from dataclasses import replace

    from topomark.reference.engine import choose
    engine, notice = choose(args.engine, setup.algorithm, setup.lighthouse, setup.policies)
    if notice is not None:
        print(notice, file=sys.stderr)
    return replace(setup, engine=engine)


def _summarise(args: argparse.Namespace) -> int:
    from topomark.reference.worstcase.summary import summarise_runs
    missing = [d for d in args.summarise if not Path(d).is_dir()]
    if missing:
        raise InvalidInput(f"--summarise: {missing[0]!r} is not a directory (give the --out directories of runs)")
    claim_out(args.out, args.force)
    dirs = [Path(d) for d in args.summarise]
    if args.out is None:
        text, held = summarise_runs(dirs)
        print(text, end="")
        return 0 if held else 1
    out = Path(args.out)
    text, held = summarise_runs(dirs, out)
    guarded(out, lambda: (out / "worst-case.md").write_text(text, encoding="utf-8"))
    print(f"wrote {out / 'worst-case.md'}")
    return 0 if held else 1


SCRATCH = "topomark-worst-case-"
"""The prefix of the temporary folders: ``topomark-worst-case-PID-XXXX`` in the system's temporary directory."""


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process
        return True
    return True


def remove_stale(parent: Path) -> list[Path]:
    """Remove the temporary folders in ``parent`` left by worst-case runs whose process is gone (a SIGKILL)."""
    removed = []
    for entry in parent.glob(f"{SCRATCH}*"):
        pid = entry.name[len(SCRATCH):].split("-", 1)[0]
        if pid.isdigit() and int(pid) != os.getpid() and not _alive(int(pid)) and entry.is_dir() \
                and not entry.is_symlink():
            shutil.rmtree(entry, ignore_errors=True)
            removed.append(entry)
    return removed


@contextlib.contextmanager
def scratch_dir():
    """A temporary folder named with this process's id, removed at the end; stale ones are removed first."""
    remove_stale(Path(tempfile.gettempdir()))
    with tempfile.TemporaryDirectory(prefix=f"{SCRATCH}{os.getpid()}-") as root:
        yield Path(root)


@contextlib.contextmanager
def _terminated_exits():
    """While the block runs, SIGTERM raises SystemExit (exit 143), so every ``with`` and ``finally`` runs."""
    def exit_on_term(signum, frame):
        raise SystemExit(128 + signal.SIGTERM)

    try:
        previous = signal.signal(signal.SIGTERM, exit_on_term)
    except ValueError:  # not the main thread: the handler cannot be installed, the default stays
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _run(args, setup, degree: int, root: Path, progress) -> dict[str, Any]:
    from topomark.reference.worstcase.resumable import worst_case
    return worst_case(setup, args.max_vertices, degree, root, args.min_vertices, args.jobs, args.scheduler, progress)


def _finish(args, setup, degree: int, found: dict[str, Any]) -> int:
    from topomark.reference.worstcase.result import rows, write_outputs
    tallies = found["tallies"]
    per_n = rows(tallies, degree, setup.spec)
    data = {"algorithm": setup.algorithm, "setup": setup.to_json(), "max_vertices": args.max_vertices,
            "max_degree": args.max_degree, "per_n": per_n, "refused_starts": found["refused"],
            "checked_runs": found["checked"], "problems": found["problems"], "problem_count": found["problem_count"],
            "method": "exhaustive: every embedded world up to isomorphism, every start up to automorphism"}
    if args.cross_check:
        from topomark.reference.worstcase.brute import brute_force, compare
        brute = brute_force(setup, args.max_vertices, degree, args.min_vertices)
        compare(tallies, brute)  # exit 3 if the two searches disagree
        data["cross_check"] = {n: t.to_summary() for n, t in brute.items()}
    if args.out is not None:
        from topomark.reference.worstcase.report import write_report
        out = Path(args.out)
        written = guarded(out, lambda: write_outputs(out, data, degree, tallies) + write_report(out, data))
        data["written"] = [str(p) for p in written]
    from topomark.reference.worstcase.report import not_correct
    failed = found["problem_count"] + sum(not_correct(r) for r in per_n)
    if args.json:
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        print(_table(data))
    return 1 if failed else 0


def _table(data: dict[str, Any]) -> str:
    from topomark.reference.worstcase.report import not_correct, table
    lines = [f"worst case of {data['algorithm']} over every world with n <= {data['max_vertices']}, "
             f"degree <= {data['max_degree']} (exhaustive, exact)", table(data["per_n"])]
    lines.append(f"{data['checked_runs']} runs re-run checked (sample and argmaxes); {data['refused_starts']} starts "
                 f"refused by the algorithm; {data['problem_count']} problems")
    kinds = sorted({k for r in data["per_n"] for k in r["outcomes"] if k != "correct"})
    if kinds:
        lines.append(f"runs that did not map their world: {sum(not_correct(r) for r in data['per_n'])} "
                     f"({', '.join(kinds)}); their costs are left out of the maxima (exit 1)")
    for p in data["problems"][:5]:
        lines.append(f"  problem: {json.dumps(p)}")
    if "cross_check" in data:
        runs = sum(t["runs"] for t in data["cross_check"].values())
        lines.append(f"cross-check: the brute force over every labelled rotation system ({runs} runs, no isomorphism "
                     "reduction) found the same maxima and the same (m, cost) values at every n")
    if "written" in data:
        lines.append(f"wrote {len(data['written'])} files, {data['written'][0]} ...")
    return "\n".join(lines)

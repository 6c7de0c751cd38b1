"""``topomark worst-case --search``: bad worlds past exhaustive sizes, by seeded local search (thesis §7.2).

For each size ``--vertices N ...`` the search (:func:`topomark.reference.worstcase.search.adversarial_search`)
changes one vertex's rotation, adds or removes an edge, moves the start, switches two edges or transposes two
neighbours (:mod:`topomark.reference.worstcase.structural`), keeping the world connected and within
``--max-degree``, and keeps what raises the ``--objective``; ``--restart-family`` starts it from a named family's
world instead of random worlds, and ``--restart-world`` from one world (a kept worst world: a search going on from
where another stopped); the same number of random worlds
(:func:`~topomark.reference.worstcase.search.random_baseline`, run by the search) is the yardstick.  What it finds is a lower bound on
the worst case, not the worst case.  The growth of the best cost with m, n, the diameter and the maximum degree is
fitted on log-log axes (:func:`~topomark.reference.worstcase.fit.fit_exponents`).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path
from typing import Any

from topomark.spec.errors import InvalidInput

from topomark.reference.files.outputs import check_output_dir
from topomark.reference.files.overwrite import claim_dir

__all__ = ["claim_out", "search_command", "setup_of"]


def claim_out(path: str | None, force: bool) -> None:
    """``-o DIR``, claimed (:func:`~topomark.reference.files.overwrite.claim_dir`), made, and a file written and
    removed there: a device, a FIFO, a read-only place are refused before the work, naming ``-o``."""
    claim_dir(path, "-o", force)
    if path is None:
        return
    try:
        out = check_output_dir(path)
        probe = out / f".topomark-probe-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except InvalidInput as e:
        raise InvalidInput(f"-o {e}") from None
    except OSError as e:
        raise InvalidInput(f"-o {path}: cannot write there: {e.strerror or e}") from None


def setup_of(args: argparse.Namespace):
    """The shared setup of a worst-case search from the command line (bad input: exit 2)."""
    from topomark.reference.algorithms.registry import algorithm_spec
    from topomark.reference.cli.cmd_explore import check_policy_kinds, parse_policies
    from topomark.reference.worstcase.exhaustive import Setup

    spec = algorithm_spec(args.algorithm)
    policies = parse_policies(args.policy, spec)
    check_policy_kinds(args.policy, spec)
    if not 0 <= args.sample <= 1:
        raise InvalidInput(f"--sample must be a fraction between 0 and 1, not {args.sample}")
    spec.lighthouse_for(args.lighthouse)  # an unknown lighthouse, or one for a kit algorithm: exit 2
    return Setup(spec.name, args.lighthouse, (policies.edge, policies.hypothesis, policies.path), args.sample,
                 args.seed)


def search_command(args: argparse.Namespace) -> int:
    from topomark.reference.worstcase.fit import fit_exponents
    from topomark.reference.worstcase.search import adversarial_search
    setup = setup_of(args)
    if args.evaluations < 1:
        raise InvalidInput(f"--evaluations must be at least 1, not {args.evaluations}")
    if args.restart_family and args.restart_world:
        raise InvalidInput("--restart-family and --restart-world both say where the search starts: give one")
    restart = args.restart_family or args.restart_world
    claim_out(args.out, args.force)
    rows: list[dict[str, Any]] = []
    for n in args.vertices:
        progress = None if args.quiet else _Progress(n, args.evaluations)
        kw = dict(objective=args.objective, evaluations=args.evaluations, seed=args.seed, lighthouse=setup.lighthouse,
                  policies=setup.policy(), family=args.world_family, restart=restart, engine=args.engine)
        found = adversarial_search(setup.algorithm, n, args.max_degree, progress=progress, **kw).to_json()
        rows.append({"n": n, "search": found, "random": found.pop("random")})
    best = [{**r["search"]["best"], "n": r["n"]} for r in rows if r["search"].get("best")]
    data = {"algorithm": setup.algorithm, "setup": setup.to_json(), "max_degree": args.max_degree,
            "objective": args.objective, "family": args.world_family, "restart": restart,
            "evaluations": args.evaluations, "per_n": rows,
            "fit": fit_exponents(best) if len(best) >= 3 else None,  # two points fit any power exactly
            "method": "seeded local search: a lower bound on the worst case, not the worst case"}
    if args.out is not None:
        from topomark.reference.files.outputs import guarded
        guarded(args.out, lambda: _write(Path(args.out), data))
    if args.json:
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        print(_lines(data))
    return 0


class _Progress:
    """One progress line per size at most every 2 seconds, and one when the size is done."""

    def __init__(self, n: int, budget: int):
        self.n, self.budget, self.last = n, budget, time.perf_counter()

    def __call__(self, done: int, best: float) -> None:
        now = time.perf_counter()
        if now - self.last >= 2 or done >= self.budget:
            self.last = now
            print(f"worst-case search: n = {self.n}, {done}/{self.budget} runs, best {best:g}", file=sys.stderr,
                  flush=True)


def _write(out: Path, data: dict[str, Any]) -> None:
    out.mkdir(parents=True, exist_ok=True)
    (out / "worst-case-search.json").write_text(json.dumps(data, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    for r in data["per_n"]:
        for kind in ("search", "random"):
            best = r[kind].get("best")
            if best and best.get("world"):
                (out / f"{kind}-best-n{r['n']}.json").write_text(json.dumps(best["world"], indent=1) + "\n",
                                                                  encoding="utf-8")


def _lines(data: dict[str, Any]) -> str:
    lines = [f"adversarial search for {data['algorithm']} ({data['objective']}, {data['evaluations']} runs per n, "
             f"degree <= {data['max_degree']}): a lower bound on the worst case",
             f"{'n':>4}  {'m':>4}  {'best cost':>9}  {'cost/m':>7}  {'cost/bound':>10}  {'random best':>11}"]
    for r in data["per_n"]:
        s, b = r["search"].get("best") or {}, r["random"].get("best") or {}
        lines.append(f"{r['n']:>4}  {s.get('m', '-'):>4}  {s.get('cost', '-'):>9}  {s.get('cost_per_m', '-'):>7}  "
                     f"{str(s.get('ratio_to_bound', '-')):>10}  {b.get('cost', '-'):>11}")
    if data["fit"]:
        lines.append(f"fitted exponents of the best cost: {json.dumps(data['fit'])}")
    return "\n".join(lines)

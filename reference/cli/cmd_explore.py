"""``topomark explore``: a checked exploration by Algorithm 3.1 (thesis §3.3–3.5).

Its options are :mod:`topomark.reference.cli.options.explore`'s; this module is imported when it runs."""

from __future__ import annotations

import contextlib
import json
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Callable, cast

from topomark.spec.errors import InvalidInput
from topomark.spec.worldfile import dumps_world

from topomark.reference.run.breakdown import KINDS
from topomark.reference.run.explore import check_run, explore
from topomark.reference.explorers.lighthouses import configured
from topomark.reference.algorithms.registry import algorithm_spec, parameters
from topomark.reference.worlds.generators import DEFAULT_WORLD
from topomark.reference.files.outputs import check_output_dir, guarded, write_output
from topomark.reference.files.overwrite import claim_dir, claim_file
from topomark.reference.explorers.policies import Policies
from topomark.reference.trace.sink import FileSink, RingSink, TeeSink
from topomark.reference.worlds.argument import resolve_world

__all__ = ["explore_command", "parse_policies", "check_policy_kinds"]


def parse_policies(items: list[str], spec=None) -> Policies:
    """The ``--policy KIND=NAME`` items as :class:`Policies`; a kind not given takes the default of the algorithm
    ``spec`` (its registration's edge policy, :meth:`AlgorithmSpec.policies`), or the package's without one."""
    chosen: dict[str, str] = {}
    for item in items:
        kind, eq, name = item.partition("=")
        if not eq:
            kind, name = "edge", item
        if kind not in ("edge", "hypothesis", "path"):
            raise InvalidInput(f"--policy {item!r}: the kind must be edge, hypothesis or path")
        if kind in chosen:
            raise InvalidInput(f"--policy: the {kind} policy is given twice")
        chosen[kind] = name
    return Policies(**chosen) if spec is None else spec.policies(chosen)


def check_policy_kinds(items: list[str], spec) -> None:
    """Refuse a ``--policy`` whose kind the algorithm ``spec`` does not declare in its options (exit 2)."""
    for item in items:
        kind = item.partition("=")[0] if "=" in item else "edge"
        if kind not in spec.policy_kinds:
            takes = (f"its policies: {', '.join(spec.policy_kinds)}" if spec.policy_kinds
                     else "it takes no --policy")
            raise InvalidInput(f"--policy {item}: the algorithm {spec.name} takes no {kind} policy ({takes})")


class _Progress:
    """Progress on stderr: a one-line bar on a terminal; otherwise, on a long run, a plain line every ``every`` s.

    The plain lines (edges explored / m, cost so far, elapsed) start only once the run has taken ``every``
    seconds, so short runs and logs stay quiet.
    """

    def __init__(self, enabled: bool, stream=None, clock=time.monotonic, every: float = 10.0):
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.tty = self.stream.isatty()
        self.clock, self.every = clock, every
        self.started = self.last = clock()

    def __call__(self, done: int, total: int, cost: int = 0) -> None:
        if not self.enabled:
            return
        now = self.clock()
        if self.tty:
            self._bar(now, done, total)
        elif now - self.last >= self.every:
            self.last = now
            self.stream.write(f"topomark: exploring: {done}/{total} edges explored, cost {cost} so far, "
                              f"{now - self.started:.0f} s elapsed\n")
            self.stream.flush()

    def _bar(self, now: float, done: int, total: int) -> None:
        if now - self.last < 0.2 and done < total:
            return
        self.last = now
        width = 30
        fill = width * done // max(total, 1)
        self.stream.write(f"\rexploring [{'#' * fill}{'.' * (width - fill)}] {done}/{total} edges")
        if done >= total:
            self.stream.write("\n")
        self.stream.flush()


def _bound_text(o, spec) -> str:
    """The cost bound row: the exact bound on this world, and whether this run was held to it (``cost-bound``);
    else the registry's statement, never claimed as checked (an O(·) bound has no constant, so no run can be
    held to it: a bench measures it), or that the thesis states none."""
    if o.upper_bound is not None:
        return (f"{o.upper_bound} ({'checked: cost-bound' if o.bound_checked else 'not checked: --no-check'}) — "
                f"{o.bound_whose}")
    return f"{spec.bound} ({spec.bound_note})" if spec.bound else spec.bound_note


def _untested(o) -> int:
    """The hypotheses never walked: Algorithm 3.1 tests H in turn and a confirmed one (case 3) "exit[s] the inner
    'while' loop" (line 20, Algorithm 3.1), so the ones left in H stay untested; the others are rejected (cases 1, 2)."""
    return o.hypotheses - o.hypotheses_rejected - o.hypotheses_confirmed


def _table(o, started: float, spec) -> str:
    """The report's table; a kit algorithm's has its steps and its own counts where Algorithm 3.1's has
    iterations and hypotheses.  ``spec`` is the algorithm's registry entry (its cost bound, in words)."""
    lighthouse = spec.uses_lighthouse
    rows = [
        ("n", o.n), ("m", o.m), ("cost (edge traversals)", o.cost), ("cost / m", f"{o.cost / o.m:.2f}"),
        ("drop trips (in the cost)", f"{o.drop_trips} (cost without them: {o.cost - o.drop_trips}, "
                                     f"{(o.cost - o.drop_trips) / o.m:.2f} m)"),
        ("cost bound (registry)", _bound_text(o, spec)),
        *((f"  {purpose}", count) for purpose, count in o.by_purpose.items()),
        ("marker operations (not cost, §3.1.2)",
         ", ".join(f"{op.replace('_', ' ')}: {n}" for op, n in o.marker_operations.items()) or "none"),
    ]
    if lighthouse:
        rows += [("iterations (non-loop + loop)", f"{o.iterations} ({o.nonloop_iterations} + {o.loop_iterations})"),
                 ("hypotheses (rejected / confirmed / untested)",
                  f"{o.hypotheses} ({o.hypotheses_rejected} / {o.hypotheses_confirmed} / {_untested(o)}; untested: "
                  "not walked, a confirmation exits the test of H, Algorithm 3.1 line 20)")]
    else:
        rows += [("steps", o.iterations), *((key.replace("_", " "), value) for key, value in o.extra.items())]
    rows += [("outcome (claimed / judged)", f"{o.claimed} / {o.outcome}"), ("checks passed", o.checks),
             ("wall time", f"{time.monotonic() - started:.2f} s")]
    width = max(len(k) for k, _ in rows)
    return "\n".join(f"{k:<{width}}  {v}" for k, v in rows)


TAIL = 8  # trace records shown before a violation's end record


def explore_command(args) -> int:
    spec = algorithm_spec(args.algorithm)
    policies = parse_policies(args.policy, spec)
    check_policy_kinds(args.policy, spec)
    options = {name: getattr(args, f"param_{name.replace('-', '_')}") for name in parameters()}
    claim_file(args.trace, "--trace", args.force)  # before the run: a typo must not cost a long exploration
    claim_file(args.map, "--map", args.force)
    claim_file(args.view, "--view", args.force)
    if args.breakdown_plot is not None:
        from topomark.reference.bench.reports.breakdown_plot import check_plot_file
        claim_file(args.breakdown_plot, "--breakdown-plot", args.force)
        check_plot_file(args.breakdown_plot)  # matplotlib missing: bad input before the run, not after it
    if args.models is not None:
        if spec.write_models is None:
            raise InvalidInput(f"--models: the algorithm {spec.name} keeps no models (model-tree does)")
        claim_dir(args.models, "--models", args.force, replace=("model-*.json",))
        check_output_dir(args.models)
    light, seed = configured(args.lighthouse, args.seed, args.walk_limit, args.neighbourhood, args.threshold)
    if args.world is None:
        if seed is not None:
            raise InvalidInput("--seed needs a generator: the built-in default world is fixed")
        world, label = DEFAULT_WORLD(), "built-in default world (5x5 lattice, 2 cells removed, seed 1)"
    else:
        world, label = resolve_world(args.world, seed), args.world
    check_run(world, spec, light, options)  # refused before the trace file is started
    started = time.monotonic()
    ring = RingSink(TAIL + 1)
    outcome = _explored(args, world, spec, policies, light, options, label, ring)
    unwritten = _write_map(args.map, outcome)
    if args.breakdown_plot is not None:
        from topomark.reference.bench.reports.breakdown_plot import save_breakdown_plot
        guarded(args.breakdown_plot, lambda: save_breakdown_plot(
            outcome.breakdown, args.breakdown_plot, f"{args.algorithm} on {label}: cost {outcome.cost}"))
    if args.models is not None:
        write_models = cast(Callable[[Any, str], list[Any]], spec.write_models)  # checked when --models was read
        guarded(args.models, lambda: write_models(outcome.explorer, args.models))
    last = ring.records[:-1]  # the records before the end record
    data = {"world": label, "policies": spec.policies_json(policies), "algorithm": args.algorithm, **outcome.summary(),
            "checked": not args.no_check, "cost_breakdown": outcome.breakdown.to_json(rows=args.breakdown)}
    if args.map:
        data.update(map_written=unwritten is None, **({"map_not_written": unwritten} if unwritten else {}))
    tail = [json.dumps(rec, sort_keys=True) for rec in last] if outcome.violation else []
    if tail:
        data["trace_tail"] = last
    if args.json:
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        _print_report(args, spec, label, policies, outcome, started, tail)
        if args.breakdown:
            print(_breakdown_text(outcome.breakdown))
        if unwritten:
            print(f"no map written to {args.map}: {unwritten}")
    if outcome.violation is not None and args.json:
        print(f"topomark: check failed: {outcome.violation}", file=sys.stderr)
    if outcome.violation is not None:  # even unchecked: the simulator refused an operation the robot tried
        return 1
    return 0 if outcome.outcome == "correct" or (args.no_check and outcome.claimed == "correct") else 1


def _explored(args, world, spec, policies, light, options, label: str, ring: RingSink):
    """The run, its trace streamed to ``ring`` and to ``--trace`` (for ``--view`` alone, a temporary file);
    with ``--view``, the viewer's page of that trace."""
    with contextlib.ExitStack() as stack:
        trace = args.trace or (str(Path(stack.enter_context(tempfile.TemporaryDirectory())) / "trace.jsonl")
                               if args.view else None)
        with contextlib.ExitStack() as files:
            sink = TeeSink(files.enter_context(FileSink(trace)), ring) if trace else ring
            outcome = explore(world, spec, policies, check=not args.no_check, sink=sink,
                              progress=_Progress(not args.quiet), check_mode=args.check_mode,
                              keep_hypotheses=False, lighthouse=light, options=options)
        if args.view:
            from topomark.reference.viewer.view import view_trace
            view_trace(cast(str, trace), world, args.view, f"{args.algorithm} on {label}")
    return outcome


COSTLIEST = 5  # iterations the --breakdown report lists


def _breakdown_text(breakdown) -> str:
    """``--breakdown``'s report: the cost by kind of walk (with its share) and the costliest iterations."""
    totals = breakdown.by_kind()
    width = max(len(k) for k in totals)
    lines = ["cost by kind of walk (§3.5.2):"]
    lines += [f"  {k:<{width}}  {v:>10}  {v / max(breakdown.cost, 1):6.1%}" for k, v in totals.items() if v]
    rows = sorted(breakdown.rows(), key=lambda r: -sum(r[3:]))[:COSTLIEST]
    lines.append(f"costliest iterations (of {len(breakdown.rows())} rows; --json --breakdown has them all):")
    for row in rows:
        parts = ", ".join(f"{k} {v}" for k, v in zip(KINDS, row[3:]) if v)
        lines.append(f"  iteration {row[0]} ({row[1]}, {row[2]} hypotheses): {sum(row[3:])} = {parts}")
    return "\n".join(lines)


def _write_map(path: str | None, outcome) -> str | None:
    """Write the final map to ``path`` (``--map``); None when written (or not asked for), else why not.

    Only a run that ended with a map writes one: an algorithm that stopped (outcome ``failed`` or ``limit``,
    e.g. §5.1's walk found no lighthouse) has none; a run the checker stopped before the algorithm
    finished (its first violation, under an explicit lighthouse) has none either.  A completed map the checker
    refutes (``wrong-map``) is written all the same — it is what the algorithm claims, to be compared with the
    world — and the outcome, never ``--map``, decides the exit code.
    """
    if not path:
        return None
    S = getattr(outcome.explorer, "S", None)
    if outcome.claimed == "unfinished":
        return "the checker stopped the run at its first violation, before the algorithm had a map"
    if outcome.claimed != "correct":
        return f"the algorithm stopped without a map (outcome {outcome.outcome})"
    if S is None or not S.complete():
        return "the algorithm keeps no single completed map"
    write_output(path, dumps_world(S.to_world()))
    return None


def _print_report(args, spec, label: str, policies, outcome, started: float, tail: list[str]) -> None:
    """The human-readable report: what ran, the table, and the outcome — claimed by the algorithm, judged by
    the checker (``spec.errors.OUTCOMES``: ``correct``, ``wrong-map``, ``failed``, ``limit``)."""
    setup = f"lighthouse {outcome.lighthouse}" if spec.uses_lighthouse else f"kit: {outcome.kit}"
    used = spec.policies_json(policies)  # only the kinds the algorithm consults
    print(f"explored {label} with {spec.thesis} ({args.algorithm}; {setup}; "
          + ("policies " + ", ".join(f"{k}={v}" for k, v in used.items()) if used else "no policies") + ")")
    print(_table(outcome, started, spec))
    if outcome.violation is not None:
        print(f"VIOLATION: {outcome.violation}")
        print("the trace up to that point (last events; --trace FILE keeps all of it):")
        print("\n".join(f"  {line}" for line in tail))
    elif outcome.reason is not None:
        print(f"outcome: {outcome.outcome} — the algorithm stopped: {outcome.reason}")
    elif args.no_check:
        print("not checked (--no-check): the map was not verified")
    else:
        at_end = ("iterations", "cost-bound")  # judged once, at the end (with the isomorphism)
        stepwise = ", ".join(c for c in spec.checks if c != "isomorphism" and c not in at_end)
        ended = " and ".join(c for c in spec.checks if c in at_end)
        print("verified: the map is extended-isomorphic to the world (markers included); "
              f"{stepwise} held after every step" + (f"; {ended} held at the end" if ended else ""))

"""Running ``topomark algorithms`` (its description and options: :mod:`topomark.reference.cli.options.algorithms`).

The JSON form is a list of objects with ``name``, ``thesis``, ``kit``,
``bound``, ``markers``, ``deterministic``, ``options``, ``checks``,
``family`` (the algorithm family its trace@2 traces are written in), ``parameters``,
``kit_from_world``, ``bound_checked`` (the exact bound is the ``cost-bound`` check of every
checked run), ``bound_note`` (how the bound is held: checked per run, measured by a bench, or none stated)
``policies`` (the policies its runs take unless ``--policy`` chooses others: the kinds it declares, with their
defaults; empty for an algorithm that consults none) and ``status`` (``implemented``, or ``implemented, expected to fail`` with ``status_reason``: the thesis references
and the world where it fails) and, for the lighthouse algorithms, ``lighthouses``
(:meth:`topomark.reference.algorithms.algorithm_spec.AlgorithmSpec.to_json`).  The algorithms of the thesis
that are not implementable from it are listed too, in their place, with only ``name``, ``thesis``, ``status``
(``not implementable from the thesis``) and ``status_reason``; ``topomark explore`` refuses them.
"""

from __future__ import annotations

import json

from topomark.reference.algorithms.registry import CHECKS, Listed, listing

__all__ = ["algorithms_command"]


def algorithms_command(args) -> int:
    specs = listing()
    if args.json:
        print(json.dumps([s.to_json() for s in specs], indent=1))
        return 0
    width = max(len(s.name) for s in specs)
    for s in specs:
        print(f"{s.name:<{width}}  {s.thesis}")
        if isinstance(s, Listed):
            print(f"{'':<{width}}  status: {s.status}: {s.reason}")
            continue
        reason = f": {s.status_reason}" if s.status_reason else ""
        print(f"{'':<{width}}  status: {s.status}{reason}")
        kit = f"computed from n and m ({s.markers})" if s.kit_fn is not None else s.kit.describe()
        lighthouse = "; lighthouse: any (--lighthouse)" if s.uses_lighthouse else ""
        print(f"{'':<{width}}  kit: {kit}{lighthouse}; bound: {s.bound or 'none stated in the thesis'}")
        if s.bound:
            print(f"{'':<{width}}  bound held: {s.bound_note}")
        if s.policy_kinds:
            print(f"{'':<{width}}  policies (default; --policy): "
                  + ", ".join(f"{k}={v}" for k, v in s.policies_json(s.policies()).items()))
        if s.parameters:
            print(f"{'':<{width}}  options: " + ", ".join(f"--{p.name} (default {p.default})" for p in s.parameters))
    print(f"\nchecks: " + "; ".join(f"{k} = {v}" for k, v in CHECKS.items()))
    return 0

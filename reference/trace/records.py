"""The trace's records (``spec/trace.md``): the format names, the header, marker operations and the end.

A run's trace is built here and nowhere else: :func:`trace_header` opens it,
:func:`op_record` turns the simulator's marker operations into records,
:func:`end_record` closes it and :func:`dump_trace` writes it byte-for-byte
reproducibly.  The robot's moves and each family's algorithm-layer records
are made by the simulator and :mod:`~topomark.reference.trace.families`.

Examples
--------
>>> dump_trace([{"event": "end", "cost": 3}])
'{"cost":3,"event":"end"}\\n'
"""

from __future__ import annotations

from typing import cast

from topomark.spec.kit import Kit
from topomark.spec.world import World

from topomark.reference.explorers.lighthouses import Lighthouse
from topomark.reference.explorers.policies import Policies
from topomark.reference.trace.families import family_of
from topomark.reference.trace.sink import trace_line

__all__ = ["TRACE_FORMAT", "TRACE_FORMAT_2", "trace_header", "op_record", "end_record", "dump_trace"]

TRACE_FORMAT = "topomark/trace@1"
TRACE_FORMAT_2 = "topomark/trace@2"


def trace_header(algorithm: str, policies: Policies, light: Lighthouse | None, world: World,
                 kit: Kit | None = None, family: str | None = None, options: dict | None = None) -> dict:
    """The trace's first record: trace@1 for Algorithm 3.1's own lighthouse (byte-for-byte as before trace@2
    existed), trace@2 with the algorithm's family, the lighthouse (null for a kit algorithm) and the kit for
    every other run, and ``options`` — a kit algorithm's options given other than their defaults, so that
    replay re-runs it as it ran — when there are any."""
    header = {"event": "header", "format": TRACE_FORMAT, "algorithm": algorithm, "policies": policies.to_json(),
              "n": world.n, "m": world.m}
    if light is None or light.name != "directional-vertex":
        header.update(format=TRACE_FORMAT_2, family=family or family_of(algorithm).name,
                      lighthouse=None if light is None else light.name,
                      kit=(cast(Lighthouse, light).kit if kit is None else kit).to_json())  # a kit run gives its kit
        if options:
            header["options"] = dict(sorted(options.items()))
    return header


def op_record(event: dict, light: Lighthouse | None) -> dict:
    """A marker operation from the simulator's log (streamed as the robot does it, between its moves): trace@2's
    ``op`` record, or trace@1's ``drop`` for the directional vertex marker, the only one trace@1 can say."""
    if light is not None and light.name == "directional-vertex":
        return {"event": "drop", "direction": event.get("direction"), "signature": event["signature"]}
    return {"event": "op", **event}


def end_record(outcome) -> dict:
    """The trace's last record; a run that stopped early (trace@2 only: Algorithm 3.1's own lighthouse never
    stops) says how and why."""
    end = {"event": "end", "cost": outcome.cost, "verified": outcome.verified,
           "violation": outcome.violation.to_json() if outcome.violation else None}
    if outcome.reason is not None:  # the algorithm stopped itself (failed, limit)
        end.update(outcome=outcome.claimed, reason=outcome.reason)
    return end


def dump_trace(trace: list[dict]) -> str:
    """JSON Lines, keys sorted, no whitespace: byte-for-byte reproducible (what a FileSink streams)."""
    return "".join(trace_line(rec) for rec in trace)

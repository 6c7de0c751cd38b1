"""Which registered explorer an Algorithm 3.1-family trace's moves are: the listing's or topomark's variant (§4.1–4.2).

Where topomark registers both its variant of a Chapter 4 listing and the listing as written (``enh3`` and
``enh3-listing`` for Algorithm 4.3, ``enh4``/``enh4-listing`` for Algorithm 4.4, ``enh5-d2``/``enh5-d2-listing``
for Algorithm 4.5 with d = 2), a trace naming either is judged by Algorithm 3.1's algorithm layer
(:mod:`~topomark.reference.replay.algorithm31_layer`) — its claims, whatever choices the recorder made — and
:class:`VariantMatch` says besides whose moves it made: both explorers are re-run on the world with the header's
policies and lighthouse, each trace ``move`` (and marker operation) is compared with each live re-run's next, a
re-run the trace leaves is dropped, and :attr:`VariantMatch.followed` is the first still live at the end (replay's
``rerun``), or None.

Decision: unlike the ``robot`` family's re-run layer (:mod:`~topomark.reference.replay.rerun_layer`), which is that
family's only algorithm layer, this comparison judges nothing: a trace that follows neither explorer's moves — a
program that made another choice the thesis leaves open (§3.3: "any" edge, hypothesis order, path) — is still
accepted when every claim holds, and the result says it follows neither.  Only the robot layer's records are
compared (a recorder's iteration records may word its counters differently); a lighthouse's own options (a
search walk's seed) are not in the header, so a re-run uses the lighthouse's defaults.
"""

from __future__ import annotations

from typing import Any

from topomark.spec.world import World

from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec
from topomark.reference.algorithms.registry import REGISTRY
from topomark.reference.explorers.policies import Policies
from topomark.reference.replay.rerun_layer import _END, _Rerun, _Stop, alternatives
from topomark.reference.run.explore import explore
from topomark.reference.trace.header import header_lighthouse

__all__ = ["VariantMatch", "paired"]

_BROKEN = object()  # a re-run that raised: no trace record is its next
_ROBOT = ("move", "op", "drop")
"""The robot layer's records (trace@1's ``drop`` included): what the comparison looks at."""


def paired(header: dict[str, Any]) -> AlgorithmSpec | None:
    """The registered Algorithm 3.1-family entry a header names, where it has a listing or a variant registered
    beside it (:func:`~topomark.reference.replay.rerun_layer.alternatives`), else None."""
    spec = REGISTRY.get(header["algorithm"])
    if spec is None or not spec.own or spec.family != "algorithm-3.1" or len(alternatives(spec)) < 2:
        return None
    return spec


class _Moves(_Rerun):
    """One explorer re-run with the header's lighthouse, handing over its robot-layer records only."""

    def __init__(self, world: World, spec: AlgorithmSpec, policies: Policies, light: Any):
        super().__init__(world, spec, policies, {})
        self.light = light

    def _run(self) -> None:
        last: object = _END
        try:
            explore(self.world, self.spec, self.policies, check=False, sink=self, lighthouse=self.light)
        except _Stop:
            return
        except Exception:  # a re-run that cannot run to its end names nothing: the trace then follows neither
            last = _BROKEN
        try:
            self._put(last)
        except _Stop:
            return

    def emit(self, record: dict) -> None:
        if record["event"] in _ROBOT:
            self._put(record)


class VariantMatch:
    """``spec`` and its listing (or variant) re-run beside the trace; :meth:`record` drops those it leaves."""

    def __init__(self, world: World, header: dict[str, Any], spec: AlgorithmSpec):
        policies = Policies(**header["policies"])
        self.specs = alternatives(spec)
        self.runs = [_Moves(world, s, policies, header_lighthouse(header)) for s in self.specs]

    @property
    def followed(self) -> AlgorithmSpec | None:
        """The explorer whose moves the trace made (the first still live), or None."""
        return self.runs[0].spec if self.runs else None

    def record(self, rec: dict[str, Any]) -> None:
        """Compare a trace record of the robot layer with each live re-run's next; the end with theirs."""
        if rec["event"] not in _ROBOT and rec["event"] != "end":
            return
        for run in list(self.runs):
            want = run.next()
            if (rec["event"] == "end") != (want is _END) or (want is not _END and want != rec):
                run.close()
                self.runs.remove(run)

    def close(self) -> None:
        for run in self.runs:
            run.close()

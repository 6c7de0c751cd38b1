"""Replaying the algorithm layer of a registered kit algorithm: its explorer re-run beside the trace (``spec/trace.md``).

A trace of the ``robot`` family records what the robot did and nothing of
what the algorithm believed: no map, no iterations.  Its end's claims — a
verified run, a violation, or a stop (``outcome`` ``failed``/``limit`` with a
reason) — say something about the algorithm, which the robot layer alone
cannot judge.  For an algorithm topomark runs itself (registered with
``family="robot"``: the Chapter 6 algorithms, Dudek et al.'s movable marker,
the tree of models), :class:`RerunLayer` is that algorithm layer: the
registered explorer is re-run on the world with the header's policies and
``options`` (a checked run: every check its registry entry names, the final
map extended-isomorphic to the world with the markers the ops left there),
and the trace must be that run, record for record:

* the header's kit is the kit the algorithm carries on this world (its
  ``kit_fn`` of n, m and the options, §6.2's Σ k markers, Case 2's m + n, …):
  a smaller or a larger one is a false claim (check ``marker kit``);
* every move and op is the one the algorithm makes next (so an operation
  left out — the last pick-up of a movable marker, the last drop — is found
  where it is missing, and the world's markers at the end are the map's);
* the end's ``cost``, ``verified``, ``violation``, ``outcome`` and ``reason``
  are the re-run's: a ``failed`` claim for a run that maps the world is
  false, and so is a verified claim for a run that runs out of markers
  (``OutOfMarkers``: the kit really was exhausted) or whose map is wrong.
  An unjudged end (``verified: false``, no violation, no outcome: ``explore
  --no-check``) claims nothing and takes the re-run's verdict.

**The listing and topomark's variant.**  Where topomark registers both its variant of a listing and the
listing as written (Algorithm 6.7: ``thread-circumference``, which skips a search its record makes needless,
and ``thread-circumference-listing``, §6.3.2; the tree of models, ``model-tree`` and ``model-tree-listing``,
Algorithm 5.1), a trace naming either is compared with both re-runs at
once: a re-run the trace leaves is dropped, the trace is accepted when it follows either to the end, and the
result says which (:attr:`RerunLayer.followed`; ``replay --json``'s ``rerun``).  When it follows neither,
the divergence reported is that of the re-run it followed longest (the named one on a tie).

Decision (the thesis leaves an algorithm's choices open only where §3.3 and
Chapter 6 say "any"; topomark's explorers make each one by a named,
deterministic rule): the re-run is topomark's own explorer, so a trace of a
registered algorithm recorded by another implementation that chose
differently is reported where it first differs.  Such a recorder should name
its algorithm as its own (any other name): the ``robot`` family then judges
what the robot did only, and replay refuses any end claim it cannot check
(:mod:`~topomark.reference.replay.replay`).

The explorer runs in a thread of its own, a bounded number of records ahead
of the trace, so a long trace is still read one line at a time and the re-run never
goes further than the trace does.
"""

from __future__ import annotations

import contextlib
import json
import queue
import threading
from typing import Any

from topomark.spec.errors import InvalidInput, Violation, clip
from topomark.spec.kit import Kit
from topomark.spec.world import World

from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec, in_family
from topomark.reference.explorers.policies import Policies
from topomark.reference.replay.divergence import Diverged, diverge
from topomark.reference.run.explore import explore

__all__ = ["RerunLayer", "rerun_spec", "alternatives"]

_END = object()  # the re-run ended (after its end record)


class _Stop(BaseException):
    """Raised in the re-run's thread to end it once replay needs no more of its records."""


def rerun_spec(header: dict[str, Any]) -> AlgorithmSpec | None:
    """The registered kit algorithm a ``robot``-family header names, or None (an algorithm topomark does not run)."""
    if header.get("family") != "robot" or header["algorithm"] not in in_family("robot"):
        return None
    spec = algorithm_spec(header["algorithm"])
    return spec if spec.own else None


def alternatives(spec: AlgorithmSpec) -> list[AlgorithmSpec]:
    """The explorers a trace naming ``spec`` may follow: ``spec``'s own, and the thesis's listing as written where
    ``spec`` is topomark's variant of it (its ``listing_entry``) — or that variant where ``spec`` is the listing
    (Algorithm 6.7: ``thread-circumference`` and ``thread-circumference-listing``)."""
    out = [spec]
    if spec.listing_entry is not None and spec.listing_entry in REGISTRY:
        out.append(REGISTRY[spec.listing_entry])
    out += [s for s in REGISTRY.values() if s.listing_entry == spec.name and s.name != spec.name]
    return out


class _Rerun:
    """One registered explorer re-run on the world in a thread of its own, its records handed over one by one."""

    def __init__(self, world: World, spec: AlgorithmSpec, policies: Policies, given: dict[str, Any]):
        self.world, self.spec, self.policies, self.given = world, spec, policies, given
        self._queue: queue.Queue = queue.Queue(maxsize=4096)
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def _run(self) -> None:
        try:
            explore(self.world, self.spec, self.policies, check=True, sink=self, options=self.given)
            last: Any = _END
        except _Stop:
            return  # replay has stopped reading: the re-run ends with nothing more to hand over
        except BaseException as exc:  # handed to the replay, which raises it (topomark's own failure)
            last = exc
        with contextlib.suppress(_Stop):  # replay may stop reading before it takes the last item
            self._put(last)

    def _put(self, item: Any) -> None:
        while not self._stop.is_set():
            try:
                self._queue.put(item, timeout=0.05)
                return
            except queue.Full:
                continue
        raise _Stop

    def emit(self, record: dict) -> None:
        """The re-run's trace sink: its records, one at a time, to :meth:`next`."""
        self._put(record)

    def next(self) -> Any:
        if self._thread is None:
            self._thread = threading.Thread(target=self._run, name="topomark-replay-rerun", daemon=True)
            self._thread.start()
        item = self._queue.get()
        if isinstance(item, BaseException):
            raise item
        return item

    def close(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()


class RerunLayer:
    """The registered explorer — and the thesis's listing or topomark's variant of it, where both are registered
    (:func:`alternatives`) — re-run on ``world``; :meth:`record` compares each trace record with each live re-run's
    next, drops a re-run the trace leaves, and reports the divergence when none is left.  :attr:`followed` names
    the re-run the trace follows (the first still live)."""

    def __init__(self, world: World, header: dict[str, Any], spec: AlgorithmSpec, source: str):
        where = f"{source} line 1"
        self.given = header.get("options", {})  # as the header gives them; explore parses them again
        try:
            self.options = spec.parse_options(self.given)
            self.policies = Policies(**header["policies"])
        except (InvalidInput, TypeError) as exc:
            raise InvalidInput(f"{where}: header.options/policies: not an option set {spec.name} takes ({exc})") from None
        self.spec, self.world, self.header = spec, world, header
        self.kit = spec.kit_for(world.n, world.m, self.options)
        self.runs = [_Rerun(world, s, self.policies, self.given) for s in alternatives(spec)
                     if s.kit_for(world.n, world.m, s.parse_options(self.given)) == self.kit]
        self.dropped: list[AlgorithmSpec] = []  # the alternatives the trace has left, in the order it left them

    @property
    def followed(self) -> AlgorithmSpec:
        """The explorer the trace follows so far: the first re-run still live."""
        return self.runs[0].spec

    def close(self) -> None:
        """Stop the re-runs (replay needs no more of them)."""
        for run in self.runs:
            run.close()

    # -- the comparison --------------------------------------------------------------
    def begin(self) -> None:
        """The header: its kit must be the algorithm's on this world."""
        for run in self.runs:
            assert run.next()["event"] == "header"
        claimed = Kit.from_json(self.header["kit"])
        if claimed != self.kit:
            diverge("header", f"the kit {self.spec.name} carries on this world (n={self.world.n}, m={self.world.m}"
                              f"{_given(self.header)}): {json.dumps(self.kit.to_json())} ({self.kit.describe()})",
                    f"{json.dumps(self.header['kit'])} ({claimed.describe()})", check="marker kit")

    def record(self, rec: dict[str, Any], where: str) -> None:
        """The trace's next record must be a live re-run's next (its end: the re-run's verdict, below)."""
        first: tuple[Diverged, AlgorithmSpec] | None = None
        for run in list(self.runs):
            try:
                self._compare(run, rec, where)
            except Diverged as exc:
                if len(self.runs) == 1:  # the explorer followed longest (on a tie, the named one)
                    raise self._neither(*(first or (exc, run.spec))) from None
                first = first or (exc, run.spec)
                run.close()
                self.runs.remove(run)
                self.dropped.append(run.spec)

    def _neither(self, exc: Diverged, reported: AlgorithmSpec) -> Diverged:
        """The divergence, saying which other explorers the trace left too (the listing or the variant)."""
        others = [s for s in (*self.dropped, *(r.spec for r in self.runs)) if s.name != reported.name]
        if not others:
            return exc
        v = exc.violation
        left = ", ".join(f"{s.name} ({s.variant_json()['follows']})" for s in others)
        return Diverged(Violation(v.check, v.where, v.expected, v.found, f"{v.detail}; the trace follows neither "
                                  f"this explorer nor {left}, registered beside it"))

    def _compare(self, run: _Rerun, rec: dict[str, Any], where: str) -> None:
        want, name = run.next(), run.spec.name
        if want is _END:
            diverge(where, f"the end of {name}'s run", _show(rec), "the algorithm, re-run, stops here",
                    check="algorithm")
        if rec["event"] == "end" and want["event"] == "end":
            return self._end(rec, want, name)
        if rec != want:
            detail = ("the algorithm, re-run on the world, does this next; a record left out or added, or a "
                      "different choice")
            diverge(where, f"{_show(want)} ({name}, re-run)", _show(rec), detail, check="algorithm")

    def _end(self, rec: dict[str, Any], want: dict[str, Any], name: str) -> None:
        if not rec["verified"] and rec["violation"] is None and "outcome" not in rec:
            if want["violation"] is not None:  # an unjudged run: the re-run's verdict stands
                raise Diverged(_violation(want))
            return
        if _claim(rec) != _claim(want):
            diverge("end", f"{_words(want)} (what {name}, re-run on the world and checked, ends with)",
                    _words(rec), "the end record's claim about the run is false", check="trace claim")
        if want["violation"] is not None:  # the trace records the failure the re-run finds
            raise Diverged(_violation(want))


def _claim(end: dict) -> tuple:
    return end["verified"], end["violation"], end.get("outcome"), end.get("reason")


def _words(end: dict) -> str:
    if end["verified"]:
        return "a verified run (the map extended-isomorphic to the world)"
    if end["violation"] is not None:
        return f"a violation: {_violation(end)}"
    if "outcome" in end:
        return f"a stopped run: {end['outcome']} ({end['reason']})"
    return "an unjudged run"


def _violation(end: dict) -> Violation:
    v = end["violation"]
    return Violation(v["check"], v["where"], v["expected"], v["found"], v["detail"])


def _given(header: dict) -> str:
    options = header.get("options")
    return f", options {json.dumps(options, sort_keys=True)}" if options else ""


def _show(rec: dict) -> str:
    return clip(json.dumps(rec, sort_keys=True, separators=(",", ":")), 200, note="")

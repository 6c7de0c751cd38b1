"""A replayed run as frames: one per trace record, with where the robot truly was (``spec/trace.md``, §3.3).

A trace records what the explorer knows; the viewer also shows the truth. So
the frames are taken while :func:`~topomark.reference.replay.replay.replay`
re-executes the trace on its world (its ``observe`` hook): frame *k* is the
state after the trace's line *k + 1* — the header (frame 0), each marker
``op`` or ``drop``, each ``move``, each ``iteration``, the ``end``.  Per frame:

* the robot's true state (vertex, entry exit: relative exit 0, §3.1.1);
* for a move, its *kind of walk* as the cost breakdown splits it
  (:data:`~topomark.reference.run.breakdown.KINDS`, §3.5.2): its purpose, and a
  validation move further split by the outcome of the hypothesis it tested —
  each iteration's validation moves come in runs, one per hypothesis tested
  with motion, in the order listed (Algorithm 3.1 lines 11–17: a rejected
  hypothesis's walk ends in its retrace); when the runs and the hypotheses do
  not pair off (an explorer that validates along a trie, §4.1), each tested
  hypothesis takes as many moves as it perceived, and moves left over are
  ``validation other``;
* the hypothesis under test (its index in the iteration's H, or -1).

Beside the frames: the markers and the thread after every frame that changed
them, Algorithm 3.1's iterations (e, the join, H with each hypothesis's M,
P^E, outcome and perceptions) with the world vertex each map vertex stands
for — v0 where the lighthouse was established (φ's anchor), a new vertex v_u
where the ``new`` move arrived — and the replay's verdict. Frames stop at
the first divergence: the run up to it.
"""

from __future__ import annotations

from array import array
from dataclasses import dataclass, field
from typing import Any

from topomark.spec.errors import Violation
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.world import Start, World

from topomark.reference.replay.replay import ReplayResult, replay
from topomark.reference.run.breakdown import CASES, KINDS

__all__ = ["RunFrames", "take_frames", "RECORD_KINDS"]

RECORD_KINDS = ("header", "drop", "op", "move", "iteration", "end")
"""The record kinds, in the order of their codes in :attr:`RunFrames.kind`."""

_WALK = {k: n for n, k in enumerate(KINDS)}
_WITHOUT_MOTION = ("overlap", "map")


@dataclass
class RunFrames:
    """The frames of one replayed run (columns indexed by frame) and what lies beside them."""

    world: World  # the world's rotation and start, without markers: what is drawn
    header: dict[str, Any]
    kind: array = field(default_factory=lambda: array("i"))  # RECORD_KINDS index
    vertex: array = field(default_factory=lambda: array("i"))  # the robot's true vertex (index in world.vertices)
    entry: array = field(default_factory=lambda: array("i"))  # its entry exit there (relative exit 0)
    walk: array = field(default_factory=lambda: array("i"))  # a move's KINDS index, else -1
    hyp: array = field(default_factory=lambda: array("i"))  # the hypothesis under test (index in H), else -1
    markers: list[list[Any]] = field(default_factory=list)  # [frame, [marker, ...]] after each change
    thread: list[list[Any]] = field(default_factory=list)  # [frame, [vertex, ...] laid walk, held] after each change
    iterations: list[dict[str, Any]] = field(default_factory=list)
    ops: list[list[Any]] = field(default_factory=list)  # [frame, words] for each marker or thread operation
    v0: list[int] | None = None  # [frame, world vertex, exit offset]: map v0 once established
    result: ReplayResult | None = None
    failure: Violation | None = None  # a verdict given beside the trace (a conformance run's), shown at its end

    def judged(self) -> tuple[Violation | None, int | None, int | None]:
        """The failure shown, its frame and its line: replay's divergence, else the verdict given beside the
        trace (at the last frame), else none."""
        r = self.result
        if r is not None and not r.ok and r.divergence is not None and r.line is not None:
            return r.divergence, r.line - 1, r.line
        if self.failure is not None:
            return self.failure, self.frames - 1, self.frames
        return None, None, None

    @property
    def frames(self) -> int:
        return len(self.kind)

    @property
    def divergence_frame(self) -> int | None:
        """The frame of the record replay diverged at, or None."""
        r = self.result
        return None if r is None or r.ok or r.line is None else r.line - 1


def _drawn(bare: World, given: World) -> World:
    """The world drawn: its rotation without markers, its start (the default one, as ``world --draw`` shows it,
    when the file gives none)."""
    at, exit_ = given.start_state()
    return bare.with_markers((), Start(at, bare.neighbour(at, exit_)))


def _walk(purpose: str) -> int:
    """A move's kind of walk before its iteration splits validation by outcome."""
    return _WALK["validation other" if purpose == "validation" else purpose if purpose in _WALK else "other"]


def _marker(m: VertexMarker | EdgeMarker, index: dict[str, int]) -> list[Any]:
    """A marker as a short list: ``["v", at, count, points_to | -1]`` or ``["e", u, v, count, head | -1]``."""
    if isinstance(m, VertexMarker):
        return ["v", index[m.at], m.count, -1 if m.points_to is None else index[m.points_to]]
    u, v = m.between
    return ["e", index[u], index[v], m.count, -1 if m.head is None else index[m.head]]


class _Observer:
    """Replay's observer: appends a frame per record (see the module's docstring)."""

    def __init__(self, frames: RunFrames):
        self.f = frames
        self.index: dict[str, int] = {}
        self.last_markers: tuple = ()
        self.last_thread: tuple = (None, 0, None, True)
        self.moves: list[int] = []  # the frames of the current iteration's moves
        self.new_state: tuple[str, int] | None = None

    def __call__(self, r: Any, rec: dict[str, Any], line: int) -> None:
        f, sim = self.f, r.robot.sim
        if line == 1:
            f.world = _drawn(sim.base_world, f.world)
            self.index = {v: k for k, v in enumerate(f.world.vertices)}
        frame = len(f.kind)
        assert frame == line - 1, "one frame per trace line, in order"
        v, entry = sim.state
        event = rec["event"]
        f.kind.append(RECORD_KINDS.index(event))
        f.vertex.append(self.index[v])
        f.entry.append(entry)
        f.walk.append(_walk(rec["purpose"]) if event == "move" else -1)
        f.hyp.append(-1)
        if event == "move":
            self.moves.append(frame)
            if rec["purpose"] == "new":
                self.new_state = sim.state
        self._markers(sim, frame)
        if event in ("op", "drop"):
            what = "drop directional vertex marker" if event == "drop" else \
                f"{rec['op'].replace('_', ' ')} {'thread' if rec['kind'] == 'thread' else rec['kind'] + ' marker'}"
            f.ops.append([frame, f"{what} at {v}"])
        alg = r.algorithm
        if f.v0 is None and alg is not None and alg.S is not None:
            f.v0 = [frame, self.index[alg.anchor[0]], alg.anchor[1]]
        if event == "iteration":
            self._iteration(rec, frame, sim)

    def _markers(self, sim: Any, frame: int) -> None:
        layer = sim.layer
        now = tuple(layer.markers())
        if now != self.last_markers:
            self.last_markers = now
            self.f.markers.append([frame, [_marker(m, self.index) for m in now]])
        t = layer.thread
        key = (t.tied, len(t.laid), t.laid[-1] if t.laid else None, t.held)
        if key != self.last_thread:
            self.last_thread = key
            walk = [] if t.tied is None else [t.tied] + [sim.world.target(d)[0] for d in t.laid]
            self.f.thread.append([frame, [self.index[w] for w in walk], t.held])

    def _iteration(self, rec: dict[str, Any], frame: int, sim: Any) -> None:
        hyps = rec["hypotheses"]
        place = None
        if rec["augmentation"] == "non-loop" and self.new_state is not None:
            (u, j), (w, entry) = rec["joined"][1], self.new_state
            place = [u, self.index[w], (entry - j) % sim.world.degree(w)]
        self.f.iterations.append({
            "frame": frame, "iteration": rec["iteration"], "edge": rec["edge"], "joined": rec["joined"],
            "augmentation": rec["augmentation"], "by_marker": rec["by_marker"], "signature": rec["signature"],
            "place": place,
            "hypotheses": [[h["dart"], h["motions"], h["expected"], h["outcome"], h["perceived"],
                            h.get("rejected_by")] for h in hyps]})
        self._attribute(hyps)
        self.moves, self.new_state = [], None

    def _attribute(self, hyps: list[dict[str, Any]]) -> None:
        """Each validation move's hypothesis and case (the module's docstring); retraces follow their hypothesis."""
        f = self.f
        tested = [k for k, h in enumerate(hyps) if h["outcome"] in CASES and h.get("rejected_by") not in
                  _WITHOUT_MOTION]
        runs: list[list[int]] = []
        previous = None
        for frame in self.moves:
            if f.walk[frame] == _WALK["validation other"]:
                if previous != frame - 1 or not runs:
                    runs.append([])
                runs[-1].append(frame)
                previous = frame
        if len(runs) != len(tested):  # no pairing: each tested hypothesis takes what it perceived
            flat = [x for run in runs for x in run]
            runs = []
            for k in tested:
                take = len(hyps[k]["perceived"])
                runs.append(flat[:take])
                flat = flat[take:]
        current = -1
        for k, run in zip(tested, runs):
            for frame in run:
                f.walk[frame] = _WALK[f"validation {hyps[k]['outcome']}"]
                f.hyp[frame] = k
        for frame in self.moves:  # a retrace belongs to the hypothesis just walked
            if f.hyp[frame] >= 0:
                current = f.hyp[frame]
            elif f.walk[frame] == _WALK["retrace"]:
                f.hyp[frame] = current


def take_frames(world: World, records: Any, source: str) -> RunFrames:
    """Replay ``records`` (:func:`~topomark.reference.replay.replay.load_trace`'s) on ``world``, taking a frame
    per record up to the first divergence; bad input is replay's :class:`~topomark.spec.errors.InvalidInput`."""
    frames = RunFrames(world, {})
    records = iter(records)
    first = next(records)
    frames.header = first

    def chained():
        yield first
        yield from records

    frames.result = replay(world, chained(), source, observe=_Observer(frames))
    return frames

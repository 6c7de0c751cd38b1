"""Viewing a trace: replay it on its world, take its frames and write the page (``topomark view``).

:func:`view_trace` is the one way every command writes a viewer page — ``view``, ``explore --view``, ``replay
--view`` and ``conformance run --view-failures`` — so a trace's bad input is always replay's own message
(:func:`~topomark.reference.replay.replay.load_trace`, :func:`~topomark.reference.replay.replay.replay`: exit 2)
and a trace that diverges is still drawn, up to the divergence, with the divergence beside it.
"""

from __future__ import annotations

from pathlib import Path

from topomark.spec.errors import Violation
from topomark.spec.world import World

from topomark.reference.files.outputs import write_output
from topomark.reference.replay.replay import load_trace
from topomark.reference.viewer.frames import RunFrames, take_frames
from topomark.reference.viewer.page import page
from topomark.reference.viewer.world_of_trace import world_of_trace

__all__ = ["view_trace", "default_output"]


def default_output(trace: str | Path) -> str:
    """Where ``view TRACE`` writes without ``-o``: beside the trace, its suffix replaced by ``.html``."""
    return str(Path(trace).with_suffix(".html"))


def view_trace(trace: str | Path, world: World | None, output: str | Path, title: str | None = None,
               failure: Violation | None = None) -> RunFrames:
    """Replay the trace file ``trace`` on ``world`` (None: the world its own final map gives) and write its page
    to ``output``; returns the frames, whose ``result`` is replay's verdict.  ``failure`` is a verdict given
    beside the trace (a conformance run's: what the reference expected, what the program did), shown at its end
    when replay itself finds nothing."""
    if world is None:
        world = world_of_trace(trace)
    frames = take_frames(world, load_trace(trace), str(trace))
    frames.failure = failure
    write_output(output, page(frames, title or Path(trace).name))
    return frames

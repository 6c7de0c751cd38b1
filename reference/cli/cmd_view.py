"""``topomark view``: a trace's page for the browser (:mod:`topomark.reference.viewer`).

Its options are :mod:`topomark.reference.cli.options.view`'s; this module is imported when it runs."""

from __future__ import annotations

from pathlib import Path
from typing import cast

from topomark.spec.errors import InvalidInput
from topomark.spec.worldfile import load_world

from topomark.reference.cli.parser import emit
from topomark.reference.files.overwrite import claim_file
from topomark.reference.replay.replay import ReplayResult
from topomark.reference.viewer.view import default_output, view_trace

__all__ = ["view_command"]


def view_command(args) -> int:
    output = default_output(args.trace) if args.output is None else args.output
    if Path(output).resolve() == Path(args.trace).resolve():
        raise InvalidInput(f"-o: the page would be written over the trace {args.trace} itself; name another with -o")
    claim_file(output, "-o", args.force)
    world = load_world(args.world) if args.world else None
    frames = view_trace(args.trace, world, output)
    result = cast(ReplayResult, frames.result)
    data = {"trace": args.trace, "world": args.world, "page": output, "frames": frames.frames,
            "verified": result.ok, "message": result.message, "line": result.line}
    emit(args, data, f"wrote {output}: {frames.frames:,} line{'s' if frames.frames != 1 else ''} of {args.trace}, "
                     + ("verified" if result.ok else f"DIVERGED {result.message}"))
    return 0 if result.ok else 1

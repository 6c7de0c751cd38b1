"""The JSON log of one problem played on the contest server (``topomark contest serve --log-dir DIR``).

One file per problem played, from its ``/select`` to its ``/guess``: ``DIR/NNNNN-PROBLEM.json``, numbered in the
order problems were selected on the server.  It is rewritten whole after every request (written beside it, then
renamed over it), so it is always one complete JSON object:

``format``
    ``"topomark/contest-log@1"``.
``number``, ``problem``, ``round``, ``echo_marks``
    the problem's number on this server, its name, the round (``full`` or ``lightning``) and whether marks are
    echoed in records.
``hidden``
    the hidden map, as a contest map object (:func:`topomark.spec.port_icfpc.map_to_json`).
``exchanges``
    every request of this problem, in order: ``endpoint``, ``request`` (the body without its ``id``: an id is a
    secret and is never written), ``status`` (200 or 400), ``answer`` (the body sent back) and ``seconds`` since
    the problem was selected.
``queryCount``
    the query count after the last exchange.
``verdict``
    the ``/guess`` answer (``correct`` and, when wrong, ``witness`` and ``reason``), or null while the problem is
    still being played.
"""

from __future__ import annotations

import json
import os
import re
import time
from pathlib import Path
from typing import Any

from topomark.spec.port_icfpc import map_to_json
from topomark.spec.port_world import PortWorld

__all__ = ["SessionLog", "LOG_FORMAT", "LOG_GLOB"]

LOG_FORMAT = "topomark/contest-log@1"
LOG_GLOB = "[0-9][0-9][0-9][0-9][0-9]-*.json"
"""The names of the logs in a log directory (what ``--force`` replaces)."""

_SAFE = re.compile(r"[A-Za-z0-9_-]{1,64}")


class SessionLog:
    """The log of one problem (see the module's docstring)."""

    def __init__(self, folder: str | Path, number: int, problem: str, hidden: PortWorld, *, round_name: str,
                 echo_marks: bool):
        name = problem if _SAFE.fullmatch(problem) else "problem"
        self.path = Path(folder) / f"{number:05d}-{name}.json"
        self._start = time.monotonic()
        try:
            hidden_json: Any = map_to_json(hidden)
        except ValueError:  # a port world the contest's format cannot hold: its joins as they are
            hidden_json = {"colours": list(hidden.colours), "start": hidden.start, "joins": hidden.joins}
        self.record: dict[str, Any] = {"format": LOG_FORMAT, "number": number, "problem": problem,
                                       "round": round_name, "echo_marks": echo_marks, "hidden": hidden_json,
                                       "exchanges": [], "queryCount": 0, "verdict": None}

    def exchange(self, endpoint: str, body: dict[str, Any], status: int, answer: dict[str, Any]) -> None:
        """Add one request and its answer, and write the file."""
        request = {k: v for k, v in body.items() if k != "id"}
        self.record["exchanges"].append({"endpoint": endpoint, "request": request, "status": status,
                                         "answer": answer, "seconds": round(time.monotonic() - self._start, 6)})
        if "queryCount" in answer:
            self.record["queryCount"] = answer["queryCount"]
        if endpoint == "/guess" and status == 200:
            self.record["verdict"] = answer
        self.write()

    def write(self) -> None:
        """Write the log whole: beside its place, then renamed over it."""
        partial = self.path.with_name(self.path.name + ".partial")
        partial.write_text(json.dumps(self.record, indent=1) + "\n", encoding="utf-8")
        os.replace(partial, self.path)

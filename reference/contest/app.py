"""The contest's HTTP interface as an ASGI application (Starlette), around :class:`.game.Contest`.

``POST /register``, ``/select``, ``/explore`` and ``/guess`` take and give JSON as the contest's server did
(:mod:`.bodies`, :mod:`.game`).  A refused request is answered ``400`` with ``{"error": MESSAGE}`` — one message
naming what is wrong, never the request's id — and the server goes on serving; another method on those paths is
``405``, another path ``404``; a fault of the server itself is ``500`` with ``{"error": ...}``.  Each request runs
in a worker thread, so one long plan batch does not hold up the other sessions.

Starlette was chosen for being small and ASGI (served by uvicorn, which stops cleanly on Ctrl-C); the game itself
imports nothing of it.
"""

from __future__ import annotations

import json
import logging
from typing import Any

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import Response
from starlette.routing import Route

from topomark.reference.contest.bodies import KEYS, MAX_BODY_BYTES, BadRequest, read_body
from topomark.reference.contest.game import Contest

__all__ = ["build_app", "ENDPOINTS"]

ENDPOINTS = tuple(KEYS)

_log = logging.getLogger("topomark.contest")


def _json(status: int, data: dict[str, Any]) -> Response:
    return Response(json.dumps(data, separators=(",", ":")), status_code=status, media_type="application/json")


async def _body(request: Request, endpoint: str) -> bytes:
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > MAX_BODY_BYTES:
            raise BadRequest(f"{endpoint}: the body is over the {MAX_BODY_BYTES:,} bytes read")
        chunks.append(chunk)
    return b"".join(chunks)


def build_app(contest: Contest) -> Starlette:
    """The application serving ``contest``."""

    def endpoint(path: str):
        async def handle(request: Request) -> Response:
            try:
                body = read_body(path, await _body(request, path))
                return _json(200, await run_in_threadpool(contest.answer, path, body))
            except BadRequest as e:
                return _json(400, {"error": str(e)})
            except Exception as e:  # noqa: BLE001 - the server's own fault: answered 500, logged, still serving
                _log.exception("internal fault answering %s", path)
                return _json(500, {"error": f"internal fault: {e.__class__.__name__}: {e}"})
        return handle

    routes = [Route(path, endpoint(path), methods=["POST"]) for path in ENDPOINTS]
    app = Starlette(routes=routes)
    app.state.contest = contest
    return app

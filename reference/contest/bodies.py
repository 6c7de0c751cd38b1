"""The request bodies of the ICFP Contest 2025's HTTP interface, read strictly.

Every endpoint takes one JSON object (the contest's task statement, "Protocol"):

* ``/register`` ``{"name", "pl", "email"}`` (each a string, each optional here);
* ``/select`` ``{"id", "problemName"}``;
* ``/explore`` ``{"id", "plans": [plan, ...]}``, each plan a string;
* ``/guess`` ``{"id", "map": {"rooms", "startingRoom", "connections"}}`` (the map read by
  :func:`topomark.spec.port_icfpc.map_from_json`).

A body that is not such an object is refused with :class:`BadRequest`, one message naming the endpoint and what is
wrong: malformed JSON, a key the endpoint does not take (named, never its value), a missing key, a value of the
wrong type.  An ``id`` is never quoted back, in a refusal or anywhere else: a team's id is its secret.

Examples
--------
>>> read_body("/select", b'{"id": "t", "problemName": "probatio"}')
{'id': 't', 'problemName': 'probatio'}
>>> read_body("/select", b'{"id": "t", "problem": "probatio"}')
Traceback (most recent call last):
...
topomark.reference.contest.bodies.BadRequest: /select: unknown key 'problem' (a /select body has the keys id, problemName)
>>> read_body("/explore", b'{"id": 7, "plans": []}')
Traceback (most recent call last):
...
topomark.reference.contest.bodies.BadRequest: /explore: id is not a string
"""

from __future__ import annotations

from typing import Any

from topomark.spec.errors import InvalidInput, clip, require_input
from topomark.spec.jsontext import no_duplicate_keys, parse_json

__all__ = ["BadRequest", "read_body", "KEYS", "OPTIONAL", "MAX_BODY_BYTES", "MAX_ID_CHARS", "MAX_PLANS"]

MAX_BODY_BYTES = 16 << 20
"""The largest request body read (a /explore of thousands of plans at the largest problem's limit fits)."""

MAX_ID_CHARS = 1000
"""The longest id accepted."""

MAX_PLANS = 100_000
"""The most plans one /explore may carry."""

KEYS = {"/register": ("name", "pl", "email"), "/select": ("id", "problemName"), "/explore": ("id", "plans"),
        "/guess": ("id", "map")}
"""Each endpoint's keys."""

OPTIONAL = {"/register": ("name", "pl", "email")}
"""The keys an endpoint may go without (locally, registering needs no details)."""


class BadRequest(InvalidInput):
    """A request the server refuses with HTTP 400 (its message is the answer's ``error``)."""


def read_body(endpoint: str, raw: bytes) -> dict[str, Any]:
    """The JSON object of ``raw``, checked for ``endpoint``'s keys and types (see the module's docstring)."""
    require_input(len(raw) <= MAX_BODY_BYTES, f"{endpoint}: the body has {len(raw):,} bytes, over the "
                  f"{MAX_BODY_BYTES:,} read", BadRequest)
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise BadRequest(f"{endpoint}: the body is not UTF-8 text") from None
    try:
        body = parse_json(text, endpoint, BadRequest, object_pairs_hook=no_duplicate_keys)
    except InvalidInput as e:
        raise BadRequest(str(e)) from None
    allowed = KEYS[endpoint]
    require_input(isinstance(body, dict), f"{endpoint}: the body is not a JSON object", BadRequest)
    for key in body:
        require_input(key in allowed, f"{endpoint}: unknown key {clip(str(key), 40, quote=True)} (a {endpoint} body "
                      f"has the keys {', '.join(allowed)})", BadRequest)
    for key in allowed:
        require_input(key in body or key in OPTIONAL.get(endpoint, ()), f"{endpoint}: the key {key!r} is missing",
                      BadRequest)
    for key in ("id", "problemName", "name", "pl", "email"):
        if key in body:
            require_input(isinstance(body[key], str), f"{endpoint}: {key} is not a string", BadRequest)
    if "id" in body:
        require_input(0 < len(body["id"]) <= MAX_ID_CHARS, f"{endpoint}: id is empty or longer than "
                      f"{MAX_ID_CHARS:,} characters", BadRequest)
    if endpoint == "/explore":
        plans = body["plans"]
        require_input(isinstance(plans, list), f"{endpoint}: plans is not a list of strings", BadRequest)
        require_input(len(plans) <= MAX_PLANS, f"{endpoint}: {len(plans):,} plans, over the {MAX_PLANS:,} one "
                      "call may carry", BadRequest)
        for k, plan in enumerate(plans):
            require_input(isinstance(plan, str), f"{endpoint}: plans[{k}] is not a string", BadRequest)
    return dict(body)

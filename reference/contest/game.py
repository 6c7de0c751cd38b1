"""The contest's game, without HTTP: sessions keyed by id, selecting, exploring and guessing (ICFP Contest 2025).

:class:`Contest` answers the four requests of the contest's interface (:mod:`.bodies` reads their bodies) exactly
as the contest's task statement describes them, with topomark's port model (:mod:`topomark.spec.port_plan`):

* ``/register`` gives a new id.  Any id is accepted by the other endpoints, registered or not, so an explorer
  with an id of its own runs unchanged; each id is a session of its own, and many run at once.
* ``/select`` draws a hidden map of the named problem (:class:`.problems.Problems`), discarding any problem the
  session had, and sets its query count to 0.
* ``/explore`` runs each plan on the hidden map from its start (:func:`~topomark.spec.port_plan.run_plan`, each
  mark echoed unless the server runs without the echo) and adds :func:`~topomark.spec.port_plan.explore_cost` to
  the query count.  Every plan is checked before any is run: a plan outside the syntax or over the round's length
  limit (:func:`~topomark.spec.port_plan.check_length`; in the lightning round, any charcoal mark) refuses the
  whole request, which then costs nothing.
* ``/guess`` judges the map exactly against the hidden one (the judge given, :mod:`topomark.reference.port.judge`
  in the server) and ends the problem, right or wrong.  The answer carries ``correct``, as the contest's did, and,
  when wrong, ``witness``: a plan with the record it gives on the hidden map and on the guess, replayed here on
  both before it is sent; and ``reason``, the judge's words.  A contest client reads ``correct`` and ignores them.

A refused request raises :class:`~.bodies.BadRequest` (HTTP 400) and changes nothing.
"""

from __future__ import annotations

import secrets
import threading
from dataclasses import dataclass, field
from typing import Any, Callable

from topomark.spec.errors import InvalidInput, TopomarkFault, require_input
from topomark.spec.port_icfpc import map_from_json
from topomark.spec.port_plan import (ROUND_FACTORS, InvalidPlan, check_length, explore_cost, parse_plan, plan_text,
                                     run_plan)
from topomark.spec.port_world import PortWorld

from topomark.reference.contest.bodies import BadRequest
from topomark.reference.contest.log import SessionLog
from topomark.reference.contest.problems import Problems

__all__ = ["Contest", "Session", "MAX_SESSIONS", "NOT_SELECTED"]

MAX_SESSIONS = 10_000
"""The most ids one server keeps (a further new id is refused)."""

NOT_SELECTED = "no problem is selected for this id: POST /select first (a /guess ends the problem)"


@dataclass
class Session:
    """One id's state: the problem selected, its hidden map, the queries counted, the log of this problem."""

    problem: str | None = None
    hidden: PortWorld | None = None
    queries: int = 0
    log: SessionLog | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)


class Contest:
    """The game (see the module's docstring).  ``judge(hidden, guess)`` returns an object with ``equivalent``,
    ``witness`` (a plan, as text or actions, or None), ``reason``; ``log_dir`` (an existing directory) receives
    one JSON log per problem played (:class:`.log.SessionLog`)."""

    def __init__(self, problems: Problems, judge: Callable[[PortWorld, PortWorld], Any], *, round_name: str = "full",
                 echo_marks: bool = True, log_dir: str | None = None):
        require_input(round_name in ROUND_FACTORS, f"--round: {round_name!r} is not a round "
                      f"({', '.join(ROUND_FACTORS)})")
        self.problems, self.judge = problems, judge
        self.round, self.echo_marks, self.log_dir = round_name, echo_marks, log_dir
        self.sessions: dict[str, Session] = {}
        self._lock = threading.Lock()
        self._played = 0

    def answer(self, endpoint: str, body: dict[str, Any]) -> dict[str, Any]:
        """The answer to a request whose body :func:`~.bodies.read_body` has read."""
        if endpoint == "/register":
            token = secrets.token_urlsafe(16)
            self._session(token)
            return {"id": token}
        session = self._session(body["id"])
        with session.lock:
            try:
                answer = getattr(self, "_" + endpoint[1:])(session, body)
            except BadRequest as e:
                if session.log is not None:
                    session.log.exchange(endpoint, body, 400, {"error": str(e)})
                raise
            if session.log is not None:
                session.log.exchange(endpoint, body, 200, answer)
            if endpoint == "/guess":
                session.problem, session.hidden, session.log = None, None, None
            return answer

    def _session(self, key: str) -> Session:
        with self._lock:
            if key not in self.sessions:
                require_input(len(self.sessions) < MAX_SESSIONS, f"this server keeps at most {MAX_SESSIONS:,} ids; "
                              "use an id it has seen", BadRequest)
                self.sessions[key] = Session()
            return self.sessions[key]

    def _select(self, session: Session, body: dict[str, Any]) -> dict[str, Any]:
        name = body["problemName"]
        try:
            hidden = self.problems.draw(name)
        except InvalidInput as e:
            raise BadRequest(f"/select: {e}") from None
        with self._lock:
            self._played += 1
            number = self._played
        session.problem, session.hidden, session.queries = name, hidden, 0
        session.log = None if self.log_dir is None else SessionLog(
            self.log_dir, number, name, hidden, round_name=self.round, echo_marks=self.echo_marks)
        return {"problemName": name}

    def _explore(self, session: Session, body: dict[str, Any]) -> dict[str, Any]:
        hidden = session.hidden
        require_input(hidden is not None, f"/explore: {NOT_SELECTED}", BadRequest)
        assert hidden is not None
        plans = []
        for k, text in enumerate(body["plans"]):
            try:
                actions = parse_plan(text, doors=hidden.doors, alphabet=hidden.alphabet)
                require_input(self.round != "lightning" or all(a.kind == "door" for a in actions),
                              "charcoal marks are not part of the lightning round (this server runs it: --round "
                              "lightning)", InvalidPlan)
                check_length(actions, hidden.rooms, self.round)
            except InvalidPlan as e:
                raise BadRequest(f"/explore: plans[{k}]: {e}") from None
            plans.append(actions)
        results = [list(run_plan(hidden, actions, echo_marks=self.echo_marks)) for actions in plans]
        session.queries += explore_cost(len(plans))
        return {"results": results, "queryCount": session.queries}

    def _guess(self, session: Session, body: dict[str, Any]) -> dict[str, Any]:
        hidden = session.hidden
        require_input(hidden is not None, f"/guess: {NOT_SELECTED}", BadRequest)
        assert hidden is not None
        try:
            guess = map_from_json(body["map"])
        except InvalidInput as e:
            raise BadRequest(f"/guess: {e}") from None
        verdict = self.judge(hidden, guess)
        if verdict.equivalent:
            return {"correct": True}
        answer: dict[str, Any] = {"correct": False, "reason": str(verdict.reason)}
        if verdict.witness is not None:
            answer["witness"] = self._replayed(verdict.witness, hidden, guess)
        return answer

    def _replayed(self, witness: Any, hidden: PortWorld, guess: PortWorld) -> dict[str, Any]:
        """The witness plan with its records on both maps, computed here; a plan that does not tell them apart is
        the judge's fault, never sent."""
        text = witness if isinstance(witness, str) else plan_text(witness)
        actions = parse_plan(text, doors=hidden.doors, alphabet=hidden.alphabet)
        mine = run_plan(hidden, actions, echo_marks=self.echo_marks)
        theirs = run_plan(guess, actions, echo_marks=self.echo_marks)
        if mine == theirs:
            raise TopomarkFault(f"the judge's witness {text!r} gives the same record on both maps")
        return {"plan": text, "hidden": list(mine), "guess": list(theirs)}

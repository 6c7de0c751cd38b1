"""Maps consistent with an exploration's records, and whether the records pin the map down (the port-labelled model,
:mod:`topomark.spec.port_world`; the contest's problem: from plans and records, find the map).

:func:`read_exchange` reads an exchange file, the plans of an ``/explore`` request with the results of its answer:
``{"plans": [...], "results": [[...], ...]}`` (a ``queryCount`` may ride along; any other key is refused, named,
never echoed).  :func:`solve_records` asks Z3 (:mod:`topomark.proofs.port_consistent`) for a world ``A`` with the
given room count consistent with the records, then for a world ``B`` consistent with them and not equivalent to
``A`` (the contest's equivalence: no plan, marks included, tells them apart -- rooted isomorphism of door targets and
colours, whatever the door-end pairings).  Its verdict:

* ``pinned``: ``A`` exists and no ``B`` does; the records determine the map up to equivalence;
* ``ambiguous``: both exist; a plan that separates them is given, replayed on both;
* ``none``: no world of that room count gives these records;
* ``unknown``: Z3 gave up (the timeout); this is not a verdict.

Nothing Z3 says is taken on trust: every record is replayed on ``A`` and ``B``
(:func:`~topomark.spec.port_plan.run_plan`); that ``B`` is not equivalent to ``A`` is decided three times, by canonical
forms, by the product search of :mod:`.solve_separate` and by the exact judge (:mod:`.judge`), whose plan (the
shortest without marks, else the shortest with one mark) is the one given, replayed on both; any disagreement is
topomark's own fault (:class:`~topomark.spec.errors.TopomarkFault`, exit 3).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

from topomark.spec.errors import InvalidInput, TopomarkFault, clip, require_input
from topomark.spec.jsontext import no_duplicate_keys, parse_json, read_text_file
from topomark.spec.port_plan import Action, parse_plan, plan_text, run_plan
from topomark.spec.port_world import DoorEnd, PortWorld

from topomark.proofs.port_consistent import ConsistentSearch

from topomark.reference.port.judge import judge
from topomark.reference.port.solve_separate import canonical_form, separating_plan

__all__ = ["Solution", "read_exchange", "solve_records", "world_json", "EXCHANGE_KEYS", "MAX_EXCHANGE_BYTES"]

EXCHANGE_KEYS = ("plans", "results", "queryCount")
MAX_EXCHANGE_BYTES = 16 << 20
"""The largest exchange file read."""


@dataclass
class Solution:
    """What :func:`solve_records` found (see the module's docstring for ``status``)."""

    status: str
    first: PortWorld | None = None
    second: PortWorld | None = None
    witness: tuple[Action, ...] | None = None
    records: tuple[tuple[int, ...], tuple[int, ...]] | None = None
    reason: str = ""
    seconds: list[float] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        return {"status": self.status, "reason": self.reason, "z3_seconds": [round(s, 3) for s in self.seconds],
                "map": None if self.first is None else world_json(self.first),
                "second_map": None if self.second is None else world_json(self.second),
                "separating_plan": None if self.witness is None else plan_text(self.witness),
                "records": None if self.records is None else [list(r) for r in self.records]}


def world_json(world: PortWorld) -> dict[str, Any]:
    """``world`` in the contest's map shape (``rooms``, ``startingRoom``, ``connections``), whatever its doors."""
    def end(e: DoorEnd) -> dict[str, int]:
        return {"room": e[0], "door": e[1]}

    return {"rooms": list(world.colours), "startingRoom": world.start,
            "connections": [{"from": end(a), "to": end(b)} for a, b in world.passages()]}


def read_exchange(path: str | Path, *, doors: int = 6, alphabet: int = 4
                  ) -> tuple[list[tuple[Action, ...]], list[tuple[int, ...]]]:
    """The plans and records of the exchange file at ``path``; :class:`InvalidInput` names what is wrong."""
    obj = parse_json(read_text_file(path, InvalidInput, MAX_EXCHANGE_BYTES), str(path), InvalidInput,
                     object_pairs_hook=no_duplicate_keys)
    try:
        return exchange_from_json(obj, doors=doors, alphabet=alphabet)
    except InvalidInput as e:
        raise InvalidInput(f"{path}: {e}") from None


def exchange_from_json(obj: Any, *, doors: int = 6, alphabet: int = 4
                       ) -> tuple[list[tuple[Action, ...]], list[tuple[int, ...]]]:
    """The plans and records of an exchange object (see :func:`read_exchange`).

    >>> exchange_from_json({"plans": ["0[1]"], "results": [[0, 2, 1]]})[1]
    [(0, 2, 1)]
    >>> exchange_from_json({"plans": [], "results": [], "id": "secret"})
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: unknown key 'id' (an exchange has the keys plans, results, queryCount)
    """
    require_input(isinstance(obj, dict), f"an exchange is a JSON object, not {type(obj).__name__}")
    for key in obj:
        require_input(key in EXCHANGE_KEYS, f"unknown key {clip(str(key), 40, quote=True)} (an exchange has the keys "
                      "plans, results, queryCount)")
    for key in EXCHANGE_KEYS[:2]:
        require_input(key in obj, f"the key {key!r} is missing")
    plans, results = obj["plans"], obj["results"]
    require_input(isinstance(plans, list) and all(isinstance(p, str) for p in plans), "plans is a list of strings")
    require_input(isinstance(results, list) and all(isinstance(r, list) for r in results),
                  "results is a list of lists of colours")
    require_input(len(plans) == len(results), f"{len(plans)} plans but {len(results)} results")
    require_input(len(plans) >= 1, "plans is empty: nothing to solve from")
    actions = []
    for k, text in enumerate(plans):
        try:
            actions.append(parse_plan(text, doors=doors, alphabet=alphabet))
        except InvalidInput as e:
            raise InvalidInput(f"plans[{k}]: {e}") from None
    for k, record in enumerate(results):
        for i, c in enumerate(record):
            require_input(isinstance(c, int) and not isinstance(c, bool),
                          f"results[{k}][{i}] is not an integer colour")
    return actions, [tuple(r) for r in results]


def solve_records(plans: Sequence[Sequence[Action]], records: Sequence[Sequence[int]], rooms: int, *,
                  doors: int = 6, alphabet: int = 4, echo_marks: bool = True, timeout: float | None = None
                  ) -> Solution:
    """Find a world of ``rooms`` rooms consistent with the records and decide whether they pin it down."""
    search = ConsistentSearch(rooms, plans, records, doors=doors, alphabet=alphabet, echo_marks=echo_marks)
    found = search.find(timeout=timeout)
    solution = Solution(found.status, seconds=[found.seconds], reason=found.reason)
    if found.status != "found" or found.world is None:
        return solution
    first = solution.first = found.world
    if alphabet < 2:  # one colour: every record is all 0s, so no plan tells any two maps apart
        solution.status, solution.reason = "pinned", "with one colour no plan tells two maps apart"
        return solution
    left = None if timeout is None else max(0.001, timeout - found.seconds)
    other = search.find(unlike=[first], timeout=left)
    solution.seconds.append(other.seconds)
    if other.status == "unknown":
        solution.status, solution.reason = "unknown", f"{other.reason} while looking for a second map"
        return solution
    if other.status == "none" or other.world is None:
        solution.status = "pinned"
        return solution
    solution.status, solution.second = "ambiguous", other.world
    solution.witness = _witness(first, other.world, echo_marks)
    solution.records = (run_plan(first, solution.witness, echo_marks=echo_marks),
                        run_plan(other.world, solution.witness, echo_marks=echo_marks))
    return solution


def _witness(a: PortWorld, b: PortWorld, echo_marks: bool) -> tuple[Action, ...]:
    """The judge's plan separating ``a`` from ``b``, after three deciders agree that one exists: canonical forms,
    the product search of :mod:`.solve_separate` and the judge (:mod:`.judge`)."""
    if canonical_form(a) == canonical_form(b):
        raise TopomarkFault("Z3's second map has the first map's canonical form", "solve: second map differs")
    if separating_plan(a, b, echo_marks=echo_marks) is None:
        raise TopomarkFault("Z3's second map differs from the first, but no plan separates them",
                            "solve: deciders agree")
    verdict = judge(a, b, echo_marks=echo_marks, names=("map A", "map B"))
    if verdict.equivalent or verdict.witness is None:
        raise TopomarkFault("Z3's second map is not equivalent to the first, but the judge finds them equivalent",
                            "solve: Z3 and the judge agree")
    return parse_plan(verdict.witness, doors=a.doors, alphabet=a.alphabet)

"""What the registry records of one algorithm: :class:`AlgorithmSpec`, its :class:`Parameter` options, and the
checks (:data:`CHECKS`) the checker may apply to it.

An algorithm of the thesis is registered once, with its section and listing, the marker kit it needs
(:mod:`topomark.spec.kit`), its cost bound and marker bound *as the thesis states them* (``None`` where it states
none), the options it takes and the checks that apply.  A cost bound is either *exact*
(``bound_fn``, named by ``bound_formula``: every checked run is held to it at
its end, the ``cost-bound`` check, which the entry then names) or
*asymptotic* only (an O(·) has no constant: ``bound_bench`` names the bench
experiment that measures it, and nothing claims it is checked per run).
Every exact bound says **whose it is** (``bound_source``, :data:`BOUND_SOURCES`, ``docs/bounds.md``): the
thesis's, topomark's for the thesis's listing as written, or topomark's for its own variant; only the first two
bind a conformance client (``bound_binds``).  ``changes`` says what the explorer changes relative to the listing
(None: it follows it), ``listing_entry`` the entry that runs the listing literally, where there is one.
``ways`` names the phases its runs can pass through and the outcomes they can end with
(:mod:`~topomark.reference.algorithms.ways`, each with its thesis section and a predicate over a finished run).
Two shapes of algorithm exist:

* **lighthouse algorithms** (``uses_lighthouse=True``: Algorithm 3.1 and the Chapter 4 enhancements) establish v0
  with any lighthouse strategy (:mod:`topomark.reference.explorers.lighthouses`); the kit is the lighthouse's; the
  explorer is built as ``cls(robot, policies, observer, lighthouse)``;
* **kit algorithms** (everything else: markers dropped all through the exploration, §6.2; movable markers, §2.3.1;
  threads, §6.3; no marker, §5.2) are given the kit ``kit_for(n, m, options)`` — the simulator computes it from the
  world, the robot never learns n or m (§6.2.1) — and are built as ``cls(robot, policies, observer, options)``.

Every entry carries a **status** (:data:`STATUSES`): ``implemented`` (it is expected to map every world it
accepts), ``implemented, expected to fail`` (the thesis says the idea fails; ``status_reason`` names the lines and
the world where its runs end ``failed`` or ``wrong-map``, and the checker judges it like any other), or ``not
implementable from the thesis`` — a :class:`Listed` algorithm, listed by ``topomark algorithms`` with the reason,
with no explorer, which ``topomark explore`` refuses as bad input.  What its runs are expected to end with
(:meth:`AlgorithmSpec.expectation`, :mod:`~topomark.reference.algorithms.expectation`) follows from the status —
``correct`` when implemented, ``fails-by-design`` when expected to fail — unless the entry states otherwise
(``expected``, with its thesis reference), per world family where it differs (``expected_by_family``), and broadened
by the lighthouse a run uses (§5.2.1's may fail).

Every explorer keeps the contract of
:func:`topomark.reference.run.explore.explore`: ``start()``, then ``step()``
until ``done()``; ``S`` and ``position`` (its map and believed pose) where
the ``pose``/``I-*``/``isomorphism`` checks apply; ``models()`` where the
``models`` check applies; it may raise
:class:`~topomark.spec.errors.AlgorithmFailed` or
:class:`~topomark.spec.errors.LimitReached` to stop with a reason.

Examples
--------
>>> p = Parameter("markers", "how many markers the robot carries", minimum=1)
>>> p.parse("3")
3
>>> p.parse("0")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: --markers must be an integer >= 1, got '0'
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping

from topomark.spec.errors import InvalidInput, clip
from topomark.spec.kit import Kit
from topomark.spec.spelling import option

from topomark.reference.explorers.edge_choices import EDGE_CHOICES
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse, lighthouse as lighthouse_named
from topomark.reference.explorers.policies import Policies
from topomark.reference.algorithms.expectation import (CORRECT, EXPECTATIONS, FAILS_BY_DESIGN, broadest,
                                                       lighthouse_expectation)
from topomark.reference.algorithms.ways import WAYS, check_ways

__all__ = ["AlgorithmSpec", "Listed", "Parameter", "STATUSES", "BOUND_SOURCES", "CHECKS", "ALGORITHM_3_1_CHECKS", "MARKER_MAP_CHECKS", "STEPWISE_MAP_CHECKS"]

CHECKS: dict[str, str] = {
    "pose": "the explorer's believed position is the robot's true state (φ anchored at the believed pose)",
    "I-1": "S is extended-isomorphic to the subgraph of G it maps onto (§3.4, I-1)",
    "I-2": "U holds exactly the unexplored edges at known vertices, with their exit indices (§3.4, I-2)",
    "bound-function": "t = |E_G| − |E_S| decreases by one per iteration (§3.4)",
    "lemma-1": "each hypothesis's (M, P^E) is unique (§3.4, Lemma 1)",
    "marker": "no marker is dropped, moved or picked up after the lighthouse is established (the kit itself is "
              "enforced by the simulator)",
    "marker-budget": "never more markers in the world than the algorithm's stated marker bound for this n and m",
    "cost-bound": "the cost (edge traversals, §3.1.2) is at most the algorithm's stated exact bound for this n and m",
    "models": "the true world survives among the explorer's live models: one of them maps into it, its pose on "
              "the robot's true state (§5.2.2)",
    "iterations": "n − 1 non-loop and m − n + 1 loop iterations (§3.1.3)",
    "isomorphism": "the final map is extended-isomorphic to the world, markers included (§3.1.3)",
}
"""Every check the checker knows, by name, with the condition it states."""

BOUND_SOURCES: dict[str, str] = {
    "thesis": "the thesis's bound for its listing",
    "listing": "topomark's bound for the thesis's listing as written (derived in docs/bounds.md)",
    "variant": "topomark's bound for its own variant of the listing",
}
"""Whose an exact cost bound is and what it bounds (module docstring); the phrase every message quotes."""

IMPLEMENTED, EXPECTED_TO_FAIL, NOT_IMPLEMENTABLE = ("implemented", "implemented, expected to fail",
                                                   "not implementable from the thesis")
STATUSES = (IMPLEMENTED, EXPECTED_TO_FAIL, NOT_IMPLEMENTABLE)
"""The statuses of a listed algorithm (module docstring); the last is a :class:`Listed` entry's."""

ALGORITHM_3_1_CHECKS = ("pose", "I-1", "I-2", "bound-function", "lemma-1", "marker", "iterations", "isomorphism")
"""Algorithm 3.1's loop conditions (§3.4) and outcome (§3.1.3): the checks of every
lighthouse algorithm (``basic`` and Chapter 4), and the checker's default."""

MARKER_MAP_CHECKS = ("pose", "I-1", "I-2", "marker-budget", "isomorphism")
"""An algorithm that keeps S and U as Algorithm 3.1 does (§3.1.3) and drops markers as it goes (§6.2): the pose,
S and U after every step, the stated marker bound after every step, the final map with every marker dropped."""

STEPWISE_MAP_CHECKS = ("pose", "I-1", "I-2", "bound-function", "marker-budget", "iterations", "isomorphism")
""":data:`MARKER_MAP_CHECKS`, and one edge joins S per step — n − 1 non-loop and m − n + 1 loop steps (§3.1.3):
the movable marker (§2.3.1) and thread (§6.3) algorithms."""


@dataclass(frozen=True)
class Parameter:
    """An option of a kit algorithm (``topomark explore --NAME VALUE``): an integer ≥ ``minimum`` (and ≤
    ``maximum`` when one is given: an option that sizes work or memory) unless ``choices`` names the allowed
    words."""

    name: str
    help: str
    default: Any = None
    minimum: int | None = 0
    choices: tuple[str, ...] = ()
    maximum: int | None = None

    def parse(self, value: Any) -> Any:
        """``value`` (a string from the command line, or already typed) checked; bad input names the option."""
        if self.choices:
            if value not in self.choices:
                raise InvalidInput(f"{option(self.name)} must be one of {', '.join(self.choices)}, got {clip(repr(value), 60)}")
            return value
        text = str(value).strip()
        if isinstance(value, bool) or not (text.isascii() and text.lstrip("-").isdigit()) or len(text) > 18:
            bound = f" and at most {self.maximum:,}" if self.maximum is not None else ""
            raise InvalidInput(f"{option(self.name)} must be an integer >= {self.minimum}{bound}, got "
                               f"{clip(repr(value), 60)}")
        number = int(text)
        if self.minimum is not None and number < self.minimum:
            raise InvalidInput(f"{option(self.name)} must be an integer >= {self.minimum}, got {value!r}")
        if self.maximum is not None and number > self.maximum:
            raise InvalidInput(f"{option(self.name)} must be at most {self.maximum:,}, got {number}")
        return number


@dataclass(frozen=True, kw_only=True, repr=False)
class AlgorithmSpec:
    """One registered algorithm (see the module docstring for the two shapes and the explorer contract); every
    field is given by name."""

    name: str
    thesis: str
    kit: Kit
    bound: str | None
    markers: str
    deterministic: bool
    options: tuple[str, ...]
    checks: tuple[str, ...]
    explorer: Callable[..., Any]  # the explorer factory (its class): see :attr:`factory`
    bound_fn: Callable[[int, int], int] | None = None
    uses_lighthouse: bool = True
    parameters: tuple[Parameter, ...] = ()
    kit_fn: Callable[[int, int, dict], Kit] | None = None  # the kit for a world of n, m (kit algorithms)
    marker_bound_fn: Callable[[int, int], int] | None = None  # the stated marker bound, for ``marker-budget``
    family: str = "algorithm-3.1"  # the trace@2 algorithm family its traces are written in
    own: bool = True  # topomark's registered explorer (False for ``registry.variant``: an explorer under test)
    check_world: Callable[[Any, dict], None] | None = None  # refuse options false for the world (e.g. §5.3 cues)
    summary_fn: Callable[[Any, Any], dict] | None = None  # (explorer, world) ↦ the algorithm's own --json fields
    write_models: Callable[[Any, str], list] | None = None  # (explorer, dir): ``explore --models DIR``
    bound_formula: str | None = None  # the exact bound ``bound_fn`` evaluates, in words, with its thesis references
    bound_excludes: tuple[str, ...] = ()  # move purposes the exact bound does not count (``cost-bound``)
    bound_bench: str | None = None  # an asymptotic-only bound: the bench experiment that measures it
    status: str = IMPLEMENTED  # or EXPECTED_TO_FAIL, with its status_reason
    status_reason: str | None = None  # why it is expected to fail: the thesis references and the world that shows it
    expected: str | None = None  # the runs' expected outcome (expectation module); None: from the status
    expected_reason: str | None = None  # the thesis reference of an expected outcome other than the status's
    expected_by_family: tuple[tuple[str, str, str], ...] = ()  # (world family, expectation, reason) where it differs
    edge_policy: str | None = None  # the edge choice its runs take unless one is chosen (None: nearest)
    bound_source: str = "variant"  # whose the exact bound is and what it bounds (BOUND_SOURCES)
    changes: str | None = None  # what the explorer changes relative to the thesis's listing (None: follows it)
    listing_entry: str | None = None  # the registered entry that follows the listing literally, if any
    ways: tuple[str, ...] = ("correct",)  # the phases and outcomes its runs can go through (ways.WAYS)

    def __post_init__(self) -> None:
        if self.status not in (IMPLEMENTED, EXPECTED_TO_FAIL):
            raise ValueError(f"algorithm {self.name}: status {self.status!r} is not one of {IMPLEMENTED!r}, "
                             f"{EXPECTED_TO_FAIL!r} (one not implementable is a Listed entry)")
        if (self.status == EXPECTED_TO_FAIL) != bool(self.status_reason):
            raise ValueError(f"algorithm {self.name}: a status_reason is given exactly when it is expected to fail")
        unknown = set(self.checks) - set(CHECKS)
        if unknown:
            raise ValueError(f"algorithm {self.name}: unknown checks {sorted(unknown)}")
        if "isomorphism" not in self.checks:  # the outcome is judged on the final map, whatever else is checked
            raise ValueError(f"algorithm {self.name}: every algorithm's final map is checked ('isomorphism')")
        if self.bound_fn is not None and not self.bound_formula:
            raise ValueError(f"algorithm {self.name}: an exact bound (bound_fn) needs its bound_formula")
        if self.bound_fn is None and "cost-bound" in self.checks:
            raise ValueError(f"algorithm {self.name}: 'cost-bound' needs an exact bound (bound_fn)")
        if self.bound_fn is None and self.bound and not self.bound_bench:
            raise ValueError(f"algorithm {self.name}: an asymptotic bound ({self.bound}) names the bench "
                             "experiment that measures it (bound_bench)")
        for family, what, why in (("", self.expected, self.expected_reason), *self.expected_by_family):
            if what is not None and (what not in EXPECTATIONS or (what != CORRECT and not why)):
                raise ValueError(f"algorithm {self.name}: expected outcome {what!r}{' on ' + family if family else ''}"
                                 f" is one of {', '.join(EXPECTATIONS)}, with its thesis reference unless 'correct'")
        if self.edge_policy is not None and (self.edge_policy not in EDGE_CHOICES or "edge" not in self.policy_kinds):
            raise ValueError(f"algorithm {self.name}: edge_policy {self.edge_policy!r} is a registered edge choice "
                             f"({', '.join(EDGE_CHOICES)}) of an algorithm that declares 'policy edge' in its options")
        check_ways(self.name, self.ways)
        if self.bound_source not in BOUND_SOURCES:
            raise ValueError(f"algorithm {self.name}: bound_source {self.bound_source!r} is not one of {BOUND_SOURCES}")
        if self.bound_fn is not None and "cost-bound" not in self.checks:  # every exact bound is checked
            object.__setattr__(self, "checks", (*self.checks, "cost-bound"))

    def expectation(self, family: str | None = None, lighthouse: str | None = None) -> tuple[str, str]:
        """The outcome a run on a world of ``family`` with ``lighthouse`` is expected to end with, and why (the
        broadest of the entry's, on that family, and the lighthouse's:
        :mod:`~topomark.reference.algorithms.expectation`);
        by default ``correct`` when implemented and ``fails-by-design`` when expected to fail (its status_reason)."""
        what, why = ((self.expected, self.expected_reason or "") if self.expected else
                     (FAILS_BY_DESIGN, self.status_reason or "") if self.status == EXPECTED_TO_FAIL else (CORRECT, ""))
        what, why = next(((w, y) for f, w, y in self.expected_by_family if f == family), (what, why))
        if lighthouse is not None and self.uses_lighthouse:
            light, reason = lighthouse_expectation(lighthouse)
            if broadest(what, light) != what:
                what, why = light, reason
        return what, why

    def _expectation_json(self) -> dict[str, Any]:
        """The expected outcomes of ``topomark algorithms --json``: the entry's, then each world family and each
        lighthouse where it differs."""
        what, why = self.expectation()
        out: dict[str, Any] = {"expected": what}
        if why:
            out["expected_reason"] = why
        if self.expected_by_family:
            out["expected_by_family"] = {f: {"expected": w, "reason": y} for f, w, y in self.expected_by_family}
        if self.uses_lighthouse:
            lights = {h: self.expectation(None, h) for h in LIGHTHOUSES}
            out["expected_by_lighthouse"] = {h: {"expected": w, "reason": y} for h, (w, y) in lights.items()
                                             if (w, y) != (what, why)}
        return out

    @property
    def bound_checked(self) -> bool:
        """Whether every checked run holds the cost to the bound (``cost-bound``): only an exact bound can be."""
        return self.bound_fn is not None

    @property
    def bound_whose(self) -> str | None:  # whose the exact bound is, what it bounds (BOUND_SOURCES); None: none
        return None if self.bound_fn is None else BOUND_SOURCES[self.bound_source]

    @property
    def bound_binds(self) -> bool:
        """Whether the exact bound binds any implementation of the thesis's algorithm: the thesis's own, or
        topomark's for the listing as written — not topomark's bound for its own variant."""
        return self.bound_fn is not None and self.bound_source in ("thesis", "listing")

    @property
    def follows_listing(self) -> bool:
        return self.changes is None  # the explorer follows the thesis's listing

    def variant_json(self) -> dict[str, Any]:
        """Which explorer a run is made with: the thesis's listing or topomark's variant of it, and how it
        differs (a conformance case's ``variant``)."""
        return {"algorithm": self.name, "follows": "the thesis's listing" if self.follows_listing else
                "topomark's variant", "changes": self.changes, "listing_entry": self.listing_entry}

    @property
    def bound_note(self) -> str:
        """How the cost bound is held: checked per run (exact, saying whose), measured by a bench (asymptotic),
        or none."""
        if self.bound_fn is not None:
            skipped = f", not counting {' and '.join(self.bound_excludes)} moves" if self.bound_excludes else ""
            return (f"exact: {self.bound_formula}; {self.bound_whose}; checked at the end of every checked run "
                    f"(cost-bound{skipped})")
        if self.bound:
            return f"asymptotic: measured by bench {self.bound_bench}, not checked per run"
        return "none stated in the thesis"

    @property
    def factory(self) -> Callable[..., Any]:
        """What builds the explorer: ``factory(robot, policies, observer, lighthouse)`` for a lighthouse algorithm,
        ``factory(robot, policies, observer, options)`` for a kit algorithm.  To run another explorer in an
        algorithm's place (a modification, or a fault a test seeds), give a copy of its spec another ``explorer``
        (``dataclasses.replace``, :func:`~topomark.reference.algorithms.registry.variant`)."""
        return self.explorer

    def bound_for(self, n: int, m: int) -> int | None:
        """The cost bound evaluated on a world of n vertices and m edges, or None if the thesis states none."""
        return None if self.bound_fn is None else self.bound_fn(n, m)

    def lighthouse_for(self, lighthouse: "str | Lighthouse | None") -> Lighthouse | None:
        """The lighthouse a run of this algorithm uses (``directional-vertex`` unless named; None for a kit
        algorithm); a lighthouse named for a kit algorithm, or an unknown one, is bad input — decided before any
        world is seen."""
        if self.uses_lighthouse:
            return lighthouse if isinstance(lighthouse, Lighthouse) else lighthouse_named(lighthouse or
                                                                                          "directional-vertex")
        if lighthouse is not None:
            name = lighthouse if isinstance(lighthouse, str) else lighthouse.name
            raise InvalidInput(f"the algorithm {self.name} takes no lighthouse (given {name!r}): it carries its own "
                               f"kit, {self.kit.describe()}")
        return None

    def counted_cost(self, cost: int, by_purpose: Mapping[str, int]) -> int:
        """The part of a run's ``cost`` its exact bound counts: all of it less the moves of the purposes the bound
        leaves out (``bound_excludes``; ``by_purpose`` maps a purpose to its traversals)."""
        return cost - sum(by_purpose.get(p, 0) for p in self.bound_excludes)

    def kit_for(self, n: int, m: int, options: dict) -> Kit:
        """The kit a kit algorithm is given on a world of n vertices and m edges (its ``kit`` if fixed)."""
        return self.kit if self.kit_fn is None else self.kit_fn(n, m, options)

    @property
    def policy_kinds(self) -> tuple[str, ...]:
        """The policy kinds (``edge``, ``hypothesis``, ``path``) this algorithm takes: those its :attr:`options`
        declare as ``"policy KIND..."``; ``explore --policy`` of any other kind is refused."""
        return tuple(o.split()[1].partition("=")[0] for o in self.options if o.startswith("policy ") and o.split()[1:])

    def policies(self, chosen: Mapping[str, str] | None = None) -> Policies:
        """The policies a run of this algorithm takes: ``chosen`` (kind ↦ name), and for a kind not chosen the
        default — for the edge, the registration's :attr:`edge_policy` if it names one."""
        given = dict(chosen or {})
        if self.edge_policy is not None:
            given.setdefault("edge", self.edge_policy)
        return Policies(**given)

    def policies_json(self, policies: Policies) -> dict[str, str]:
        """The policies of :attr:`policy_kinds` only, as a run's header reports them: those this algorithm
        consults (none for an algorithm that declares none)."""
        return {kind: name for kind, name in policies.to_json().items() if kind in self.policy_kinds}

    def parse_options(self, given: dict[str, Any]) -> dict[str, Any]:
        """``given`` (name ↦ value, None meaning not given) checked against :attr:`parameters`, defaults filled
        in; an option this algorithm does not take is bad input naming both."""
        known = {p.name: p for p in self.parameters}
        out = {p.name: p.default for p in self.parameters}
        for name, value in given.items():
            if value is None:
                continue
            if name not in known:
                takes = ", ".join(option(p) for p in known) or "none"
                raise InvalidInput(f"the algorithm {self.name} takes no option {option(name)} (its options: {takes})")
            out[name] = known[name].parse(value)
        return out

    def __repr__(self) -> str:
        """``AlgorithmSpec(name='basic', thesis='§3.3, Algorithm 3.1', bound=..., implemented)``: which algorithm
        of the registry, in one short line (the kit, options and checks stay attributes)."""
        bound = clip(self.bound or "none stated", 200)
        return f"AlgorithmSpec(name={self.name!r}, thesis={self.thesis!r}, bound={bound!r}, {self.status})"

    def to_json(self) -> dict[str, Any]:
        """The listing of ``topomark algorithms --json``; ``kit`` is the default lighthouse's (or the fixed kit),
        ``lighthouses`` the strategies a lighthouse algorithm runs with."""
        out = {"name": self.name, "thesis": self.thesis, "kit": self.kit.to_json(), "bound": self.bound,
               "markers": self.markers, "deterministic": self.deterministic, "options": list(self.options),
               "checks": list(self.checks), "family": self.family, "kit_from_world": self.kit_fn is not None,
               "parameters": {p.name: {"help": p.help, "default": p.default} for p in self.parameters},
               "bound_checked": self.bound_checked, "bound_note": self.bound_note, "status": self.status,
               "policies": self.policies_json(self.policies()), "bound_source": self.bound_source
               if self.bound_fn is not None else None, "bound_whose": self.bound_whose,
               "bound_binds": self.bound_binds, "ways": {w: WAYS[w].to_json() for w in self.ways},
               **{k: v for k, v in self.variant_json().items() if k != "algorithm"}}
        if self.status_reason:
            out["status_reason"] = self.status_reason
        out.update(self._expectation_json())
        if self.uses_lighthouse:
            out["lighthouses"] = {h.name: {"thesis": h.thesis, "kit": h.kit.to_json()} for h in LIGHTHOUSES.values()}
        return out


@dataclass(frozen=True, kw_only=True, repr=False)
class Listed:
    """An algorithm of the thesis that is listed but cannot be run: the thesis does not give enough of it to
    implement (``reason`` says what is missing, with its thesis references).  ``family`` places it in the listing only."""

    name: str
    thesis: str
    reason: str
    family: str = "robot"
    status: str = NOT_IMPLEMENTABLE

    def __post_init__(self) -> None:
        if self.status != NOT_IMPLEMENTABLE or not self.reason:
            raise ValueError(f"listed algorithm {self.name}: status {NOT_IMPLEMENTABLE!r}, with its reason")

    def __repr__(self) -> str:
        """``Listed(name=..., thesis=..., not implementable: <the reason, cut when long>)``."""
        return f"Listed(name={self.name!r}, thesis={self.thesis!r}, {self.status}: {clip(self.reason, 400)})"

    def to_json(self) -> dict[str, Any]:
        """Its ``topomark algorithms --json`` entry: name, thesis reference, status and reason."""
        return {"name": self.name, "thesis": self.thesis, "status": self.status, "status_reason": self.reason}

    def refusal(self) -> str:
        """The one-line message ``topomark explore --algorithm NAME`` exits 2 with."""
        return f"the algorithm {self.name} ({self.thesis}) is {self.status}: {self.reason}"

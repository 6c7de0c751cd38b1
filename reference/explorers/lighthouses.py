"""Lighthouses: how a Chapter 3–4 algorithm establishes v0 and recognises it (thesis §3.3, §3.7, §6.1–6.3).

Algorithm 3.1 needs one place that gives *explicit place and back-link
information* (§3.2.2): on entering it, the robot knows it is at v0 *and* by
which exit it came in.  The thesis names several marker kits that establish
such a place, "equivalent to" its directional vertex marker:

=========================  ==========================================================  =====================
name                       what the robot drops at v0, facing exit 0                   thesis
=========================  ==========================================================  =====================
directional-vertex         a directional vertex marker pointing at exit 0              §3.3, Algorithm 3.1
directional-edge           a directional edge marker on exit 0, its head at v0         §6.1, Figure 6.1(b)
vertex-and-edge            an undirected marker at v0 and one on exit 0                §6.2
three-undirected-edge      one undirected marker on exit 0, two on exit 1              §6.2
thread                     a thread of length ε tied at v0, laid out toward exit 0     §6.3.1
three-undirected-vertex    one undirected marker at v0, two at the neighbour on        §3.7, Figure 3.21(b)
                           exit 0 (the robot walks there and back: 2 traversals)
undirected-vertex          one undirected marker where a random walk finds aperiodic   §5.1
                           neighbour degrees D (options seed, walk_limit,
                           neighbourhood; :mod:`.lighthouse_search`)
undirected-edge            one undirected edge marker on an edge a random walk finds   §6.1
                           with ends of different degrees (options seed, walk_limit)
local-pair                 nothing: v0 is where a random walk saw its least-seen pair  §5.2.1 A
                           of adjacent degrees (options seed, walk_limit, threshold;
                           :mod:`.local_lighthouses`)
local-degree-list          nothing: v0 is where a random walk saw its least-seen       §5.2.1 B
                           aperiodic neighbour degree list, rotations merged (options
                           seed, walk_limit, neighbourhood, threshold)
=========================  ==========================================================  =====================

A :class:`Lighthouse` (a strategy: establish v0, recognise it, give the
expected perception there) drops its markers, then records in S what it senses at
v0 (:meth:`~topomark.spec.mapstate.PartialMap.mark_as_sensed`), so the
expected perceptions P^E of every hypothesis (which read S) include the
markers "at the incident edges of each visited vertex and the direction of
the marker if the marker is present" (§6.1).  Recognition is the same for
every lighthouse: the signature just sensed equals v0's signature read from
exactly one entry — that entry is the back-link.  :meth:`Lighthouse.establish`
asserts the thesis's condition that makes this work: v0's signatures from
its d entries are d different ones (explicit back-link information).

Decisions (the thesis is silent):

* §6.1 does not say which way a directional edge marker points; the head at
  v0 matches its example ``[3, A, E-2-H]`` at the lighthouse end.
* §6.2 names one marker on one edge of v0 and two on another without saying
  which edges; we take the faced exit and the next one clockwise, so a start
  vertex of degree 1 cannot hold this lighthouse (bad input, checked before
  the run).
* Figure 3.21(b) names "three undirected markers, one in a vertex and two in
  a neighbor vertex" (§3.7) without saying which neighbour: the faced one.
  Its back-link needs "extra traversals looking for the marked neighbors", as
  does §5.1's: for these two *probing* lighthouses the signature sensed at v0
  is the same from every entry, so the robot probes
  (:mod:`.probing`) and the perception it then has is written as the thesis
  writes Figure 3.21's, ``[3,V-1,A]``: a virtual head at v0's exit 0.  The
  recognition table, P^E and every Chapter 4 technique use that perception;
  S keeps the true marks (Figure 3.21).
* A searched lighthouse's v0 is not the start: after :meth:`Lighthouse.establish`
  the robot stands at v0, entered by map exit 0, the explorer's believed pose
  (v0, 0), where the checker anchors φ.
* The two marker-less lighthouses of §5.2.1 are probing ones with nothing
  sensed at v0: every vertex of v0's degree is probed, and v0's perception
  is written with a virtual head (:class:`~.local_lighthouses.VirtualMap`,
  the lighthouse's ``perceiver``).  They may choose a place that is not
  unique; the run then ends ``wrong-map`` or ``failed`` (§5.2.1).

Examples
--------
>>> LIGHTHOUSES["directional-edge"].kit.to_json()
{'directional-edge': 1}
>>> [op.to_json() for op in LIGHTHOUSES["three-undirected-edge"].ops]
[{'op': 'drop', 'kind': 'edge', 'count': 1, 'exit': 0}, {'op': 'drop', 'kind': 'edge', 'count': 2, 'exit': 1}]
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Callable, Iterator, cast

from topomark.spec.errors import InvalidInput, clip, unknown_name
from topomark.spec.kit import Kit, MarkerOp, ThreadOp
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature, back_link_table, signature_at
from topomark.spec.spelling import option

from topomark.reference.explorers.inconsistency import inconsistent
from topomark.reference.explorers.lighthouse_search import after_search, search_edge, search_vertex
from topomark.reference.explorers.local_lighthouses import VirtualMap, search_degree_list, search_pair
from topomark.reference.explorers.probing import PerceivedMap, ProbingRobot, identify, perceived

__all__ = ["Lighthouse", "Beacon", "LIGHTHOUSES", "lighthouse", "configured", "MAX_WALK_LIMIT", "MAX_NEIGHBOURHOOD",
           "MAX_THRESHOLD", "OPTION_CAPS"]

MAX_WALK_LIMIT = 1_000_000
"""The largest ``--walk-limit``: 5,000 times §5.1's threshold of 200 walk steps.  A §5.2.1 walk keeps
every step's observations until it chooses v0, so its memory and time grow with the limit: a million steps of
``local-degree-list`` on a 4×4 lattice take about 30 s and 150 MB; 10^8 ran out of memory."""

MAX_NEIGHBOURHOOD = 8
"""The largest ``--neighbourhood`` d: probing the views to distance d walks every path of length d from a
vertex, so the work grows exponentially with d (on a 4×4 lattice d = 14 already takes seconds per search and
d = 100 never ends).  The thesis's experiments use d = 1 (§5.1); 8 leaves room for "further extend[ing] the
local signature" (§5.1) while every search stays short."""

MAX_THRESHOLD = MAX_WALK_LIMIT + 1
"""The largest ``--threshold``: a candidate is seen at most once per observation, and a walk makes at most
``MAX_WALK_LIMIT`` + 1 observations (§5.2.1, scheme B), so a larger threshold refuses nothing more."""

OPTION_CAPS = {"walk_limit": MAX_WALK_LIMIT, "neighbourhood": MAX_NEIGHBOURHOOD, "threshold": MAX_THRESHOLD}
"""The cap of each searched lighthouse's option that sizes its work or memory (``seed`` is any integer)."""


@dataclass
class Beacon:
    """v0 once established: how the explorer recognises and perceives it.

    ``table`` maps v0's perception from each entry to that entry (§3.3: place
    and back-link); ``perceived`` is S as the explorer perceives it (S itself,
    or S with v0's virtual head for a probing lighthouse); ``recognise`` and
    ``raw`` (v0's own signatures) make the robot probe on meeting v0;
    ``walk_steps`` counts the random walk that found v0 (§5.1, §6.1);
    ``prober(robot, recognise, raw)`` makes the probing robot (§5.2.1's
    also checks each new edge's arrival at v0).
    """

    table: dict[Signature, int]
    perceived: Any
    recognise: Callable | None = None
    raw: frozenset = frozenset()
    walk_steps: int = 0
    prober: Callable = ProbingRobot

    def robot(self, robot):
        """The robot the explorer drives: ``robot`` itself, or one that probes at v0 (:class:`ProbingRobot`)."""
        return robot if self.recognise is None else self.prober(robot, self.recognise, self.raw)


@dataclass(frozen=True)
class Lighthouse:
    """A way to make v0 a place of explicit place and back-link information.

    ``script`` is ``ops`` with the motions between them (ints), where the
    robot moves while establishing (Figure 3.21(b); a drop trip, purpose ``drop``); ``recognition(S, v0)``
    gives the probing recogniser of a lighthouse whose back-link needs probes
    (None: v0's signatures from its entries differ); ``search`` finds and
    establishes v0 by a random walk (§5.1, §6.1, §5.2.1), with ``seed``,
    ``walk_limit``, ``neighbourhood`` and ``threshold`` (the ``options`` it
    takes; ``threshold`` None: the walk's number of observations);
    ``perceiver`` makes S as perceived for a probing lighthouse (default
    :class:`PerceivedMap`).
    """

    name: str
    thesis: str
    kit: Kit
    ops: tuple[MarkerOp | ThreadOp, ...]
    drops: str  # what the robot drops, in words
    min_degree: int = 1
    script: tuple = ()
    recognition: Callable | None = None
    search: Callable | None = None
    options: tuple[str, ...] = ()
    seed: int = 0
    walk_limit: int = 200
    neighbourhood: int = 1
    threshold: int | None = None
    perceiver: Callable | None = None

    @property
    def certain(self) -> bool:
        """Whether v0 surely gives explicit place and back-link information, or the run fails: every lighthouse
        with a marker; not the marker-less ones of §5.2.1, whose place may repeat in the world."""
        return self.kit != Kit()

    @property
    def probing(self) -> bool:
        """Whether recognising v0 needs probing moves (then the explorer perceives S through a PerceivedMap)."""
        return self.recognition is not None

    def perceive(self, S):
        """S as the explorer perceives it: v0 with its virtual head if recognising it probes, else S itself."""
        return (self.perceiver or PerceivedMap)(S) if self.probing else S

    def establish(self, robot, S: PartialMap) -> Beacon:
        """Set up v0 = map vertex 0 (the robot stands at the start, facing exit 0; a search walks first) and
        record in S what the robot senses there; the robot ends at v0, entered by map exit 0."""
        if self.search is not None:
            return self.search(self, robot, S)
        v0 = S.add_vertex(robot.sense().degree)
        for item in self.script or self.ops:
            if isinstance(item, int):
                robot.move(item, "drop")  # a drop trip (Figure 3.21(b): to the neighbour it marks, and back)
            else:
                robot.operate(item)
        S.mark_as_sensed(v0, robot.sense(), 0)
        return self.beacon(S, v0)

    def beacon(self, S: PartialMap, v0: int, walk_steps: int = 0, recognise: Callable | None = None) -> Beacon:
        """The recognition of v0, once S holds its marks; raises if it gives no explicit back-link (§3.2.2).

        A lighthouse of explicit place and back-link gives one wherever the world was accepted for it
        (:func:`~topomark.reference.run.explore.prepare_world`; §3.3): otherwise the lighthouse is defined
        wrongly, a bug.  One that is not explicit may give none (§5.2.1): the ``failed`` outcome."""
        P = self.perceive(S)
        table, bad = back_link_table(P, v0, f"v0 (lighthouse {self.name})")
        if bad is not None:
            raise inconsistent(self, f"establishing the lighthouse: {bad}", "§3.3")
        if not self.probing:
            return Beacon(table, P, walk_steps=walk_steps)
        raw = frozenset(signature_at(S, v0, e) for e in range(S.degree(v0)))
        recognition = cast(Callable[..., Any], self.recognition)  # probing: it has one
        return Beacon(table, P, recognise or recognition(S, v0), raw, walk_steps)

    def placed_ops(self, world, state: tuple) -> Iterator[tuple[tuple, MarkerOp | ThreadOp]]:
        """(robot state, op) for each op the start makes, walking the script's motions on ``world`` (anything
        with ``degree`` and ``target``) from ``state``; none for a searched lighthouse (its v0 is not known)."""
        if self.search is not None:
            return
        v, entry = state
        for item in self.script or self.ops:
            if isinstance(item, int):
                v, entry = world.target((v, (entry + item) % world.degree(v)))
            else:
                yield (v, entry), item

    def with_options(self, **given) -> "Lighthouse":
        """This lighthouse with ``seed``, ``walk_limit``, ``neighbourhood`` or ``threshold`` set (None:
        unchanged); bad input names the option."""
        given = {k: v for k, v in given.items() if v is not None}
        for key, value in given.items():
            flag = option(key.replace("_", "-"))
            if key not in self.options:
                raise InvalidInput(f"the {self.name} lighthouse takes no option {flag}"
                                   + (f" (it takes {', '.join(option(o.replace('_', '-')) for o in self.options)})"
                                      if self.options else "; only a searched lighthouse does: "
                                      + ", ".join(h.name for h in LIGHTHOUSES.values() if h.options)))
            given[key] = _option_value(key, flag, value)
        return replace(self, **given)


def _option_value(key: str, flag: str, value: Any) -> int:
    """``value`` of option ``key`` (``flag`` on the command line) as an int: an integer, at least 1 and at most
    its :data:`OPTION_CAPS` cap (``seed``: any integer of at most 18 digits); bad input names the option."""
    cap = OPTION_CAPS.get(key)
    too_big = f"{flag} must be at most {cap or 0:,} (topomark.reference.explorers.lighthouses.MAX_{key.upper()})"
    if isinstance(value, str) and value.strip().lstrip("-").isdecimal() and value.strip().isascii():
        text = value.strip()
        if len(text.lstrip("-")) > 18:  # int() of thousands of digits is slow, and refused past 4,300
            if cap is None:
                why = f"{flag} must be an integer of at most 18 digits"
            else:
                why = f"{flag} must be at least 1" if text.startswith("-") else too_big
            raise InvalidInput(f"{why}; got {clip(text, 40)}")
        value = int(text)
    if not isinstance(value, int) or isinstance(value, bool):
        raise InvalidInput(f"{flag} must be an integer, got {clip(repr(value), 60)}")
    if key != "seed" and value < 1:
        raise InvalidInput(f"{flag} must be at least 1, got {clip(str(value), 40)}")
    if cap is not None and value > cap:
        raise InvalidInput(f"{too_big}; got {clip(str(value), 40)}")
    return value


def _marked_neighbour(S: PartialMap, v0: int) -> Callable:
    """Figure 3.21(b): v0's entry is found by probing for the neighbour with two markers (v0's exit 0)."""

    def two(sig: Signature) -> bool:
        return sig.vertex_count == 2

    def recognise(robot, sig: Signature, previous: Signature) -> Signature:
        d = sig.degree
        return perceived(sig, identify(robot, sig, lambda j, r: (j + r) % d == 0, two(previous), 1, two))

    return recognise


def _edge(exit: int, count: int = 1, direction: str | None = None) -> MarkerOp:
    return MarkerOp("edge", exit=exit, direction=direction, count=count)


LIGHTHOUSES: dict[str, Lighthouse] = {h.name: h for h in (
    Lighthouse("directional-vertex", "§3.3, Algorithm 3.1", Kit(vertex=1, directional=True),
               (MarkerOp("vertex", direction=0),), "a directional vertex marker pointing at the faced exit"),
    Lighthouse("directional-edge", "§6.1, Figure 6.1(b)", Kit(edge=1, directional=True), (_edge(0, direction="H"),),
               "a directional edge marker on the faced edge, its head at v0"),
    Lighthouse("vertex-and-edge", "§6.2", Kit(vertex=1, edge=1), (MarkerOp("vertex"), _edge(0)),
               "an undirected vertex marker and an undirected edge marker on the faced edge"),
    Lighthouse("three-undirected-edge", "§6.2", Kit(edge=3), (_edge(0), _edge(1, 2)),
               "one undirected edge marker on the faced edge and two on the next exit clockwise", min_degree=2),
    Lighthouse("three-undirected-vertex", "§3.7, Figure 3.21(b)", Kit(vertex=3),
               (MarkerOp("vertex"), MarkerOp("vertex", count=2)),
               "one undirected vertex marker at the start vertex and two at the neighbour it faces",
               script=(MarkerOp("vertex"), 0, MarkerOp("vertex", count=2), 0), recognition=_marked_neighbour),
    Lighthouse("undirected-vertex", "§5.1", Kit(vertex=1), (MarkerOp("vertex"),),
               "one undirected vertex marker, dropped where a random walk found aperiodic neighbour degrees",
               recognition=after_search, search=search_vertex, options=("seed", "walk_limit", "neighbourhood")),
    Lighthouse("undirected-edge", "§6.1, Figure 6.2", Kit(edge=1), (_edge(0),),
               "one undirected edge marker, dropped on an edge a random walk found with ends of different degrees",
               search=search_edge, options=("seed", "walk_limit")),
    Lighthouse("local-pair", "§5.2.1, scheme A", Kit(), (),
               "no marker (§5.2.1: v0 is where a random walk saw its least-seen pair of adjacent degrees)",
               recognition=after_search, search=search_pair, options=("seed", "walk_limit", "threshold"),
               perceiver=VirtualMap),
    Lighthouse("local-degree-list", "§5.2.1, scheme B", Kit(), (),
               "no marker (§5.2.1: v0 is where a random walk saw its least-seen aperiodic neighbour list)",
               recognition=after_search, search=search_degree_list,
               options=("seed", "walk_limit", "neighbourhood", "threshold"), perceiver=VirtualMap),
    # §6.3.1: tied at v0, laid out toward the faced exit, its free end left there; the robot senses
    # "whether the thread is present at the vertex and the direction of the thread": T-p and F (spec.signature).
    Lighthouse("thread", "§6.3.1", Kit(thread=0), (ThreadOp("tie", direction=0), ThreadOp("leave")),
               "a thread of length ε tied at the start vertex, laid out toward the faced exit"),
)}
"""The lighthouses by name; ``directional-vertex`` is Algorithm 3.1's own and the default."""


def configured(name: str | None, seed=None, walk_limit=None, neighbourhood=None,
               threshold=None) -> tuple[Lighthouse | None, Any]:
    """The CLI's lighthouse (None: the algorithm's default) with its options, and the seed left for the world.

    Decision: ``--seed`` seeds a searched lighthouse's random walk when the lighthouse takes it (the world's own
    seed then goes in its generator text, ``lattice-hole:seed=3``); otherwise it stays the generator's seed.
    """
    if name is None:
        given = [option(f) for f, v in (("walk-limit", walk_limit), ("neighbourhood", neighbourhood),
                                        ("threshold", threshold)) if v is not None]
        if given:
            flag = given[0]
            raise InvalidInput(f"{flag} is an option of a searched lighthouse ({option('lighthouse')} "
                               + "|".join(h.name for h in LIGHTHOUSES.values() if h.options) + ")")
        return None, seed
    light = lighthouse(name)
    walk_seed = "seed" in light.options
    light = light.with_options(seed=seed if walk_seed else None, walk_limit=walk_limit, neighbourhood=neighbourhood,
                               threshold=threshold)
    return light, None if walk_seed else seed


def lighthouse(name: str) -> Lighthouse:
    """The lighthouse called ``name``; an unknown name is bad input listing the known ones."""
    if name not in LIGHTHOUSES:
        raise unknown_name("lighthouse", name, LIGHTHOUSES)
    return LIGHTHOUSES[name]

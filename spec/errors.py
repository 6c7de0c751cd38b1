"""The three kinds of failure topomark keeps apart, and the exit codes they map to.

* :class:`CheckFailure`: a loop invariant (thesis §3.4), an isomorphism or a
  verdict check failed.  That means the *implementation, world, map or trace
  under test* is wrong.  The CLI exits with code 1.
* :class:`InvalidInput` (and its child :class:`InvalidWorld`): what the user gave
  us is not a valid world, map, motion or option.  The CLI exits with code 2.
* :class:`TopomarkFault`: topomark's *own* checks disagree (its two isomorphism
  implementations, a witness that fails re-verification, its own explorer
  breaking under ``drive``) or an unexpected exception escaped.  That is a bug in
  topomark, not in what it judged.  The CLI exits with code 3 and says so.

Exit 0 is success or a positive verdict.

Checks are made with :func:`require`, never with bare ``assert`` statements, so
they survive ``python -O``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Iterable

if TYPE_CHECKING:  # at run time imported when first used (:func:`__getattr__`)
    from topomark.spec.violation import Violation

__all__ = [
    "TopomarkError",
    "InvalidInput",
    "InvalidWorld",
    "InvalidKeyword",
    "Violation",
    "CheckFailure",
    "require",
    "require_input",
    "TopomarkFault",
    "ExplorerFault",
    "AlgorithmStopped",
    "AlgorithmFailed",
    "LimitReached",
    "OutOfMarkers",
    "OUTCOMES",
    "MAX_MESSAGE",
    "bounded",
    "clip",
    "CLIP_NOTE",
    "did_you_mean",
    "unknown_name",
    "EXIT_OK",
    "EXIT_NEGATIVE",
    "EXIT_BAD_INPUT",
    "EXIT_FAULT",
    "EXIT_CODES_HELP",
]

EXIT_OK, EXIT_NEGATIVE, EXIT_BAD_INPUT, EXIT_FAULT = 0, 1, 2, 3
EXIT_CODES_HELP = ("exit codes: 0 success or a positive verdict; 1 a negative verdict (the world, map, trace or "
                   "implementation under test is wrong); 2 bad input (one message naming it); 3 a fault in "
                   "topomark itself (it writes a fault report to send to topomark's maintainers)")


class TopomarkError(Exception):
    """Base class of every error topomark raises on purpose."""


MAX_MESSAGE = 1000
"""The longest message an error carries, in characters: a message that quotes a hostile value (a
megabyte-long name, a 100,000-bracket key) keeps its first and last parts, so it still names the
place and the rule, and stays one readable line."""


def bounded(message: str, limit: int = MAX_MESSAGE) -> str:
    """``message`` if short, else its first and last parts around a note of what was left out."""
    if len(message) <= limit:
        return message
    head, tail = limit * 7 // 10, limit * 2 // 10
    return f"{message[:head]} ... ({len(message) - head - tail:,} characters left out) ... {message[-tail:]}"


CLIP_NOTE = " ({n:,} characters)"
"""The note :func:`clip` puts after a cut text by default; ``{n}`` is the text's full length."""


def clip(text: str, limit: int = 120, *, note: str = CLIP_NOTE, quote: bool = False) -> str:
    """``text`` for a message, cut when longer than ``limit`` characters (a quoted value can be megabytes long).

    A cut text keeps its first ``limit`` characters, then "..." and ``note`` formatted with the full length
    ``n``.  With ``note=""`` the length is left out and the "..." counts in ``limit``: ``limit − 3`` characters
    are kept, so the result is never longer than ``limit``.  ``quote`` shows the kept part as ``repr`` does.

    >>> clip("x" * 10, 4), clip("x" * 10, 4, note=" ({n} in all)"), clip("x" * 10, 4, note="")
    ('xxxx... (10 characters)', 'xxxx... (10 in all)', 'x...')
    >>> clip("abc", quote=True), clip("abcdef", 2, quote=True)
    ("'abc'", "'ab'... (6 characters)")
    """
    if len(text) <= limit:
        return repr(text) if quote else text
    kept = text[:limit] if note else text[:max(0, limit - 3)]
    return (repr(kept) if quote else kept) + "..." + note.format(n=len(text))


def did_you_mean(name: str, choices: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` naming the choices closest to a misspelled ``name``, or ``""`` when none is close.

    The one place a misspelling gets a suggestion: a command, an option, and every name looked up by the
    commands (generator, algorithm, lighthouse, experiment, marker class, policy, family).

    >>> did_you_mean("explor", ["world", "explore", "drive"])
    " (did you mean 'explore'?)"
    >>> did_you_mean("enh", ["basic", "enh1", "enh2"])
    " (did you mean 'enh1' or 'enh2'?)"
    >>> did_you_mean("zzz", ["basic"])
    ''
    """
    if not isinstance(name, str) or len(name) > 200:  # a hostile megabyte name is close to nothing
        return ""
    import difflib  # only when a name is wrong: the command line's start stays fast

    choices = [str(c) for c in choices]
    close = difflib.get_close_matches(name, choices, n=3, cutoff=0.6)
    score = {c: difflib.SequenceMatcher(None, c, name).ratio() for c in close}
    close.sort(key=lambda c: (-score[c], choices.index(c)))  # closest first; a tie in the choices' own order
    if not close:
        return ""
    return " (did you mean " + " or ".join(repr(c) for c in close) + "?)"


def unknown_name(kind: str, name: str, choices: Iterable[str]) -> "InvalidInput":
    """The bad input of a name that is not one of ``choices``: what it is, the closest names, and the choices.

    Raise it where the name is looked up (``raise unknown_name("algorithm", name, REGISTRY)``).

    >>> print(unknown_name("generator", "latice", ["lattice", "complete"]))
    unknown generator 'latice' (did you mean 'lattice'?) (choose from lattice, complete)
    """
    choices = [str(c) for c in choices]
    return InvalidInput(f"unknown {kind} {clip(str(name), 80, quote=True)}{did_you_mean(name, choices)} "
                        f"(choose from {', '.join(choices)})")


class InvalidInput(TopomarkError, ValueError):
    """Input that is not acceptable: the CLI reports it and exits 2.  Its message is :func:`bounded`."""

    def __init__(self, message: str = ""):
        super().__init__(bounded(str(message)))


class InvalidWorld(InvalidInput):
    """A rotation system, marker or start that violates §3.1.1."""


class InvalidKeyword(InvalidInput, TypeError):
    """A keyword argument a Python function of topomark does not take (a misspelt option, say), or arguments its
    signature cannot take (too many, a required one missing).

    Both bad input (an :class:`InvalidInput`, as every refusal of topomark) and a :class:`TypeError`, as Python
    raises for an unexpected keyword of any function, so either ``except`` catches it.
    """


class CheckFailure(TopomarkError, AssertionError):
    """A violated invariant or failed internal check: the CLI exits 1."""

    def __init__(self, violation: Violation | str):
        if isinstance(violation, str):
            from topomark.spec.violation import Violation

            violation = Violation("internal check", "-", "true", "false", violation)
        self.violation = violation
        super().__init__(str(violation))


class TopomarkFault(TopomarkError, RuntimeError):
    """topomark itself failed: its own checks disagree.  The CLI exits 3.

    Raised where two of topomark's independent implementations disagree or a
    result fails its own re-verification; never for a fault of the thing
    under test (that is :class:`CheckFailure`, exit 1).  ``check`` names the
    check of topomark's own that failed (``"models"``, ``"isomorphism
    implementations agree"`` ...), ``""`` when none is named; the CLI's fault
    report gives it with the message.
    """

    def __init__(self, message: str, check: str = ""):
        super().__init__(message)
        self.check = check


class ExplorerFault(TopomarkFault):
    """An explorer found its own map, or what it sensed, inconsistent where the thesis proves that cannot happen.

    A bug in the explorer (exit 3), never the checker's verdict: an explorer does not raise
    :class:`CheckFailure`.  Where the thesis predicts such an inconsistency (a lighthouse whose place or
    back-link may not be explicit, §5.2.1) the explorer raises :class:`AlgorithmFailed` instead.  Under
    ``drive`` the world is an outside program, and the same finding shows that its answers fit no world.
    """


OUTCOMES = ("correct", "wrong-map", "failed", "limit")
"""How an exploration ends: the map is ``correct`` (extended-isomorphic to the world), or a
``wrong-map``; or the algorithm stopped — ``failed`` (it says it cannot go on, and why: §5.1's walk found no
lighthouse, §6.2's markers ran out) or ``limit`` (a cap on steps or models was reached — the thesis's "never
terminates", §5.2.2).  Only ``correct`` exits 0; the others exit 1."""


class AlgorithmStopped(TopomarkError):
    """An explorer stops before it has a map.  Not a fault of topomark, and not bad input: an outcome.

    Raised by an explorer (through the robot interface it knows only what it sensed); the driver
    (:func:`topomark.reference.run.explore.explore`) turns it into the run's outcome, :attr:`outcome`, with
    :attr:`reason` in words.
    """

    outcome = "failed"

    def __init__(self, reason: str):
        self.reason = bounded(str(reason))
        super().__init__(self.reason)


class AlgorithmFailed(AlgorithmStopped):
    """The algorithm reports that it cannot go on (e.g. no lighthouse within the walk limit, §5.1).

    :attr:`walk_steps`: the steps a lighthouse search walked before it gave up (the whole limit, §5.1), which
    the run reports as it reports a found lighthouse's walk; None for any other failure.
    """

    outcome = "failed"

    def __init__(self, reason: str, walk_steps: int | None = None):
        super().__init__(reason)
        self.walk_steps = walk_steps


class LimitReached(AlgorithmStopped):
    """A cap on steps, live models or cost was reached before the algorithm terminated (§5.2.2)."""

    outcome = "limit"


class OutOfMarkers(CheckFailure):
    """The robot tried to drop a marker its kit has none left of (running out is a named outcome, not a crash).

    A :class:`CheckFailure` to everything that judges a robot from outside (replay, the protocol: an
    operation the kit refuses), and the ``failed`` outcome to the driver of an exploration, with
    :attr:`reason`.
    """

    outcome = "failed"

    def __init__(self, violation: Violation):
        super().__init__(violation)
        self.reason = f"out of markers at {violation.where}: {violation.detail}"


def require(condition: bool, message: str) -> None:
    """Raise :class:`CheckFailure` with ``message`` unless ``condition`` holds.

    Unlike ``assert``, this is not removed by ``python -O``.
    """
    if not condition:
        raise CheckFailure(message)


def require_input(condition: bool, message: str, kind: type[InvalidInput] = InvalidInput) -> None:
    """Raise ``kind`` (an :class:`InvalidInput`) with ``message`` unless ``condition`` holds."""
    if not condition:
        raise kind(message)


def __getattr__(name: str) -> Any:
    """:class:`~topomark.spec.violation.Violation`, imported when first used (PEP 562): it is a dataclass, and
    the command line's ``--help``, which imports this module, has no use for :mod:`dataclasses`."""
    if name == "Violation":
        from topomark.spec.violation import Violation

        return Violation
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

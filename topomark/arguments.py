"""The API's arguments checked before any work, as the command line checks its options.

argparse gives every command-line option its type, so the commands check only ranges
(:mod:`topomark.reference.cli.args`).  A Python caller can pass anything: ``None``, a string for a count, NaN,
``True`` for an integer, a 100-digit number.  The functions here refuse each such value with
:class:`~topomark.spec.errors.InvalidInput` naming the parameter as the caller spelt it, before any work starts,
using the command line's bounds (:data:`~topomark.reference.cli.args.MAX_JOBS`,
:data:`~topomark.reference.cli.args.MAX_SECONDS`, ...).  :func:`keywords_checked` makes a misspelt keyword of a
function :class:`~topomark.spec.errors.InvalidKeyword`, naming the closest keywords.

Examples
--------
>>> integer("max_vertices", 5, 2, 8)
5
>>> integer("max_vertices", "5", 2, 8)
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: max_vertices must be an integer from 2 to 8, not str ('5')
>>> fraction("sample", float("nan"))
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: sample must be a number from 0 to 1, not float (nan)
"""

from __future__ import annotations

import functools
import inspect
import math
import os
from collections.abc import Callable
from numbers import Integral, Real
from typing import Any, ParamSpec, TypeVar

from topomark.keywords import unexpected_keyword
from topomark.reference.cli.args import check_seconds
from topomark.reference.worstcase.limits import exhaustive_refusal
from topomark.spec.errors import InvalidInput, InvalidKeyword, clip
from topomark.spec.spelling import python_spelling

__all__ = ["integer", "fraction", "seconds", "flag", "text", "optional_text", "path", "callback",
           "largest_degree", "keywords_checked"]

P = ParamSpec("P")
R = TypeVar("R")


def _real(value: Any) -> float | None:
    """``value`` as a float, or None for an int too large to be one."""
    try:
        return float(value)
    except OverflowError:
        return None


def _shown(value: Any) -> str:
    """``value``'s type and a short ``repr`` (a huge int or string is clipped) for a refusal."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10 ** 30:
        return f"an integer of {len(str(abs(value))):,} digits"
    return f"{type(value).__name__} ({clip(repr(value), 60)})"


def integer(name: str, value: Any, minimum: int, maximum: int, why: str = "") -> int:
    """``value`` if it is an int (not a bool) from ``minimum`` to ``maximum``; else InvalidInput naming ``name``
    and the range (``why`` says where the bound comes from)."""
    range_ = f"an integer from {minimum:,} to {maximum:,}{why}"
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise InvalidInput(f"{name} must be {range_}, not {_shown(value)}")
    number = int(value)
    if not minimum <= number <= maximum:
        shown = _shown(number) if abs(number) >= 10 ** 30 else str(number)
        raise InvalidInput(f"{name} must be {range_}, not {shown}")
    return number


def fraction(name: str, value: Any) -> float:
    """``value`` if it is a real number (not a bool) from 0 to 1; NaN and infinities are refused."""
    if isinstance(value, bool) or not isinstance(value, Real):
        raise InvalidInput(f"{name} must be a number from 0 to 1, not {_shown(value)}")
    number = _real(value)
    if number is None or not (math.isfinite(number) and 0 <= number <= 1):
        raise InvalidInput(f"{name} must be a number from 0 to 1, not {_shown(value)}")
    return number


def seconds(name: str, value: Any) -> float | None:
    """``value`` (None: no limit) as a time limit: a positive finite number of seconds, at most the command
    line's :data:`~topomark.reference.cli.args.MAX_SECONDS` (:func:`~topomark.reference.cli.args.check_seconds`)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, Real):
        raise InvalidInput(f"{name} must be a number of seconds or None, not {_shown(value)}")
    number = _real(value)
    if number is None:
        raise InvalidInput(f"{name} must be positive and finite, at most a week, not {_shown(value)}")
    return check_seconds(number, name)


def flag(name: str, value: Any) -> bool:
    """``value`` if it is True or False: a string such as ``"no"`` would be true, so anything else is refused."""
    if not isinstance(value, bool):
        raise InvalidInput(f"{name} must be True or False, not {_shown(value)}")
    return value


def text(name: str, value: Any, what: str) -> str:
    """``value`` if it is a string; ``what`` says what the string names (``"an algorithm's name"``)."""
    if not isinstance(value, str):
        raise InvalidInput(f"{name} must be {what} (a str), not {_shown(value)}")
    return value


def optional_text(name: str, value: Any, what: str) -> str | None:
    """``value`` if it is None or a string (:func:`text`)."""
    return None if value is None else text(name, value, what)


def path(name: str, value: Any) -> str:
    """``value`` as a path string: a str or an ``os.PathLike`` of one, not empty, without a NUL byte."""
    if not isinstance(value, (str, os.PathLike)):
        raise InvalidInput(f"{name} must be a path (a str or an os.PathLike), not {_shown(value)}")
    given = os.fspath(value)
    if not isinstance(given, str):
        raise InvalidInput(f"{name} must be a path given as text, not {_shown(given)}")
    if not given.strip():
        raise InvalidInput(f"{name}: the path is empty")
    if "\0" in given:
        raise InvalidInput(f"{name}: {clip(given, 80, quote=True)} is not a path (it contains a NUL byte)")
    return given


def callback(name: str, value: Any) -> Any:
    """``value`` if it is None or callable."""
    if value is not None and not callable(value):
        raise InvalidInput(f"{name} must be a function or None, not {_shown(value)}")
    return value


def largest_degree(max_vertices: int, max_degree: int) -> int:
    """``max_degree`` if the exhaustive search of worlds up to ``max_vertices`` vertices fits in memory with it
    (:data:`~topomark.reference.worstcase.limits.LARGEST_DEGREE`, the command's own bound); else InvalidInput."""
    refusal = exhaustive_refusal(max_vertices, max_degree)  # the command's own check, naming the keywords here
    if refusal is not None:
        raise InvalidInput(refusal)
    return max_degree


def keywords_checked(function: Callable[P, R]) -> Callable[P, R]:
    """``function``, whose unexpected keyword raises :class:`~topomark.spec.errors.InvalidKeyword` (an
    InvalidInput and a TypeError, as Python raises) naming the closest keywords it takes, and so does a call its
    signature cannot take (too many positional arguments, a required one missing, one given twice); a function
    with ``**options`` checks its own keywords.  The function runs inside
    :func:`~topomark.spec.spelling.python_spelling`: a message naming an option, however deep it is raised,
    names the keyword argument (``max_models``), not the command line's flag (``--max-models``)."""
    signature = inspect.signature(function)
    parameters = signature.parameters.values()
    takes = [p.name for p in parameters if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]
    name = function.__name__
    words = f"{name}() takes {', '.join(takes) or 'no keywords'}"
    open_ended = any(p.kind == p.VAR_KEYWORD for p in parameters)  # **options: checked by the function itself

    @functools.wraps(function)
    def checked(*args: P.args, **kwargs: P.kwargs) -> R:
        for keyword in kwargs:
            if keyword not in takes and not open_ended:
                raise unexpected_keyword(name, keyword, takes, words)
        try:
            signature.bind(*args, **kwargs)
        except TypeError as exc:  # too many positional arguments, a required one missing, one given twice
            raise InvalidKeyword(f"{name}() cannot be called so: {exc}; {words}") from None
        with python_spelling():  # every message naming an option names the keyword (topomark.spec.spelling)
            return function(*args, **kwargs)

    return checked

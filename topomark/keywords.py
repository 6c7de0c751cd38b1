"""Keyword arguments checked as Python checks a function's own: a misspelt one is named, with the closest names.

:func:`explore` takes the algorithm's options and :func:`generate` the generator's parameters as keywords,
so Python cannot check them; :func:`check_keywords` does, and refuses a keyword the function does not take
with :class:`~topomark.spec.errors.InvalidKeyword` — bad input to topomark and a :class:`TypeError` to
Python, as an unexpected keyword of any function is — worded as Python words it, with a suggestion::

    explore() got an unexpected keyword argument 'algoritm'; did you mean 'algorithm'? (...)

Examples
--------
>>> check_keywords("explore", {"algoritm": "basic"}, ["world", "algorithm"], "...")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
topomark.spec.errors.InvalidKeyword: explore() got an unexpected keyword argument 'algoritm'; did you mean ...
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Mapping
from typing import Any

from topomark.spec.errors import InvalidKeyword, clip

__all__ = ["check_keywords", "unexpected_keyword"]


def unexpected_keyword(function: str, name: str, choices: Iterable[str], takes: str) -> InvalidKeyword:
    """The error for the keyword ``name`` that ``function`` does not take: the closest of ``choices`` (by
    :func:`difflib.get_close_matches`) suggested, then ``takes``, the keywords it does take in words."""
    close = difflib.get_close_matches(name, list(choices), n=2, cutoff=0.6) if len(name) <= 200 else []
    hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
    return InvalidKeyword(f"{function}() got an unexpected keyword argument {clip(name, 80, quote=True)}{hint} "
                          f"({takes})")


def check_keywords(function: str, given: Mapping[str, Any], allowed: Iterable[str], takes: str,
                   suggest: Iterable[str] = ()) -> None:
    """Refuse the first keyword of ``given`` that is not ``allowed`` (:func:`unexpected_keyword`), suggesting
    the closest of ``allowed`` and ``suggest`` (the function's own keywords, which Python has matched already
    when they are spelt right)."""
    allowed = list(allowed)
    for name in given:
        if name not in allowed:
            raise unexpected_keyword(function, name, [*suggest, *allowed], takes)

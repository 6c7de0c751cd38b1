"""How a message names an option: ``--max-degree`` to the command line, ``max_degree`` to a Python caller.

The same check serves the ``topomark`` command and the Python API (``topomark.explore``, ``topomark.census``,
...), and its message must name what the caller typed: a command-line flag, or a keyword argument.  Every message
that names an option builds the name with :func:`option`, given the command line's spelling without its dashes;
the API's functions run inside :func:`python_spelling` (``topomark.arguments.keywords_checked`` enters it for
every public function), where the same call gives the keyword.  Outside it (the command line, and any code that
did not enter it) the flag is named.  The choice is a context variable, so threads and the API's nested calls
each see their own.

Decision: a run's *reason* (``LimitReached``'s text, ``--max-steps 2000 reached: ...``) is not a message to the
caller but part of the run: a trace records it in its ``end`` and replay compares it with a re-run's
(``spec/trace.md``), so it keeps one spelling whoever started the run; only refusals of arguments use
:func:`option`.

Examples
--------
>>> option("max-degree"), option("max-degree", 6)
('--max-degree', '--max-degree 6')
>>> with python_spelling():
...     option("max-degree"), option("max-degree", 6), option("prior", "single-leaf"), option("force", True)
('max_degree', 'max_degree=6', "prior='single-leaf'", 'force=True')
"""

from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Iterator

__all__ = ["option", "python_spelling", "in_python"]

_PYTHON: ContextVar[bool] = ContextVar("topomark_python_spelling", default=False)
_UNSET: Any = object()


def in_python() -> bool:
    """Whether messages now speak to a Python caller (inside :func:`python_spelling`)."""
    return _PYTHON.get()


def option(name: str, value: Any = _UNSET) -> str:
    """The option ``name`` (its command-line spelling without dashes, ``max-degree``), with ``value`` if given,
    as the caller spells it: ``--max-degree 6`` on the command line, ``max_degree=6`` from Python (the bare
    keyword ``max_degree`` without a value)."""
    if _PYTHON.get():
        keyword = name.replace("-", "_")
        return keyword if value is _UNSET else f"{keyword}={value!r}"
    return f"--{name}" if value is _UNSET else f"--{name} {value}"


@contextmanager
def python_spelling() -> Iterator[None]:
    """Within it, :func:`option` names keyword arguments (the Python API's functions run inside it)."""
    token = _PYTHON.set(True)
    try:
        yield
    finally:
        _PYTHON.reset(token)

"""Compiling the engine's kernels with numba, or not at all when numba cannot be imported.

:func:`kernel` is the one decorator every compiled function of the engine
uses: numba's ``njit(cache=True)`` — nopython mode, the machine code kept in
``__pycache__`` so compilation is paid once per installation, not per process
— when numba imports, else the function itself, unchanged.  Uncompiled, the
kernels still run (as slow plain Python), but the engine does not use them:
without numba every run goes through the reference (:mod:`topomark.reference.engine`).

Examples
--------
>>> @kernel
... def twice(x):
...     return 2 * x
>>> twice(21)
42
"""

from __future__ import annotations

from typing import Any, Callable, TypeVar

__all__ = ["NUMBA", "NUMBA_ERROR", "kernel"]

F = TypeVar("F", bound=Callable[..., Any])

try:
    import numba
except Exception as exc:  # ImportError, or a numba that fails on import (a NumPy it does not support)
    numba = None
    NUMBA_ERROR: str | None = f"{type(exc).__name__}: {exc}"
else:
    NUMBA_ERROR = None

NUMBA = numba is not None
"""Whether numba imported: the kernels are compiled."""


def kernel(fn: F) -> F:
    """``fn`` compiled by numba (nopython, cached on disk), or ``fn`` itself without numba."""
    if numba is None:
        return fn
    return numba.njit(cache=True)(fn)

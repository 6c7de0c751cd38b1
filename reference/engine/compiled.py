"""Compiling the engine's kernels with numba, or not at all when numba cannot be imported.

:func:`kernel` is the decorator the engine's compiled functions use (:func:`step` for
the small ones, inlined into their callers): numba's ``njit(cache=True)`` — nopython mode, the machine code kept in
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

import hashlib
from pathlib import Path
from typing import Any, Callable, TypeVar, cast

__all__ = ["NUMBA", "NUMBA_ERROR", "kernel", "step", "KERNEL_SOURCES", "fresh_cache"]

F = TypeVar("F", bound=Callable[..., Any])

_numba: Any
try:
    import numba as _numba
except Exception as exc:  # ImportError, or a numba that fails on import (a NumPy it does not support)
    _numba = None
    NUMBA_ERROR: str | None = f"{type(exc).__name__}: {exc}"
else:
    NUMBA_ERROR = None

NUMBA = _numba is not None
"""Whether numba imported: the kernels are compiled."""


def kernel(fn: F) -> F:
    """``fn`` compiled by numba (nopython, cached on disk), or ``fn`` itself without numba."""
    if _numba is None:
        return fn
    return cast(F, _numba.njit(cache=_cached(fn), error_model="numpy")(fn))


def step(fn: F) -> F:
    """A small kernel (a robot call, a query of the map) compiled into every kernel that calls it (numba's
    ``inline="always"``): its callers pass tuples of arrays, and a call that is not inlined pays for every array
    of them, more than the step itself costs."""
    if _numba is None:
        return fn
    return cast(F, _numba.njit(cache=_cached(fn), inline="always", error_model="numpy")(fn))


def _cached(fn: Callable[..., Any]) -> bool:
    """Whether ``fn``'s machine code may be kept on disk: only when its module is imported as part of topomark,
    from a file (not, say, a docstring's example).
    numba keys its cache by file, not by module name, so a module run under another name (``python -m doctest
    reference/engine/runs.py``) would leave code that the package then fails to load."""
    return fn.__module__.startswith("topomark.") and Path(fn.__code__.co_filename).is_file()


KERNEL_SOURCES = ("compiled.py", "digest.py", "signature.py", "robot.py", "mapstate.py", "algorithm31.py",
                  "lighthouses.py", "trie.py", "records.py", "expansion.py", "hypothesis_trie.py", "tracing.py",
                  "enhanced.py", "runs.py", "marks.py", "footprints.py", "footprint_runs.py")
"""The engine's modules holding compiled code: one changed, every kernel is compiled again."""


def fresh_cache(folder: Path = Path(__file__).parent) -> bool:
    """Drop the kept machine code of every kernel when any of :data:`KERNEL_SOURCES` changed; whether it did.

    numba checks a cached function against its own file only, not against the files of the functions it calls:
    after an edit of :mod:`.algorithm31`, the runs' kernel in :mod:`.runs` would load the old loop.  A digest of
    all the sources, kept beside the cache, catches that.  A cache folder that cannot be written is left as it is
    (numba then keeps its cache elsewhere, or none)."""
    stamp = hashlib.sha256(b"".join((folder / name).read_bytes() for name in KERNEL_SOURCES)).hexdigest()
    cache = folder / "__pycache__"
    kept = cache / "engine-sources.sha256"
    try:
        if kept.is_file() and kept.read_text() == stamp:
            return False
        for old in (*cache.glob("*.nbi"), *cache.glob("*.nbc")):
            old.unlink()
        cache.mkdir(exist_ok=True)
        kept.write_text(stamp)
    except OSError:  # a read-only install: numba keeps its cache elsewhere, or none; nothing stale can load from here
        return True
    return True


if _numba is not None:
    fresh_cache()

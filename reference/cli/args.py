"""Numeric command-line options: the one place that says which durations, counts and degrees are sane.

``float("nan")``, ``float("inf")`` and ``1e308`` all parse as floats, and a
time limit of NaN never fires (every comparison with NaN is false) while
``1e308`` seconds overflows wherever it is turned into a timestamp or into
milliseconds.  Every command that takes a time limit (``run-external``,
``conformance run``, ``drive``, ``search``) and every count limit
(``--max-traversals``) checks the parsed value here, after argparse, so the
message names the option: exit 2, one line.

>>> check_seconds(2.5, "--timeout")
2.5
>>> check_seconds(float("nan"), "--timeout")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: --timeout must be positive and finite, at most 604800 seconds (one week); got nan
"""

from __future__ import annotations

import argparse
import math

from topomark.spec.errors import InvalidInput, clip

__all__ = ["MAX_SECONDS", "MAX_COUNT", "MAX_JOBS", "SEED_DIGITS", "check_seconds", "check_count", "check_max_degree", "check_min_vertices",
           "check_jobs", "seed"]

SEED_DIGITS = 18
"""The most digits a ``--seed`` may have, as for the generators' integers and JSON's (MAX_INT_DIGITS): every
seed is reduced to 64 bits anyway, and a value of thousands of digits only makes a long message."""

MAX_SECONDS = 7 * 24 * 3600  # one week: longer than any run, far from every overflow
MAX_COUNT = 10 ** 15  # fits the protocol's integers (spec.jsontext.MAX_INT_DIGITS) and every clock

MAX_JOBS = 256
"""The most worker processes ``--jobs`` may ask for (``bench``, ``census``): far more than any machine the
sweeps run on has cores, and few enough that a typo (``--jobs 2000``) is refused instead of forking a
process per task until the machine runs out of memory."""


def check_seconds(value: float, option: str) -> float:
    """``value`` if it is a finite number of seconds in (0, MAX_SECONDS]; else InvalidInput naming ``option``."""
    if not (math.isfinite(value) and 0 < value <= MAX_SECONDS):
        raise InvalidInput(f"{option} must be positive and finite, at most {MAX_SECONDS} seconds (one week); "
                           f"got {value!r}")
    return value


def check_count(value: int, option: str, maximum: int = MAX_COUNT) -> int:
    """``value`` if it is an integer in [0, maximum]; else InvalidInput naming ``option``."""
    if not 0 <= value <= maximum:
        raise InvalidInput(f"{option} must be >= 0 and at most {maximum}; got {value}")
    return value


def check_jobs(value: int) -> int:
    """``--jobs``: at least 1 worker process, at most :data:`MAX_JOBS`; else InvalidInput naming the option.

    >>> check_jobs(0)
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: --jobs must be at least 1 and at most 256; got 0
    """
    if not 1 <= value <= MAX_JOBS:
        raise InvalidInput(f"--jobs must be at least 1 and at most {MAX_JOBS}; got {value}")
    return value


def check_min_vertices(minimum: int, maximum: int) -> int:
    """``--min-vertices`` of the commands that enumerate worlds: between 2 and ``--max-vertices``.

    >>> check_min_vertices(1, 5)
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: --min-vertices must be between 2 and --max-vertices (5), not 1
    """
    if not 2 <= minimum <= maximum:
        raise InvalidInput(f"--min-vertices must be between 2 and --max-vertices ({maximum}), not {minimum}")
    return minimum


def check_max_degree(value: int) -> int:
    """``--max-degree`` of the commands that enumerate worlds: at least 1, at most any world's degree can be."""
    from topomark.spec.world import MAX_DEGREE  # here: the options that use this module are built for --help too

    if value < 1:
        raise InvalidInput(f"--max-degree must be at least 1, not {value}")
    if value > MAX_DEGREE:
        raise InvalidInput(f"--max-degree {value} is larger than any world's degree can be "
                           f"(at most {MAX_DEGREE:,}, topomark.spec.world.MAX_DEGREE)")
    return value


def seed(text: str) -> int:
    """``--seed``'s argparse type: an integer of at most :data:`SEED_DIGITS` digits; the refusal quotes the value
    clipped.

    >>> seed("-42")
    -42
    """
    digits = text.strip().lstrip("+-")
    if not (digits.isascii() and digits.isdigit()) or len(digits) > SEED_DIGITS:
        raise argparse.ArgumentTypeError(f"must be an integer of at most {SEED_DIGITS} digits, got "
                                         f"{clip(text, 40, quote=True)}")
    return int(text)

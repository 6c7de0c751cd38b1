"""Reading untrusted JSON and files: the one place that bounds what an input may cost.

Every file format topomark reads (worlds and maps, traces, conformance
manifests, protocol lines) is JSON written by someone else.  Python's
:mod:`json` accepts inputs that later blow up far from where they were read:
100,000 levels of nesting (``RecursionError``), integers of 5,000 digits
(``ValueError`` when printed, ``OverflowError`` when used as a size),
``NaN`` and ``Infinity``.  And a path can name a FIFO (``open`` blocks
forever) or ``/dev/zero`` (``read`` never ends).  This module refuses all of
them at the door with one :class:`~topomark.spec.errors.InvalidInput` naming
the source and what is wrong.

Limits, and why they are safe:

* :data:`MAX_DEPTH` = 64 levels of nesting.  The deepest document topomark
  defines (a trace ``iteration`` record) is 5 levels deep.
* :data:`MAX_INT_DIGITS` = 18 digits, i.e. magnitudes below 10**18: every
  count, index, step and cost fits; a 64-bit signed integer does too.
* No ``NaN``, ``Infinity`` or ``-Infinity``: they are not JSON (RFC 8259 §6).
* :data:`MAX_FILE_BYTES` = 1 GiB by default for a whole file read into memory;
  only regular files are read (a FIFO, a device or a directory is refused
  before it is opened for reading, so nothing blocks).

Examples
--------
>>> parse_json('{"a": [1, 2]}', "x.json")
{'a': [1, 2]}
>>> parse_json("[" * 100 + "]" * 100, "x.json")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: x.json: JSON nested deeper than 64 levels
>>> parse_json('{"n": 1' + "0" * 30 + '}', "x.json")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: x.json: integer 1000000000000000... (31 digits) is out of range (at most 18 digits)
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path
from typing import Any, BinaryIO, Callable

from topomark.spec.errors import InvalidInput, clip

__all__ = ["MAX_DEPTH", "MAX_INT_DIGITS", "MAX_FILE_BYTES", "parse_json", "no_duplicate_keys", "check_depth",
           "open_regular_fd", "open_regular_file", "read_text_file"]

MAX_DEPTH = 64
MAX_INT_DIGITS = 18
MAX_FILE_BYTES = 1 << 30


class _Refused(ValueError):
    """Raised inside the decoder's hooks; turned into InvalidInput by :func:`parse_json`."""


def _parse_int(text: str) -> int:
    digits = len(text.lstrip("-"))
    if digits > MAX_INT_DIGITS:
        raise _Refused(f"integer {text[:16]}... ({digits} digits) is out of range (at most {MAX_INT_DIGITS} digits)")
    return int(text)


def _parse_constant(name: str) -> Any:
    raise _Refused(f"{name} is not a JSON number")


def check_depth(obj: Any, limit: int = MAX_DEPTH) -> bool:
    """True if ``obj`` (parsed JSON) nests at most ``limit`` containers deep; iterative, so it cannot recurse."""
    stack = [(obj, 1)]
    while stack:
        item, depth = stack.pop()
        if isinstance(item, (dict, list)):
            if depth > limit:
                return False
            stack.extend((x, depth + 1) for x in (item.values() if isinstance(item, dict) else item))
    return True


def no_duplicate_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """An ``object_pairs_hook`` for :func:`parse_json` that refuses an object naming a key twice (JSON allows it
    and :func:`json.loads` keeps the last, silently dropping the first): world files, ``--kit``.

    >>> parse_json('{"thread": 1, "thread": 2}', "--kit", object_pairs_hook=no_duplicate_keys)
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: --kit: duplicate key 'thread' in a JSON object
    """
    seen: dict[str, Any] = {}
    for key, value in pairs:
        if key in seen:
            raise InvalidInput(f"duplicate key {clip(key, 60, quote=True)} in a JSON object")
        seen[key] = value
    return seen


def parse_json(text: str, source: str, error: type[InvalidInput] = InvalidInput,
               object_pairs_hook: Callable[[list[tuple[str, Any]]], Any] | None = None) -> Any:
    """Parse ``text`` as JSON within the limits above; anything else raises ``error`` prefixed with ``source``.

    ``object_pairs_hook`` is passed to :func:`json.loads` (the world loader
    uses it to refuse duplicate keys); an ``InvalidInput`` it raises is
    re-raised as ``error`` with the source prefixed.
    """
    try:
        obj = json.loads(text, parse_int=_parse_int, parse_constant=_parse_constant,
                         object_pairs_hook=object_pairs_hook)
    except RecursionError:
        raise error(f"{source}: JSON nested deeper than {MAX_DEPTH} levels") from None
    except json.JSONDecodeError as exc:
        raise error(f"{source}: malformed JSON at line {exc.lineno} column {exc.colno}: {exc.msg}") from None
    except _Refused as exc:
        raise error(f"{source}: {exc}") from None
    except InvalidInput as exc:
        raise error(f"{source}: {exc}") from None
    if not check_depth(obj):
        raise error(f"{source}: JSON nested deeper than {MAX_DEPTH} levels")
    return obj


_PATH_NOTE = " ({n} characters)"  # a long path's length, with no thousands separator


def open_regular_fd(path: str | Path, flags: int = os.O_RDONLY, error: type[InvalidInput] = InvalidInput,
                    max_bytes: int | None = MAX_FILE_BYTES) -> int:
    """A blocking descriptor on ``path`` opened with ``flags`` if it is a regular file of at most ``max_bytes``.

    The file is opened non-blocking and checked with ``fstat`` on the open
    descriptor, so a FIFO never blocks and a file swapped after the check is
    still the one checked.  ``max_bytes=None`` (for streamed inputs such as
    traces) skips the size limit.  ``flags`` may ask for writing or creating
    (``os.O_RDWR | os.O_CREAT``: a lock file, a file appended to).
    """
    verb = "read" if flags & (os.O_WRONLY | os.O_RDWR) == 0 else "open"
    try:
        fd = os.open(path, flags | os.O_NONBLOCK, 0o644)
    except OSError as exc:
        shown = clip(str(path), 200, note=_PATH_NOTE)
        raise error(f"{shown}: cannot {verb} the file ({exc.__class__.__name__}: {exc.strerror or exc})") from None
    except ValueError:  # a NUL byte: no file has such a name
        raise error(f"{clip(str(path), 200, note=_PATH_NOTE)}: not a file name (it contains a NUL byte)") from None
    info = os.fstat(fd)
    if not stat.S_ISREG(info.st_mode):
        os.close(fd)
        raise error(f"{path}: not a regular file (a directory, FIFO or device cannot be read as input)")
    if max_bytes is not None and info.st_size > max_bytes:
        os.close(fd)
        raise error(f"{path}: file of {info.st_size:,} bytes is larger than the limit of {max_bytes:,} bytes")
    os.set_blocking(fd, True)
    return fd


def open_regular_file(path: str | Path, error: type[InvalidInput] = InvalidInput,
                      max_bytes: int | None = MAX_FILE_BYTES) -> BinaryIO:
    """Open ``path`` for binary reading if it is a regular file of at most ``max_bytes`` (:func:`open_regular_fd`)."""
    return os.fdopen(open_regular_fd(path, os.O_RDONLY, error, max_bytes), "rb")


def read_text_file(path: str | Path, error: type[InvalidInput] = InvalidInput,
                   max_bytes: int = MAX_FILE_BYTES) -> str:
    """The UTF-8 text of the regular file ``path`` (at most ``max_bytes``), or ``error`` naming the file."""
    with open_regular_file(path, error, max_bytes) as fh:
        try:
            data = fh.read(max_bytes + 1)
        except OSError as exc:
            raise error(f"{path}: cannot read the file ({exc.__class__.__name__}: {exc.strerror or exc})") from None
    if len(data) > max_bytes:
        raise error(f"{path}: file is larger than the limit of {max_bytes:,} bytes")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise error(f"{path}: not UTF-8 text (invalid byte at offset {exc.start})") from None

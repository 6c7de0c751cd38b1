"""Reading back a file that an earlier run wrote: a regular file of bounded size, or bad input naming it.

A directory handed back to topomark (``worst-case --summarise DIR``, ``worst-case --shards DIR``) may hold
anything under the names topomark writes: a symbolic link to ``/dev/zero``, a FIFO no one writes, a file of
300 MB.  The rule: every file read back is opened without blocking (``O_NONBLOCK``: opening a FIFO does not wait
for a writer), checked on the open descriptor to be a regular file (``S_ISREG`` of ``fstat``, so a link to a
device is refused whatever its name) and no larger than a cap, and read to at most that cap.  JSON is read as
strict UTF-8 with no ``NaN`` or ``Infinity``; nesting too deep, numbers too long and text that is not JSON are
all bad input (:class:`~topomark.spec.errors.InvalidInput`, exit 2) naming the file.

Examples
--------
>>> read_regular("/dev/zero", "the plot")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: the plot /dev/zero: not a regular file (a character device); refused
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path
from typing import Any

from topomark.spec.errors import InvalidInput

__all__ = ["MAX_READ_BYTES", "read_regular", "read_json", "is_regular_or_absent"]

MAX_READ_BYTES = 16 * 2**20
"""The largest file read back (16 MiB): the JSON and plots a worst-case run writes are far smaller."""

_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"))


def _kind(mode: int) -> str:
    return next((name for test, name in _KINDS if test(mode)), "not a regular file")


def read_regular(path: str | os.PathLike, what: str, cap: int = MAX_READ_BYTES) -> bytes:
    """The bytes of ``path`` if it is a regular file of at most ``cap`` bytes; else InvalidInput naming it."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_NOCTTY", 0))
    except OSError as e:
        raise InvalidInput(f"{what} {path}: cannot be read ({e.strerror or e})") from None
    try:
        mode, size = (s := os.fstat(fd)).st_mode, s.st_size
        if not stat.S_ISREG(mode):
            raise InvalidInput(f"{what} {path}: not a regular file ({_kind(mode)}); refused")
        if size > cap:
            raise InvalidInput(f"{what} {path}: {size} bytes, more than the {cap} read back; refused")
        data = os.read(fd, cap + 1) if size else b""
        while size and len(data) < size and len(data) <= cap:  # os.read may return less than asked
            more = os.read(fd, cap + 1 - len(data))
            if not more:
                break
            data += more
        if len(data) > cap:
            raise InvalidInput(f"{what} {path}: it grew past the {cap} bytes read back; refused")
        return data
    except OSError as e:
        raise InvalidInput(f"{what} {path}: cannot be read ({e.strerror or e})") from None
    finally:
        os.close(fd)


def is_regular_or_absent(path: Path, what: str) -> bool:
    """Whether ``path`` exists (False: it does not); InvalidInput if it exists and is not a regular file."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return False
    except OSError as e:
        raise InvalidInput(f"{what} {path}: cannot be read ({e.strerror or e})") from None
    if not stat.S_ISREG(mode):
        raise InvalidInput(f"{what} {path}: not a regular file ({_kind(mode)}); refused")
    return True


def _constant(name: str) -> Any:
    raise ValueError(f"{name} is not a JSON number")


def read_json(path: str | os.PathLike, what: str, cap: int = MAX_READ_BYTES) -> Any:
    """The JSON value in ``path`` (see :func:`read_regular`); anything that is not strict JSON is InvalidInput."""
    data = read_regular(path, what, cap)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise InvalidInput(f"{what} {path}: not UTF-8 text (byte {e.start})") from None
    try:
        return json.loads(text, parse_constant=_constant)
    except RecursionError:
        raise InvalidInput(f"{what} {path}: nested too deeply to be a topomark file") from None
    except ValueError as e:  # not JSON, or a number of more digits than Python converts
        raise InvalidInput(f"{what} {path}: not JSON ({str(e)[:120]})") from None

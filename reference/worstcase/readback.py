"""Reading back a file that an earlier run wrote: a regular file of bounded size, or bad input naming it.

A directory handed back to topomark (``worst-case --summarise DIR``, ``worst-case --shards DIR``) may hold
anything under the names topomark writes: a symbolic link to ``/dev/zero``, a FIFO no one writes, a file of
300 MB.  The rule is the one every input file of topomark follows (:func:`topomark.spec.jsontext.open_regular_file`:
opened without blocking, checked on the open descriptor to be a regular file, no larger than a cap), here with the
cap :data:`MAX_READ_BYTES` and the caller's name for the file in front of the message.  JSON is read as strict UTF-8
with no ``NaN`` or ``Infinity``; nesting too deep and text that is not JSON are bad input naming the file.  Integers
are not limited in digits here, unlike :func:`topomark.spec.jsontext.parse_json`: an out-of-range field is then
refused by the schema of the file (:mod:`.summary_input`), which names the field.

Examples
--------
>>> read_regular("/dev/zero", "the plot")
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: the plot /dev/zero: not a regular file (a directory, FIFO or device cannot be read as input)
"""

from __future__ import annotations

import json
import os
from typing import Any

from topomark.spec.errors import InvalidInput
from topomark.spec.jsontext import open_regular_file

__all__ = ["MAX_READ_BYTES", "read_regular", "read_json"]

MAX_READ_BYTES = 16 * 2**20
"""The largest file read back (16 MiB): the JSON and plots a worst-case run writes are far smaller."""


def read_regular(path: str | os.PathLike, what: str, cap: int = MAX_READ_BYTES) -> bytes:
    """The bytes of ``path`` if it is a regular file of at most ``cap`` bytes; else InvalidInput naming it."""
    try:
        with open_regular_file(str(path), max_bytes=cap) as fh:
            data = fh.read(cap + 1)
    except InvalidInput as exc:
        raise InvalidInput(f"{what} {exc}") from None
    except OSError as e:
        raise InvalidInput(f"{what} {path}: cannot be read ({e.strerror or e})") from None
    if len(data) > cap:
        raise InvalidInput(f"{what} {path}: it grew past the {cap} bytes read back; refused")
    return data


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

"""What every command's parsing shares: an argparse parser whose errors are bad input, and ``--json`` output.

>>> Parser(prog="topomark x").parse_args(["--nope"])
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: topomark x: unrecognized arguments: --nope
"""

from __future__ import annotations

import argparse
import json
from typing import Any

from topomark.spec.errors import InvalidInput

__all__ = ["Parser", "emit"]


class Parser(argparse.ArgumentParser):
    """argparse that reports bad options as InvalidInput (exit 2, one line) instead of printing usage."""

    def error(self, message: str):
        raise InvalidInput(f"{self.prog}: {message}")


def emit(args: argparse.Namespace, data: dict[str, Any], text: str) -> None:
    """Print ``data`` as JSON with --json, else ``text``."""
    if getattr(args, "json", False):
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        print(text)

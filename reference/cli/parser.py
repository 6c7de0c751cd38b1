"""What every command's parsing shares: an argparse parser whose errors are bad input, and ``--json`` output.

A parse error is :class:`InvalidInput` (exit 2, one line) naming the command it happened in, never the
program's name a second time (the command line prints ``topomark: error:`` once, :mod:`.main`).  A
misspelled option or choice gets the closest ones (:func:`topomark.spec.errors.did_you_mean`).

>>> Parser(prog="topomark x").parse_args(["--nope"])
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: x: unrecognized arguments: --nope
>>> p = Parser(prog="topomark explore")
>>> _ = p.add_argument("--algorithm")
>>> p.parse_args(["--algoritm", "basic"])
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: explore: unrecognized arguments: --algoritm basic (did you mean '--algorithm'?)
"""

from __future__ import annotations

import argparse
import importlib
import json
from typing import Any

from topomark.spec.errors import InvalidInput, clip, did_you_mean

__all__ = ["PROG", "JSON_HELP", "Parser", "Later", "emit"]

PROG = "topomark"
JSON_HELP = "print one JSON object on stdout (an error too: {\"error\": ..., \"exit\": 2})"


class Parser(argparse.ArgumentParser):
    """argparse that reports bad options as InvalidInput (exit 2, one line) instead of printing usage.

    A subcommand's parser refuses what it does not know itself (instead of handing it to the top-level
    parser, which would name the wrong command), so it can suggest its own options.
    """

    def error(self, message: str):
        where = self.prog.removeprefix(PROG).strip()
        raise InvalidInput(f"{where}: {message}" if where else message)

    def parse_known_args(self, args=None, namespace=None):
        namespace, extras = super().parse_known_args(args, namespace)
        if extras:
            self.error(self._unrecognized(extras))
        return namespace, extras

    def _unrecognized(self, extras: list[str]) -> str:
        """argparse's message, plus the closest option to the first unknown one that looks like an option."""
        text = f"unrecognized arguments: {clip(' '.join(extras), 200)}"
        option = next((e.partition("=")[0] for e in extras if e.startswith("--")), None)
        return text + (did_you_mean(option, self._option_string_actions) if option else "")

    def _check_value(self, action, value):
        """A value outside ``choices`` (a command name, ``--method``...): argparse's message with a suggestion."""
        if action.choices is not None and value not in action.choices:
            choices = [str(c) for c in action.choices]
            raise argparse.ArgumentError(action, f"invalid choice: {clip(str(value), 80, quote=True)}"
                                                 f"{did_you_mean(str(value), choices)} "
                                                 f"(choose from {', '.join(choices)})")


class Later:
    """A command's handler, imported when the command runs and never for its ``--help``: the function ``name`` of
    the module ``topomark.reference.cli.MODULE`` (``Later("cmd_world", "world_command")``), looked up at each call.

    >>> Later("cmd_claims", "claims_command")
    Later('cmd_claims', 'claims_command')
    """

    def __init__(self, module: str, name: str):
        self.module, self.name = module, name

    def __call__(self, args: argparse.Namespace) -> int:
        handler = getattr(importlib.import_module(f"{__package__}.{self.module}"), self.name)
        return int(handler(args))

    def __repr__(self) -> str:
        return f"Later({self.module!r}, {self.name!r})"


def emit(args: argparse.Namespace, data: dict[str, Any], text: str) -> None:
    """Print ``data`` as JSON with --json, else ``text``."""
    if getattr(args, "json", False):
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        print(text)

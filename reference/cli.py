"""The ``topomark`` command line.

Every command exits 0 for success or a positive verdict, 1 for a negative
verdict or a violated invariant, 2 for bad input (one message, no traceback),
and takes ``--json`` for machine-readable output on stdout.

Commands from other parts of topomark register themselves through a
``register(subparsers)`` function that adds a subparser whose ``handler``
default is ``handler(args) -> int``.
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from typing import Any, Sequence

from topomark.spec.errors import CheckFailure, InvalidInput

__all__ = ["main", "build_parser", "emit"]

# Modules that contribute commands: each has register(subparsers).
COMMAND_MODULES = (
    "topomark.reference.cmd_world",
    "topomark.reference.cmd_explore",
    "topomark.reference.cmd_oracle",
    "topomark.reference.cmd_bench",
    "topomark.proofs.cli_distinguish",
    "topomark.proofs.cli_search",
)


class _Parser(argparse.ArgumentParser):
    """argparse that reports bad options as InvalidInput (exit 2, one line) instead of printing usage."""

    def error(self, message: str):
        raise InvalidInput(f"{self.prog}: {message}")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="topomark", description="Marker-based topological SLAM: the thesis's reference "
                                                    "implementation, checker and proofs.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name in COMMAND_MODULES:
        try:
            module = importlib.import_module(name)
        except ModuleNotFoundError as exc:
            if exc.name == name:
                continue
            raise
        module.register(sub)
    return parser


def emit(args: argparse.Namespace, data: dict[str, Any], text: str) -> None:
    """Print ``data`` as JSON with --json, else ``text``."""
    if getattr(args, "json", False):
        print(json.dumps(data, indent=1, sort_keys=True))
    else:
        print(text)


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        parser = build_parser()
        if not argv:
            argv = ["explore"]  # the main job: a checked exploration of the built-in default world
        args = parser.parse_args(argv)
        if not getattr(args, "command", None):
            parser.print_help()
            return 2
        return int(args.handler(args))
    except InvalidInput as exc:
        print(f"topomark: error: {exc}", file=sys.stderr)
        return 2
    except CheckFailure as exc:
        print(f"topomark: check failed: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("topomark: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return 0


if __name__ == "__main__":
    sys.exit(main())

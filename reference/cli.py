"""The ``topomark`` command line.

Every command exits 0 for success or a positive verdict, 1 for a negative
verdict or a violated invariant, 2 for bad input (one message, no traceback),
3 when topomark itself failed (its own checks disagree, or an unexpected
exception: a bug to report), and takes ``--json`` for machine-readable output
on stdout.

Commands from other parts of topomark register themselves through a
``register(subparsers)`` function that adds a subparser whose ``handler``
default is ``handler(args) -> int``.
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import sys
from typing import Any, Sequence

import traceback

from topomark.spec.errors import (EXIT_BAD_INPUT, EXIT_CODES_HELP, EXIT_FAULT, EXIT_NEGATIVE, CheckFailure,
                                  InvalidInput, TopomarkFault)

__all__ = ["main", "build_parser", "emit", "clip_message"]

# Modules that contribute commands: each has register(subparsers).
COMMAND_MODULES = (
    "topomark.reference.cmd_world",
    "topomark.reference.cmd_explore",
    "topomark.reference.cmd_oracle",
    "topomark.reference.cmd_bench",
    "topomark.reference.cmd_algorithms",
    "topomark.proofs.cli_distinguish",
    "topomark.proofs.cli_search",
    "topomark.proofs.cli_count",
)


class _Parser(argparse.ArgumentParser):
    """argparse that reports bad options as InvalidInput (exit 2, one line) instead of printing usage."""

    def error(self, message: str):
        raise InvalidInput(f"{self.prog}: {message}")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="topomark", description="Marker-based topological SLAM: the thesis's reference "
                                                    "implementation, checker and proofs.", epilog=EXIT_CODES_HELP)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    _add_parser = sub.add_parser

    def add_parser(*a, **kw):  # every command's --help ends with the four exit codes
        kw.setdefault("epilog", EXIT_CODES_HELP)
        return _add_parser(*a, **kw)

    sub.add_parser = add_parser
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
        print(f"topomark: error: {clip_message(str(exc))}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except CheckFailure as exc:
        print(f"topomark: check failed: {clip_message(str(exc))}", file=sys.stderr)
        return EXIT_NEGATIVE
    except KeyboardInterrupt:
        print("topomark: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return 0
    except TopomarkFault as exc:
        return _fault(f"{exc}")
    except Exception as exc:  # noqa: BLE001 - anything else is a bug in topomark, reported as one
        return _fault(f"unexpected {exc.__class__.__name__}: {exc}", traceback.format_exc())


def clip_message(text: str, limit: int = 1000) -> str:
    """One message, bounded: whatever an input quotes back, stderr gets at most ``limit`` characters of it."""
    return text if len(text) <= limit else f"{text[:limit]}... ({len(text):,} characters in all)"


def _fault(message: str, detail: str = "") -> int:
    """Exit 3: topomark itself failed.  The traceback goes to stderr only with TOPOMARK_DEBUG=1."""
    print(f"topomark: internal fault (a bug in topomark, not in what it checked): {message[:2000]}\n"
          "please report it with the command line and input that caused it", file=sys.stderr)
    if detail and os.environ.get("TOPOMARK_DEBUG"):
        print(detail, file=sys.stderr)
    return EXIT_FAULT


if __name__ == "__main__":
    sys.exit(main())

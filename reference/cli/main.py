"""The ``topomark`` command line.

Every command exits 0 for success or a positive verdict, 1 for a negative
verdict or a violated invariant, 2 for bad input (one message, no traceback),
3 when topomark itself failed (its own checks disagree, or an unexpected
exception: a bug to report), and takes ``--json`` for machine-readable output
on stdout.

Each command is a module of this folder (``cmd_*``) with a
``register(subparsers)`` function that adds a subparser whose ``handler``
default is ``handler(args) -> int``; :data:`COMMAND_MODULES` lists them.
"""

from __future__ import annotations

import argparse
import os
import sys
import traceback
from typing import Sequence

from topomark.spec.errors import (EXIT_BAD_INPUT, EXIT_CODES_HELP, EXIT_FAULT, EXIT_NEGATIVE, CheckFailure,
                                  InvalidInput, TopomarkFault, clip)

from topomark.reference.cli import (cmd_algorithms, cmd_bench, cmd_claims, cmd_count, cmd_distinguish, cmd_explore,
                                    cmd_oracle, cmd_search, cmd_world, cmd_worst_case)
from topomark.reference.cli.parser import Parser
from topomark.reference.cli.pipes import closed_pipe_safe

__all__ = ["main", "build_parser"]

STDERR_LIMIT, STDERR_NOTE = 1000, " ({n:,} characters in all)"
"""One message, bounded: whatever an input quotes back, stderr gets at most 1000 characters of it."""

# The modules that contribute commands, in --help order: each has register(subparsers).
COMMAND_MODULES = (cmd_world, cmd_explore, cmd_oracle, cmd_bench, cmd_algorithms, cmd_distinguish, cmd_search,
                   cmd_count, cmd_claims, cmd_worst_case)


def build_parser() -> argparse.ArgumentParser:
    parser = Parser(prog="topomark", description="Marker-based topological SLAM: the thesis's reference "
                                                    "implementation, checker and proofs.", epilog=EXIT_CODES_HELP)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    _add_parser = sub.add_parser

    def add_parser(*a, **kw):  # every command's --help ends with the four exit codes
        kw.setdefault("epilog", EXIT_CODES_HELP)
        return _add_parser(*a, **kw)

    sub.add_parser = add_parser
    for module in COMMAND_MODULES:
        module.register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command; its exit code, whether or not anyone still reads stdout (:mod:`.pipes`)."""
    with closed_pipe_safe():
        return _main(list(sys.argv[1:] if argv is None else argv))


def _main(argv: list[str]) -> int:
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
        print(f"topomark: error: {clip(str(exc), STDERR_LIMIT, note=STDERR_NOTE)}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except CheckFailure as exc:
        print(f"topomark: check failed: {clip(str(exc), STDERR_LIMIT, note=STDERR_NOTE)}", file=sys.stderr)
        return EXIT_NEGATIVE
    except KeyboardInterrupt:
        print("topomark: interrupted", file=sys.stderr)
        return 130
    except TopomarkFault as exc:
        return _fault(f"{exc}")
    except Exception as exc:  # noqa: BLE001 - anything else is a bug in topomark, reported as one
        return _fault(f"unexpected {exc.__class__.__name__}: {exc}", traceback.format_exc())


def _fault(message: str, detail: str = "") -> int:
    """Exit 3: topomark itself failed.  The traceback goes to stderr only with TOPOMARK_DEBUG=1."""
    print(f"topomark: internal fault (a bug in topomark, not in what it checked): {message[:2000]}\n"
          "please report it with the command line and input that caused it", file=sys.stderr)
    if detail and os.environ.get("TOPOMARK_DEBUG"):
        print(detail, file=sys.stderr)
    return EXIT_FAULT


if __name__ == "__main__":
    sys.exit(main())

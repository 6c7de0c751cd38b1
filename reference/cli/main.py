"""The ``topomark`` command line.

Every command exits 0 for success or a positive verdict, 1 for a negative
verdict or a violated invariant, 2 for bad input (one message, no traceback),
3 when topomark itself failed (its own checks disagree, or an unexpected
exception: a bug, for which it writes a fault report to send to its maintainers,
:mod:`.fault_report`), and takes ``--json`` for machine-readable output on stdout.

Each command has its options in a module of :mod:`.options` with a ``register(subparsers)`` function that
adds a subparser whose ``handler`` default is ``handler(args) -> int``, and its implementation in a module of
this folder (``cmd_*``), imported by the handler when the command runs (:class:`.parser.Later`);
:data:`COMMANDS` lists them with the one-line summary ``topomark --help`` shows.  Only the options of the
command named are imported, and ``--help`` imports no implementation and reads the names and limits it lists
from a table (:mod:`.facts`): every ``--help`` starts about as fast as Python does, whatever the commands
need.  ``topomark`` alone prints the commands, a line each, on stdout and exits 0.

Under ``--json`` (anywhere before a ``--``) every outcome is one JSON object on stdout, an error too:
``{"error": "...", "exit": 2}``.  A first Ctrl-C ends the command with ``topomark: interrupted``, exit
130; a second one, during the clean-up the first started, ends the process at once and silently, exit 130;
one that comes once only the interpreter's own exit is left is ignored, so it too ends quietly with 130.
Worker processes leave Ctrl-C to the command (their initializer ignores it) so it is reported once.

An option is spelled one way in every command: ``-o/--out`` names where the output goes (a file for
``world``, a directory for ``bench`` and ``search``; ``world --output`` is still accepted, unlisted);
``--jobs N`` is 1 to 256 worker processes everywhere (0 is refused: no command runs without a process,
and each has its default: ``bench`` one per CPU, its runs being small and independent; ``census`` 1,
all in the leader, since a census's memory grows with its workers and its long runs are started
deliberately); ``--seed N`` is one integer type (:func:`.args.seed`); ``--timeout SECONDS``;
``--quiet`` silences progress; ``--json``; ``--force`` lets a command write over an output that is
already there (:data:`topomark.reference.files.overwrite.RULE`, printed in the command-line reference).
"""

from __future__ import annotations

import argparse
import atexit
import importlib
import json
import os
import signal
import sys
import threading
from typing import Sequence

from topomark.spec.errors import (EXIT_BAD_INPUT, EXIT_CODES_HELP, EXIT_FAULT, EXIT_NEGATIVE, CheckFailure,
                                  InvalidInput, TopomarkFault, clip)

from topomark.reference.cli import facts
from topomark.reference.cli.parser import PROG, Parser
from topomark.reference.cli.pipes import closed_pipe_safe

__all__ = ["main", "build_parser", "asks_for_help", "short_help", "COMMANDS", "EXIT_INTERRUPTED"]

STDERR_LIMIT, STDERR_NOTE = 1000, " ({n:,} characters in all)"
"""One message, bounded: whatever an input quotes back, stderr gets at most 1000 characters of it."""

EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report a process ended by Ctrl-C

COMMANDS = {  # name: (module of .options that registers it, summary for topomark --help), in --help order
    "world": ("world", "generate a world file, or --show one"),
    "iso": ("world", "extended-isomorphism verdict for two world/map files"),
    "explore": ("explore", "explore a world with every invariant checked after every step"),
    "run-external": ("oracle", "play a world to another program over topomark/protocol@1 and judge it"),
    "check-map": ("oracle", "judge a map file against a world file (extended isomorphism)"),
    "replay": ("oracle", "verify a topomark/trace@1 trace recorded by any implementation"),
    "drive": ("oracle", "drive an external world provider (simulator or robot bridge) with Algorithm 3.1"),
    "conformance": ("oracle", "export, lint or run the conformance suite (topomark/conformance@2)"),
    "view": ("view", "a trace stepped through in the browser: one self-contained HTML page"),
    "bench": ("bench", "run a thesis experiment (figures 3.10-3.12, tables 4.1-4.8, lighthouses, "
                           "tables 6.1-6.2) and write CSV + report"),
    "algorithms": ("algorithms", "list the registered algorithms with their thesis references and bounds"),
    "distinguish": ("distinguish", "shortest motion sequence telling two worlds apart"),
    "census": ("distinguish", "group all small worlds by what a robot perceives"),
    "search": ("search", "SAT search for indistinguishable non-isomorphic worlds (Z3)"),
    "census-count": ("count", "how many embedded worlds there are per size (Burnside's lemma)"),
    "claims": ("claims", "every claim of the thesis and how topomark backs it (the claims ledger)"),
    "worst-case": ("worst_case", "the worst cost of an algorithm over every small world, or found by search "
                                     "past them (§7.2)"),
    "port": ("port", "the port-labelled robot of the ICFP Contest 2025: import, run and judge port worlds"),
    "contest": ("contest", "a local server for ICFP Contest 2025 explorers: /select, /explore, /guess, judged "
                           "exactly"),
    "completion": ("completion", "print a shell completion script (bash, zsh or tcsh)"),
}


class _Version(argparse.Action):
    """``--version``: ``topomark X.Y.Z``, the installed package's version, looked up only when asked for."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS, help=None):
        super().__init__(option_strings, dest, nargs=0, default=default, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        from importlib.metadata import PackageNotFoundError, version

        try:
            text = f"{PROG} {version(PROG)}"
        except PackageNotFoundError:
            text = f"{PROG} (version unknown: the package is not installed)"
        print(text)  # on stdout, as argparse's own version action does
        parser.exit()


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The whole command line; with ``only``, the full parser of that command alone (its options module
    imported) and, for every other command, its name and summary (enough for ``--help`` and for suggestions)."""
    parser = Parser(prog=PROG, description="Marker-based topological SLAM: the thesis's reference "
                                           "implementation, checker and proofs.", epilog=EXIT_CODES_HELP)
    parser.add_argument("--version", action=_Version, help="print the version (topomark X.Y.Z) and exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    _add_parser = sub.add_parser

    def add_parser(name, **kw):  # every command's --help ends with the four exit codes
        kw.setdefault("epilog", EXIT_CODES_HELP)
        if name in COMMANDS:
            kw.setdefault("help", COMMANDS[name][1])
        return _add_parser(name, **kw)

    sub.add_parser = add_parser  # type: ignore[method-assign]  # wrapped: every --help ends with the exit codes
    done: set[str] = set()
    for name, (module, summary) in COMMANDS.items():
        if module in done:
            continue
        if only is None or COMMANDS.get(only, ("",))[0] == module:
            importlib.import_module(f"{__package__}.options.{module}").register(sub)
            done.add(module)
        else:
            _add_parser(name, help=summary, add_help=False)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command; its exit code, whether or not anyone still reads stdout (:mod:`.pipes`)."""
    previous = _catch_second_interrupt()
    code = EXIT_INTERRUPTED
    try:
        with closed_pipe_safe():
            code = _main(list(sys.argv[1:] if argv is None else argv))
        return code
    finally:
        if previous is not None and code != EXIT_INTERRUPTED:
            signal.signal(signal.SIGINT, previous)
        elif previous is not None:  # after a Ctrl-C, a second one stays quiet to the end, the interpreter's too
            atexit.register(signal.signal, signal.SIGINT, signal.SIG_IGN)


def _catch_second_interrupt():
    """From the first Ctrl-C on, a second one exits 130 at once, silently; the handler it replaces (None when
    Ctrl-C is not Python's to handle here: another thread, or a handler someone else installed)."""
    if threading.current_thread() is not threading.main_thread():
        return None
    previous = signal.getsignal(signal.SIGINT)
    if previous is not signal.default_int_handler:
        return None

    def first(signum, frame):
        signal.signal(signal.SIGINT, _second)
        raise KeyboardInterrupt

    signal.signal(signal.SIGINT, first)
    return previous


def _second(signum, frame) -> None:
    os._exit(EXIT_INTERRUPTED)


def _main(argv: list[str]) -> int:
    as_json = "--json" in (argv[:argv.index("--")] if "--" in argv else argv)
    given = list(argv)  # the command line as typed, for a fault report
    try:
        if not argv:
            print(short_help())
            return 0
        command = next((a for a in argv if not a.startswith("-")), None)
        with facts.for_help(asks_for_help(argv)):
            parser = build_parser(only=command if command in COMMANDS else "")
        args = parser.parse_args(argv)
        if not getattr(args, "command", None):
            raise InvalidInput(f"give a COMMAND ({', '.join(COMMANDS)}); {PROG} --help describes them")
        return int(args.handler(args))
    except InvalidInput as exc:
        return _say("error", str(exc), EXIT_BAD_INPUT, as_json)
    except CheckFailure as exc:
        return _say("check failed", str(exc), EXIT_NEGATIVE, as_json)
    except KeyboardInterrupt:
        return _say("interrupted", "", EXIT_INTERRUPTED, as_json)
    except TopomarkFault as exc:
        return _fault(f"{exc}", exc, given, as_json)
    except Exception as exc:  # noqa: BLE001 - anything else is a bug in topomark, reported as one
        return _fault(f"unexpected {exc.__class__.__name__}: {exc}", exc, given, as_json)


def asks_for_help(argv: list[str]) -> bool:
    """Whether ``argv`` asks for help (``-h``, ``--help`` or an abbreviation, before any ``--``), so the parser
    may be built from :mod:`.facts`'s table: a command that runs reads the modules themselves."""
    mine = argv[:argv.index("--")] if "--" in argv else argv
    return any(a == "-h" or (a.startswith("--h") and "--help".startswith(a)) for a in mine)


def short_help() -> str:
    """What ``topomark`` alone prints: the usage, the commands with their summaries, a line each, and where
    to read more."""
    width = max(map(len, COMMANDS))
    lines = [build_parser(only="").format_usage().rstrip(), "", "commands:"]
    lines += [f"  {name:<{width}}  {summary}" for name, (_, summary) in COMMANDS.items()]
    return "\n".join([*lines, "", f"{PROG} COMMAND --help describes a command and its options; {PROG} --help adds the exit codes"])


def _say(what: str, message: str, code: int, as_json: bool) -> int:
    """One line on stderr, ``topomark: WHAT: message``; under --json also the one JSON object on stdout."""
    message = clip(message, STDERR_LIMIT, note=STDERR_NOTE)
    print(f"{PROG}: {what}: {message}" if message else f"{PROG}: {what}", file=sys.stderr)
    if as_json:
        print(json.dumps({"error": message or what, "exit": code}))
    return code


def _fault(message: str, exc: BaseException, argv: list[str], as_json: bool = False) -> int:
    """Exit 3: topomark itself failed.  A fault report is written (:mod:`.fault_report`) and the message says
    where and what to do with it; the traceback is in the report, and on stderr too with TOPOMARK_DEBUG=1."""
    message = clip(" ".join(message.split()), STDERR_LIMIT, note=STDERR_NOTE)  # one line, however long the fault
    path, shown, why = _report(argv, exc)
    where = (f"A report was written to {shown} (the command line, the world files it names and the run in "
             "progress, if any): please send that file to topomark's maintainers (see CITATION.cff in topomark's "
             "source)." if shown is not None else
             f"No report could be written ({why}): please send topomark's maintainers (see CITATION.cff in "
             "topomark's source) the command line and the input that caused it.")
    print(f"{PROG}: internal fault: {message}\nThis is a fault in topomark, not in your input or in what it "
          f"checked. {where}", file=sys.stderr)
    if os.environ.get("TOPOMARK_DEBUG"):
        import traceback  # here: only a fault needs it

        print("".join(traceback.format_exception(type(exc), exc, exc.__traceback__)), file=sys.stderr)
    if as_json:
        error = {"error": f"internal fault: {message}", "exit": EXIT_FAULT, "report": path}
        print(json.dumps(error if path is not None else {**error, "report_not_written": why}))
    return EXIT_FAULT


def _report(argv: list[str], exc: BaseException) -> tuple[str | None, str | None, str]:
    """Write the fault report: its absolute path and the path the message shows (``./NAME`` in the current
    directory), or None, None and why not.  Never raises: the fault is reported, report or not."""
    try:
        from pathlib import Path

        from topomark.reference.cli.fault_report import write_report

        written, why = write_report(argv, exc)
        if written is None:
            return None, None, clip(why, STDERR_LIMIT // 2, note=STDERR_NOTE)
        full = written.absolute()
        try:
            here = full.parent.resolve() == Path.cwd().resolve()
        except OSError:  # the current directory is gone
            here = False
        return str(full), f"./{full.name}" if here else str(full), ""
    except Exception as error:  # noqa: BLE001 - the report is a help; its failure must not hide the fault
        return None, None, f"{error.__class__.__name__}: {clip(str(error), 200)}"
    except KeyboardInterrupt:  # Ctrl-C while a large report is written: the fault is still reported, exit 3
        return None, None, "interrupted while it was being written"


if __name__ == "__main__":
    sys.exit(main())

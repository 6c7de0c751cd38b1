"""The command-line reference, ``docs/cli.md``, generated from the parsers the ``topomark`` command runs.

Every command of :data:`topomark.reference.cli.main.COMMANDS` (and every sub-command, such as
``conformance export``) gets its summary, usage, description and a table of its arguments with their help,
read from :func:`topomark.reference.cli.main.build_parser` — so the page cannot say what the parser does not.
The output does not depend on the terminal: usage lines are wrapped at a fixed width.

    python -m topomark.reference.cli.docgen > docs/cli.md

>>> text = markdown()
>>> text.startswith("# Command-line reference")
True
>>> "## topomark explore" in text and "`--algorithm NAME`" in text
True
"""

from __future__ import annotations

import argparse
import sys

from topomark.reference.cli.main import COMMANDS, build_parser
from topomark.reference.files.overwrite import RULE
from topomark.spec.errors import EXIT_CODES_HELP

__all__ = ["markdown", "main"]

WIDTH = 100  # usage lines are wrapped here, whatever the terminal
HEADER = ("# Command-line reference\n\n"
          "Generated from the parsers of the `topomark` command (`python -m topomark.reference.cli.docgen`); "
          "`topomark COMMAND --help` prints the same text.\n\n")


def markdown() -> str:
    """The whole reference: one section per command, in ``topomark --help`` order."""
    parser = build_parser()
    codes = _one_line(EXIT_CODES_HELP).removeprefix("exit codes:").strip()
    parts = [HEADER, f"Every command exits with one of four codes: {codes}. `topomark` alone, with no command, "
                     "prints the commands below, a line each, and exits 0.\n\n", f"**Output paths.** {RULE}\n\n"]
    parts.append("| command | what it does |\n|---|---|\n")
    parts += [f"| [`{name}`](#topomark-{name}) | {_cell(summary)} |\n" for name, (_, summary) in COMMANDS.items()]
    for name, (_, summary) in COMMANDS.items():
        parts.append(_command(f"topomark {name}", _subparser(parser, name), summary, level=2))
    return "".join(parts)


def _subparser(parser: argparse.ArgumentParser, name: str) -> argparse.ArgumentParser:
    """The parser of one command (or sub-command) ``name`` below ``parser``."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return action.choices[name]
    raise KeyError(name)


def _command(title: str, parser: argparse.ArgumentParser, summary: str, level: int) -> str:
    """A section: heading, summary, usage, description and arguments; then its own sub-commands."""
    out = [f"\n{'#' * level} {title}\n\n"]
    if summary:
        out.append(f"{_one_line(summary)}.\n\n" if not summary.endswith(".") else f"{_one_line(summary)}\n\n")
    out.append(f"```text\n{_usage(parser)}```\n\n")
    if parser.description:
        out.append(f"{_one_line(parser.description)}\n\n")
    rows = [_row(parser, a) for a in parser._actions
            if a.help is not argparse.SUPPRESS and not isinstance(a, (argparse._HelpAction,
                                                                      argparse._SubParsersAction))]
    if rows:
        out.append("| argument | meaning |\n|---|---|\n" + "".join(rows) + "\n")
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            helps = {c.dest: c.help or "" for c in action._choices_actions}
            for sub, subparser in action.choices.items():
                out.append(_command(f"{title} {sub}", subparser, helps.get(sub, ""), level + 1))
    return "".join(out)


def _usage(parser: argparse.ArgumentParser) -> str:
    formatter = argparse.HelpFormatter(parser.prog, width=WIDTH)
    formatter.add_usage(parser.usage, parser._actions, parser._mutually_exclusive_groups)
    return formatter.format_help()


def _row(parser: argparse.ArgumentParser, action: argparse.Action) -> str:
    """One table row: the argument as typed (``--out DIR``, ``-o DIR``) and its help, defaults expanded."""
    formatter = argparse.HelpFormatter(parser.prog, width=WIDTH)
    if action.option_strings:
        metavar = formatter._format_args(action, action.dest.upper()) if action.nargs != 0 else ""
        names = ", ".join(f"`{o} {metavar}`" if metavar else f"`{o}`" for o in action.option_strings)
    else:
        names = f"`{formatter._format_args(action, action.dest)}`"
    text = formatter._expand_help(action) if action.help else ""
    return f"| {names} | {_cell(text)} |\n"


def _one_line(text: str) -> str:
    return " ".join(text.split())


def _cell(text: str) -> str:
    return _one_line(text).replace("|", "\\|")


def main() -> int:
    sys.stdout.write(markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main())

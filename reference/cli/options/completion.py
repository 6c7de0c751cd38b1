"""``topomark completion bash|zsh|tcsh``: a shell completion script, generated from the command line itself.

The command's options; it runs in :mod:`topomark.reference.cli.cmd_completion`."""

from __future__ import annotations

from topomark.reference.cli.parser import Later

SHELLS = ("bash", "zsh", "tcsh")

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser("completion", description=__doc__.split("\n\n")[0] + " Exit 0; 2 for an unknown shell.")
    p.add_argument("shell", choices=SHELLS, metavar="SHELL", help=f"the shell to complete in: {', '.join(SHELLS)}")
    p.set_defaults(handler=Later("cmd_completion", "completion_command"))

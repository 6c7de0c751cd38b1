"""``topomark completion bash|zsh|tcsh``: a shell completion script, generated from the command line itself.

The script is written by ``shtab`` from the same parser the commands use, so every command, option and fixed
choice completes, and a new one completes without editing the script.  Install it, e.g. for bash::

    topomark completion bash > ~/.local/share/bash-completion/completions/topomark

or for zsh, into a directory of ``$fpath`` as ``_topomark``.  Exit 0.
"""

from __future__ import annotations

from topomark.spec.errors import TopomarkFault

__all__ = ["register", "completion_command", "SHELLS"]

SHELLS = ("bash", "zsh", "tcsh")


def register(sub) -> None:
    p = sub.add_parser("completion", description=__doc__.split("\n\n")[0] + " Exit 0; 2 for an unknown shell.")
    p.add_argument("shell", choices=SHELLS, metavar="SHELL", help=f"the shell to complete in: {', '.join(SHELLS)}")
    p.set_defaults(handler=completion_command)


def completion_command(args) -> int:
    try:
        import shtab  # only here: nothing else needs it
    except ImportError:
        raise TopomarkFault("completion needs shtab, a dependency of topomark that is not installed here "
                            "(pip install shtab)") from None
    from topomark.reference.cli.main import build_parser

    print(shtab.complete(build_parser(), shell=args.shell), end="")
    return 0

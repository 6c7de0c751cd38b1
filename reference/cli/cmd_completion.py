"""Running ``topomark completion`` (its description and options: :mod:`topomark.reference.cli.options.completion`).

The script is written by ``shtab`` from the same parser the commands use, so every command, option and fixed
choice completes, and a new one completes without editing the script.  Install it, e.g. for bash::

    topomark completion bash > ~/.local/share/bash-completion/completions/topomark

or for zsh, into a directory of ``$fpath`` as ``_topomark``.  Exit 0.
"""

from __future__ import annotations

from topomark.spec.errors import TopomarkFault

__all__ = ["completion_command", "SHELLS"]

from topomark.reference.cli.options.completion import SHELLS


def completion_command(args) -> int:
    try:
        import shtab  # only here: nothing else needs it
    except ImportError:
        raise TopomarkFault("completion needs shtab, a dependency of topomark that is not installed here "
                            "(pip install shtab)") from None
    from topomark.reference.cli.main import build_parser

    print(shtab.complete(build_parser(), shell=args.shell), end="")
    return 0

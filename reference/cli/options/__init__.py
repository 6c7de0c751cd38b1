"""The options of every command: one module per ``cmd_*`` module, with its ``register(subparsers)``.

These modules import only argparse, :mod:`..parser`, :mod:`..args` and :mod:`..facts` (the names and limits
the help lists), so ``topomark COMMAND --help`` imports nothing the command needs to run; the command's own
module (``cmd_*``) is imported when it runs, by its handler (:class:`..parser.Later`).
"""

from topomark.reference.cli.facts import fact

__all__ = ["add_marker_bounds", "add_force", "FORCE_HELP"]

FORCE_HELP = ("write over an existing output file, or into a non-empty output directory (default: refuse, "
              "exit 2)")


def add_marker_bounds(p, largest: int) -> None:
    """The options that bound a search over small marked worlds (``census``, ``search``): the marker class, the
    largest world size (2..``largest``) and the largest vertex degree."""
    p.add_argument("--marker", required=True, metavar="CLASS", help="one of: " + ", ".join(fact("marker_classes")))
    p.add_argument("--max-vertices", type=int, required=True, metavar="N", help=f"largest world size, 2..{largest}")
    p.add_argument("--max-degree", type=int, required=True, metavar="D", help="largest vertex degree, >= 1")


def add_force(p, help: str = FORCE_HELP) -> None:
    """``--force``: the command may write over its existing outputs (the rule:
    :data:`topomark.reference.files.overwrite.RULE`)."""
    p.add_argument("--force", action="store_true", help=help)

"""``topomark algorithms [--json]``: the registered algorithms, their thesis references, kits and bounds.

The command's options; it runs in :mod:`topomark.reference.cli.cmd_algorithms`."""

from __future__ import annotations

from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser("algorithms", description=__doc__.split("\n\n")[0])
    p.add_argument("--json", action="store_true", help="a JSON list on stdout")
    p.set_defaults(handler=Later("cmd_algorithms", "algorithms_command"))

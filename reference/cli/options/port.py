"""The options of ``topomark port ACTION`` (the port-labelled model: :mod:`topomark.spec.port_world`).

Each action registers itself from a module of this folder named ``port_*.py`` with a
``register(actions)`` function (``actions`` is the ``port`` command's sub-parsers), found by name, so an action is
added by adding its module.
"""

from __future__ import annotations

import importlib
import pkgutil
from pathlib import Path

from topomark.reference.cli.parser import Parser

__all__ = ["register", "action_modules"]


def action_modules() -> list[str]:
    """The names of the modules that register ``port``'s actions, in name order."""
    here = str(Path(__file__).parent)
    return sorted(info.name for info in pkgutil.iter_modules([here]) if info.name.startswith("port_"))


def register(sub) -> None:
    p = sub.add_parser("port", description="The port-labelled robot (rooms with absolute door numbers and colours, "
                                           "plans with charcoal marks, as in the ICFP Contest 2025): import, export "
                                           "and run port worlds, judge two maps, find maps consistent with records.")
    actions = p.add_subparsers(dest="action", metavar="ACTION", parser_class=Parser)
    for name in action_modules():
        importlib.import_module(f"{__package__}.{name}").register(actions)
    names = sorted(actions.choices)
    p.set_defaults(handler=lambda args: _no_action(names))


def _no_action(names: list[str]) -> int:
    from topomark.spec.errors import InvalidInput

    raise InvalidInput("port needs an action: " + (", ".join(names) if names else "none is installed"))

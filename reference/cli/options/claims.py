"""``topomark claims [--json | --markdown]``: every claim of the thesis and how topomark backs it.

The command's options; it runs in :mod:`topomark.reference.cli.cmd_claims`."""

from __future__ import annotations

from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser("claims", description=__doc__.split("\n\n")[0] + " Exit 0.")
    form = p.add_mutually_exclusive_group()
    form.add_argument("--json", action="store_true", help="one JSON object: the claims and per-chapter counts")
    form.add_argument("--markdown", action="store_true", help="the Markdown page docs/claims.md")
    p.set_defaults(handler=Later("cmd_claims", "claims_command"))

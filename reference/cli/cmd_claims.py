"""``topomark claims [--json | --markdown]``: every claim of the thesis and how topomark backs it.

The ledger (:mod:`topomark.reference.claims.ledger`) lists each theorem, lemma, stated bound and
experimental statement of §2.3.1 and Chapters 3–6 with where the thesis states it, how topomark backs it
(proved, checked, tested, measured, assumed, unbacked) and the command that reproduces the
evidence.  Text by default, ``--json`` for one JSON object, ``--markdown`` for the page
``docs/claims.md``.  Exit 0.
"""

from __future__ import annotations

import json

from topomark.reference.claims import ledger, report

__all__ = ["register", "claims_command"]


def register(sub) -> None:
    p = sub.add_parser("claims", description=__doc__.split("\n\n")[0] + " Exit 0.")
    form = p.add_mutually_exclusive_group()
    form.add_argument("--json", action="store_true", help="one JSON object: the claims and per-chapter counts")
    form.add_argument("--markdown", action="store_true", help="the Markdown page docs/claims.md")
    p.set_defaults(handler=claims_command)


def claims_command(args) -> int:
    claims = ledger.load()
    if args.json:
        print(json.dumps(report.to_json(claims), indent=1, sort_keys=True, ensure_ascii=False))
    elif args.markdown:
        print(report.markdown(claims), end="")
    else:
        print(report.text(claims))
    return 0

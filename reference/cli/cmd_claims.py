"""Running ``topomark claims`` (its description and options: :mod:`topomark.reference.cli.options.claims`).

The ledger (:mod:`topomark.reference.claims.ledger`) lists each theorem, lemma, stated bound and
experimental statement of §2.3.1 and Chapters 3–6 with where the thesis states it, how topomark backs it
(proved, checked, tested, measured, assumed, unbacked) and the command that reproduces the
evidence.  Text by default, ``--json`` for one JSON object, ``--markdown`` for the page
``docs/claims.md``.  Exit 0.
"""

from __future__ import annotations

import json

from topomark.reference.claims import ledger, report

__all__ = ["claims_command"]


def claims_command(args) -> int:
    claims = ledger.load()
    if args.json:
        print(json.dumps(report.to_json(claims), indent=1, sort_keys=True, ensure_ascii=False))
    elif args.markdown:
        print(report.markdown(claims), end="")
    else:
        print(report.text(claims))
    return 0

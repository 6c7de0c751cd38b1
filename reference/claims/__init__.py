"""The claims ledger: every claim of the thesis, and how topomark backs it (``topomark claims``)."""

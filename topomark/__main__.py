"""``python -m topomark``: the ``topomark`` command (:mod:`topomark.reference.cli.main`), with the same exit codes."""

from __future__ import annotations

import sys

from topomark.reference.cli.main import main

__all__: list[str] = []

if __name__ == "__main__":
    sys.exit(main())

"""Shared by the tests of the independent clients written from a thesis listing (``reference/oracle/examples/``):
which modules a client imports, and a copy of it with one line changed (a seeded fault)."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "reference" / "oracle" / "examples"


def imported_modules(client: Path) -> set[str]:
    """Every module ``client`` imports (a standalone client: the standard library only)."""
    tree = ast.parse(client.read_text())
    imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
    return imported | {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}


def patched(client: Path, tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    """The command running a copy of ``client`` in ``tmp_path`` with its one occurrence of ``old`` made ``new``."""
    text = client.read_text()
    if old:
        assert text.count(old) == 1
        text = text.replace(old, new)
    copied = tmp_path / client.name
    copied.write_text(text)
    return [sys.executable, str(copied)]

"""The tests test this checkout: every subpackage of ``topomark`` is imported from the checkout's own files.

``pyproject.toml`` puts the checkout's root first on ``sys.path`` for pytest, so an installed copy of topomark
(a non-editable install, a stale wheel) can never stand in for the files under test.  :func:`foreign_packages`
states the condition; the first test asserts it for every package folder, and the second points it at a stale
copy of the package and checks that it fails there, naming the copy.
"""

from __future__ import annotations

import importlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def package_names(root: Path) -> dict[str, Path]:
    """Every package of the checkout at ``root``: its dotted name and the ``__init__.py`` it must come from."""
    found = {"topomark": root / "topomark" / "__init__.py"}
    for top in ("spec", "reference", "proofs"):
        for init in sorted((root / top).rglob("__init__.py")):
            parts = init.parent.relative_to(root).parts
            if "examples" not in parts:
                found[".".join(("topomark", *parts))] = init
    return found


def foreign_packages(root: Path) -> list[str]:
    """The packages that Python imports from somewhere other than the checkout at ``root`` (empty when none)."""
    wrong = []
    for name, init in package_names(root).items():
        module = importlib.import_module(name)
        where = Path(module.__file__ or "").resolve()
        if where != init.resolve():
            wrong.append(f"{name} from {where}")
    return wrong


def test_every_package_comes_from_this_checkout():
    names = package_names(ROOT)
    assert len(names) >= 20 and "topomark.reference.cli" in names and "topomark.spec" in names
    assert foreign_packages(ROOT) == []


def test_the_check_fails_against_a_stale_copy(tmp_path):
    """A copy of the package put first on the path (as an installed copy would be) is caught, package by package."""
    stale = tmp_path / "site"
    shutil.copytree(ROOT / "topomark", stale / "topomark", symlinks=False,
                    ignore=shutil.ignore_patterns("__pycache__"))
    code = ("import json, sys; sys.path.insert(0, %r); import test_checkout as t; "
            "print(json.dumps(t.foreign_packages(t.ROOT)))" % str(ROOT / "tests"))
    env = {**os.environ, "PYTHONPATH": str(stale)}
    p = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    wrong = json.loads(p.stdout)
    assert len(wrong) == len(package_names(ROOT))  # every package, not just the top one
    assert all(str(stale.resolve()) in w for w in wrong)

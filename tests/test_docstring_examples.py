"""Every ``>>>`` example in topomark runs, in every module of topomark (the API), topomark.spec, topomark.reference
and topomark.proofs.

The modules are found by walking the installed packages (a new module is covered without editing a list), and
each is imported under its installed name, so an example's ``topomark.spec.errors.InvalidInput: ...`` traceback
line matches.  Each test also counts the ``>>>`` lines in the module's source: an example that doctest cannot
find (in a comment, or on an object that another module defines) would otherwise never run, and is a failure.
"""

from __future__ import annotations

import doctest
import importlib
import io
import pkgutil
import re
from pathlib import Path

import pytest

import topomark
import topomark.proofs
import topomark.reference
import topomark.spec

PACKAGES = (topomark, topomark.spec, topomark.reference, topomark.proofs)
PROMPT = re.compile(r"^\s*>>>", re.M)


def _module_names() -> list[str]:
    """Every module once: walking ``topomark`` already reaches the modules of its subpackages, which are walked
    again from :data:`PACKAGES`' own entries."""
    names = set()
    for package in PACKAGES:
        names.add(package.__name__)
        names |= {info.name for info in pkgutil.walk_packages(package.__path__, package.__name__ + ".")}
    return sorted(names)


MODULES = _module_names()


@pytest.mark.slow
@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    tests = doctest.DocTestFinder().find(module)
    runner = doctest.DocTestRunner()  # the flags doctest.testmod uses; an example may set its own
    report = io.StringIO()
    for test in tests:
        runner.run(test, out=report.write)
    assert runner.failures == 0, report.getvalue()
    found = sum(len(test.examples) for test in tests)
    written = len(PROMPT.findall(Path(module.__file__).read_text(encoding="utf-8")))
    assert found == written, f"{name}: {written} '>>>' lines in the source, {found} examples found by doctest"


SCRIPTS = Path(topomark.reference.__path__[0]) / "oracle" / "examples"
"""Programs shipped as package data and run as subprocesses (the protocol's example clients), not modules."""
SCRIPT_FOLDERS = (SCRIPTS, Path(topomark.reference.__path__[0]) / "contest" / "examples")
"""Every such folder: the protocol's example clients and the contest server's example explorer."""


def test_every_source_file_is_a_walked_module():
    """A file the walk misses (a folder without ``__init__.py``) would have its examples pass unseen."""
    walked = {Path(importlib.import_module(name).__file__).resolve() for name in MODULES}
    on_disk = {path.resolve() for package in PACKAGES for folder in package.__path__
               for path in Path(folder).rglob("*.py") if path.parent not in SCRIPT_FOLDERS}
    assert sorted(map(str, on_disk - walked)) == []
    assert "topomark.proofs.census" in MODULES and "topomark.reference.worlds.generators" in MODULES
    assert "topomark" in MODULES and "topomark.exploration" in MODULES


def test_the_scripts_shipped_as_package_data_hold_no_examples():
    """An example in reference/oracle/examples/*.py would never run: show it in a module instead."""
    scripts = sorted(script for folder in SCRIPT_FOLDERS for script in folder.glob("*.py"))
    assert scripts
    assert [s.name for s in scripts if PROMPT.search(s.read_text(encoding="utf-8"))] == []

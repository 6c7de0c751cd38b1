"""The package's layering: one job per folder, every import pointing down, no circles.

The folders of ``reference/`` are ranked top to bottom (:data:`LAYERS`); a
module may import its own folder's modules and those of any folder ranked
below its own, never one above.  ``proofs/`` sits under every folder of
``reference/`` that uses it (the CLI's search commands, the wheel worlds) and
``spec/`` under everything.  The package's face (``topomark/``, imported as
``topomark`` itself: ``import topomark``, ``python -m topomark``) sits on top of
everything: it may import any folder, and no folder may import it.  Imports are read from the source (every ``import``
statement, including those inside functions), so a lazy import cannot hide an
arrow pointing up.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FACE = "topomark"
"""The folder of the ``topomark`` package's own modules (``topomark``, ``topomark.exploration``, ...)."""
LAYERS = (
    (FACE,),
    ("reference.cli",),
    ("reference.worstcase", "reference.contest"),
    ("reference.oracle", "reference.bench", "reference.claims", "reference.engine", "reference.port"),
    ("reference.viewer",),
    ("reference.replay",),
    ("reference.run",),
    ("reference.trace",),
    ("reference.algorithms",),
    ("reference.explorers", "reference.worlds"),
    ("reference.files",),
    ("proofs",),
    ("spec",),
)
RANK = {folder: rank for rank, folders in enumerate(LAYERS) for folder in folders}


SUBPACKAGES = ("spec", "reference", "proofs")


def modules() -> dict[str, Path]:
    found = {}
    for top in (*SUBPACKAGES, FACE):
        for path in (ROOT / top).rglob("*.py"):
            if "examples" in path.parts:
                continue  # standalone programs that speak the protocol; they import nothing of topomark
            parts = list(path.relative_to(ROOT).with_suffix("").parts)
            if parts[0] == FACE:  # face/ is installed as topomark itself
                parts.pop(0)
            if parts and parts[-1] == "__init__":
                parts.pop()
            found[".".join(["topomark", *parts])] = path
    return found


def imports_of(name: str, path: Path, known: set[str]) -> set[str]:
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package.split(".")[:len(package.split(".")) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            targets = [f"{module}.{a.name}" if f"{module}.{a.name}" in known else module for a in node.names]
        else:
            continue
        out.update(t for t in targets if t in known and t != name)
    return out


def folder_of(name: str) -> str:
    parts = name.split(".")[1:]
    if not parts or parts[0] not in SUBPACKAGES:
        return FACE
    if parts[0] != "reference":
        return parts[0]
    return ".".join(parts[:2]) if len(parts) > 2 or (len(parts) == 2 and parts[1] in
                                                     {f.split(".")[1] for f in RANK if "." in f}) else parts[0]


GRAPH = {name: imports_of(name, path, set(modules())) for name, path in modules().items()}


def test_every_folder_is_ranked():
    assert {folder_of(name) for name in GRAPH} - {"reference"} == set(RANK)


@pytest.mark.parametrize("name", sorted(GRAPH))
def test_imports_point_down(name):
    here = folder_of(name)
    if here == "reference":  # the package's own __init__: a docstring
        assert not GRAPH[name]
        return
    up = sorted(t for t in GRAPH[name] if folder_of(t) != here and RANK[folder_of(t)] <= RANK[here])
    assert not up, f"{name} ({here}) imports {up}: an arrow pointing up or sideways"


def circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Tarjan's strongly connected components of more than one module."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while not comp or comp[-1] != v:
                comp.append(stack.pop())
                on.discard(comp[-1])
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_circles():
    assert circles(GRAPH) == []


def test_the_circle_finder_finds_one():
    assert circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_the_face_is_walked_and_nothing_imports_it():
    face = {name for name in GRAPH if folder_of(name) == FACE}
    assert {"topomark", "topomark.exploration", "topomark.worlds"} <= face
    importers = sorted(name for name in GRAPH if folder_of(name) != FACE and GRAPH[name] & face)
    assert importers == []


def test_an_import_of_the_face_is_caught(tmp_path):
    fake = tmp_path / "fake.py"
    fake.write_text("import topomark\nfrom topomark.exploration import explore\n")
    found = imports_of("topomark.reference.run.fake", fake, set(modules()))
    assert found == {"topomark", "topomark.exploration"}
    assert all(folder_of(t) == FACE and RANK[FACE] < RANK["reference.run"] for t in found)


def test_explorers_import_only_spec_and_themselves():
    for name in (n for n in GRAPH if folder_of(n) == "reference.explorers"):
        bad = {t for t in GRAPH[name] if folder_of(t) not in ("reference.explorers", "spec")}
        assert not bad, f"{name} imports {bad}"


def test_an_upward_import_is_caught(tmp_path):
    fake = tmp_path / "fake.py"
    fake.write_text("from topomark.reference.run.checker import Checker\n")
    found = imports_of("topomark.reference.explorers.fake", fake, set(modules()))
    assert found == {"topomark.reference.run.checker"}
    assert RANK[folder_of(next(iter(found)))] < RANK["reference.explorers"]

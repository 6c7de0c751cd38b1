"""The wall between explorer and truth is structural.

Every module in ``reference/explorers/`` (found by listing the folder, so a
new explorer is covered without editing this file; the robot interface and
the policies it is handed live there too) may import only the spec's
signature, map-state, kit, error and spelling modules and each other; never the world,
the simulator, the checker or anything that can reach the truth.  The layering
of the whole package is tested in ``tests/test_layers.py``.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from topomark.reference.worlds import generators
from topomark.reference.explorers.robot import Robot
from topomark.reference.run.simulator import Simulator

ROOT = Path(__file__).resolve().parents[1]
EXPLORERS = ROOT / "reference" / "explorers"
EXPLORER_MODULES = sorted(p.name for p in EXPLORERS.glob("*.py"))
SIBLINGS = {f"topomark.reference.explorers.{p.stem}" for p in EXPLORERS.glob("*.py") if p.stem != "__init__"}
ALLOWED = {
    "__future__", "dataclasses", "typing", "collections",
    "topomark.spec.signature", "topomark.spec.mapstate", "topomark.spec.errors", "topomark.spec.kit",
    "topomark.spec.spelling",  # how a refusal names an option (a context variable): nothing of the world
} | SIBLINGS


def imports(path: Path) -> set[str]:
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            found.add("." * node.level + (node.module or ""))
    return found


@pytest.mark.parametrize("name", EXPLORER_MODULES)
def test_explorer_modules_import_nothing_that_sees_the_world(name):
    bad = imports(EXPLORERS / name) - ALLOWED
    assert not bad, f"explorers/{name} imports {bad}"


def test_the_contract_rejects_a_forbidden_import(tmp_path):
    sneaky = tmp_path / "sneaky.py"
    sneaky.write_text("from .simulator import Simulator\nimport topomark.spec.world\n"
                      "from topomark.reference.run.checker import Checker\n")
    assert imports(sneaky) - ALLOWED == {".simulator", "topomark.spec.world", "topomark.reference.run.checker"}


def test_robot_exposes_only_motions_perception_and_markers():
    sim = Simulator(generators.cycle(4), ("0", 0), {"directional-vertex": 1})
    robot = sim.robot()
    assert isinstance(robot, Robot)
    public = {name for name in dir(robot) if not name.startswith("_")}
    assert public == {"move", "sense", "operate", "drop_marker", "rewind"}  # rewind: a thread move (§6.3)
    assert not hasattr(robot, "__dict__")  # __slots__: nothing can be attached
    assert str(robot.move(1, "new")) == "[2,A,A]" and sim.cost == 1

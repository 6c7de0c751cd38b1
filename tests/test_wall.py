"""The wall between explorer and truth is structural (issue: the reference explorer).

Every module in ``reference/explorers/`` (found by listing the folder, so a
new explorer is covered without editing this file) and the two interface
modules it is handed (the robot and the policies) may import only the spec's
signature, map-state, kit and error modules, each other, and the robot and
policy modules; never the world, the simulator, the checker or anything that
can reach the truth.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from topomark.reference import generators
from topomark.reference.robot import Robot
from topomark.reference.simulator import Simulator

REFERENCE = Path(__file__).resolve().parents[1] / "reference"
EXPLORERS = REFERENCE / "explorers"
INTERFACE_MODULES = ["robot.py", "policies.py"]  # what explorers are handed: the robot, the open choices
EXPLORER_MODULES = INTERFACE_MODULES + sorted(f"explorers/{p.name}" for p in EXPLORERS.glob("*.py"))
SIBLINGS = {f".{p.stem}" for p in EXPLORERS.glob("*.py") if p.stem != "__init__"}  # any module of the folder
ALLOWED = {
    "__future__", "dataclasses", "typing", "collections",
    "topomark.spec.signature", "topomark.spec.mapstate", "topomark.spec.errors", "topomark.spec.kit",
    ".policies", "..policies", "..robot",
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
    bad = imports(REFERENCE / name) - ALLOWED
    assert not bad, f"{name} imports {bad}"


def test_the_contract_rejects_a_forbidden_import(tmp_path):
    sneaky = tmp_path / "sneaky.py"
    sneaky.write_text("from .simulator import Simulator\nimport topomark.spec.world\n")
    assert imports(sneaky) - ALLOWED == {".simulator", "topomark.spec.world"}


def test_robot_exposes_only_motions_perception_and_markers():
    sim = Simulator(generators.cycle(4), ("0", 0), {"directional-vertex": 1})
    robot = sim.robot()
    assert isinstance(robot, Robot)
    public = {name for name in dir(robot) if not name.startswith("_")}
    assert public == {"move", "sense", "operate", "drop_marker", "rewind"}  # rewind: a thread move (§6.3)
    assert not hasattr(robot, "__dict__")  # __slots__: nothing can be attached
    assert str(robot.move(1, "new")) == "[2,A,A]" and sim.cost == 1

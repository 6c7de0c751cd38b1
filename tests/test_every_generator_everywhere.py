"""Every built-in world generator's output, written by ``topomark world`` with its defaults, is accepted by every
command that takes a world: ``explore`` maps it (and writes the map), ``check-map`` accepts that map, and
``run-external`` with the example client passes on it."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.worlds.generators import GENERATORS

CLIENT = [sys.executable, str(Path(__file__).resolve().parents[1] / "reference" / "oracle" / "examples" / "client.py")]
SMALL = {"lattice-hole": "rows=5,cols=5", "small-world": "n=12", "random": "n=8",
         "rewired-strip": "n=46"}  # the rest at their defaults (the rewired strip's, n = 100, costs the example
#                                   client about a million traversals: more than run-external's default time limit)


@pytest.mark.parametrize("name", sorted(GENERATORS))
def test_every_generator_everywhere(name, tmp_path, capsys):
    world, mapped = tmp_path / "w.json", tmp_path / "m.json"
    text = f"{name}:{SMALL[name]}" if name in SMALL else name
    assert main(["world", text, "-o", str(world)]) == 0
    assert main(["explore", str(world), "--quiet", "--map", str(mapped)]) == 0, capsys.readouterr()
    assert main(["check-map", str(world), str(mapped)]) == 0, capsys.readouterr()
    assert main(["run-external", str(world), "--", *CLIENT]) == 0, capsys.readouterr()

"""What ``topomark bench comparison-markers`` runs: the thesis's marker algorithms beside Table 2.3's classic
baselines on the Chapter 4 worlds (lattice-hole, complete-hole; thesis §2.3.1, Table 2.3).  Registered in
:mod:`~topomark.reference.bench.plan`'s tables when this module is imported; the report is
:mod:`~topomark.reference.bench.reports.marker_classes`.

Examples
--------
>>> EXPERIMENTS[NAME].parts[0].family, EXPERIMENTS[NAME].parts[1].family
('lattice-hole', 'complete-hole')
>>> set(BASELINES) < set(COMPARED)
True
"""

from __future__ import annotations

from topomark.reference.bench.plan import EXPERIMENTS, Experiment, Part

__all__ = ["NAME", "COMPARED", "BASELINES", "SIZES"]

NAME = "comparison-markers"
BASELINES = ("footprints", "labelled-dfs")
"""Table 2.3's classic rows: m + n homogeneous markers and the labelled graph."""
COMPARED = ("basic", "dudek", "case-1a", "case-2", "footprints", "case-3b", "case-dv-sum", "thread-knots",
            "labelled-dfs")
"""One immovable marker (Algorithm 3.1), one movable marker (§2.3.1), m and m + n markers (§6.2.1 Cases 1a, 2 and
the footprints model), Σ k markers (Case 3b, §6.2.2), a long thread (§6.3) and the labelled graph: fewest markers
first, most last."""
SIZES = {"lattice-hole": (90, 202, 360), "complete-hole": (24, 40, 55)}

EXPERIMENTS[NAME] = Experiment(
    NAME, tuple(Part(family, COMPARED, sizes) for family, sizes in SIZES.items()),
    "Marker classes side by side: the thesis's algorithms and Table 2.3's classic baselines on the Chapter 4 worlds")

"""Benchmark experiments: Figures 3.10-3.12 and Tables 4.1-4.8 of the thesis, checked and resumable.

``topomark bench EXPERIMENT [--graphs 30] [--sizes ...] [--jobs N] [--out DIR]``

Worlds (world families; the *size* of a row is the thesis's vertex count):

``lattice-hole``
    Figure 3.10(c), Tables 4.1/4.3/4.5/4.7.  *Interpretation:* the thesis's
    sizes 72, 90, 108, 152, 202, 230, 260, 324, 360 are 8x10, 10x10, 10x12,
    13x13, 15x15, 16x16, 17x17, 19x19, 20x20 grids (80 ... 400 vertices) with
    10% of the *vertices* removed at random, keeping the graph connected
    (:func:`~topomark.reference.worlds.generators.lattice_hole`); the resulting n is
    exactly the thesis's size (rounded).
``complete-hole``
    Figure 3.10(d), Tables 4.2/4.4/4.6/4.8.  *Interpretation:* K_n on n = 24,
    28, ..., 55 vertices with 10% of the *edges* removed, kept connected.
``lattice``, ``complete``
    Figure 3.10(a)/(b): the same grids (no holes) and K_n; the graph is fixed,
    so the 30 "graphs" of a size differ in their start (vertex and facing).
``small-world-k2-p10``, ``small-world-k4-p20``
    Figure 3.11: ring of n vertices, k nearest neighbours, shortcuts with
    probability p (:func:`~topomark.reference.worlds.generators.small_world`).
``random-20``, ``random-40``
    Figure 3.12: random connected graphs with 20% / 40% of all vertex pairs
    as edges (:func:`~topomark.reference.worlds.generators.random_graph`).

Every world of seed ``s`` is built from fixed seeds derived from (world family,
size, s), and the robot starts at a vertex and facing drawn from the same
seed, so each algorithm of a row explores exactly the same worlds.

Experiments (EXPERIMENT names) pick world families, algorithms and sizes:
``figure-3.10``, ``figure-3.11``, ``figure-3.12`` (basic; every world family
alone is an experiment too), ``table-4.1`` ... ``table-4.8``, ``tables`` (all of
4.1-4.8: lattice-hole and complete-hole with every enhancement),
``policies`` (edge-selection policies side by side, basic and enh3),
``lighthouses`` (the lighthouses of §3.3, §6.1 and §6.2 side by side, basic
and enh3: :mod:`~topomark.reference.bench.reports.lighthouses`), ``all``; and §6.2's
marker algorithms (kit algorithms, :mod:`~topomark.reference.bench.reports.section62`):
``table-6.1`` (with Figures 6.11, 6.12), ``table-6.2`` (Figures 6.17, 6.18),
``figure-6.13`` and ``section-6.2`` (all three; not part of ``all``); and §6.3's
threads with §2.3.1's movable markers (:mod:`~topomark.reference.bench.reports.section63`,
which also defines the ``lattice-edge-hole`` world family): ``table-6.3`` (with Figure
6.23), ``figure-6.24``, ``comparison`` and ``section-6.3`` (all three; not part of ``all``);
``chapter-5`` (§5.1, §6.1, §5.2.1 and Algorithm 5.1 on the Chapter 3 world families, small worlds and
Figure 3.4: :mod:`~topomark.reference.bench.reports.chapter5`; not part of ``all``); ``comparison-markers``
(the thesis's marker algorithms beside Table 2.3's classic baselines, the footprints model and the labelled
graph, on lattice-hole and complete-hole worlds: :mod:`~topomark.reference.bench.reports.marker_classes`; not
part of ``all``).

Runs go to ``DIR/runs.csv`` keyed by (experiment = world family, size, seed,
algorithm, edge policy, lighthouse); a restarted sweep skips keys already there.  Each
run is checked (invariants after every iteration, final isomorphism) unless
``--no-check``; the row records ``verified``.  The report ``DIR/EXPERIMENT.md``
and plots ``DIR/EXPERIMENT-*.png`` are generated from the CSV.  One sweep at
a time works in a directory (``DIR/.lock``), and a file damaged by a killed
sweep is repaired when read (:mod:`~topomark.reference.bench.run_store`).

Heavy rows: Enhancement-5 with d = 2 on complete-hole worlds invests
Θ(n^4) expansion traversals (§4.2: "O(n^4) extra traversals"; 6.2 million
moves and about 18 CPU-seconds for one checked run at n = 55), so the
experiments run that row on ``HEAVY_GRAPHS`` graphs per size
(``--heavy-graphs``; its cost varies little between worlds) and only up to
size ``HEAVY_MAX_SIZE`` (``--heavy-max-size``); the report marks the row.

The modules, one concept each: :mod:`~topomark.reference.bench.plan` (worlds,
experiments, the plan of runs), :mod:`~topomark.reference.bench.runs` (running
and appending), :mod:`~topomark.reference.bench.reports.chapter34` (the report and plots, on the report kit
:mod:`~topomark.reference.bench.reports.kit`), :mod:`~topomark.reference.bench.reports.lighthouses`
(the lighthouses' report) and
:mod:`~topomark.reference.bench.run_store` (the CSV).  This module is their front:
the names the CLI and the tests use.
"""

from __future__ import annotations

from pathlib import Path

from topomark.reference.bench.reports import chapter5, chapter34, lighthouses, marker_classes, section62, section63  # section63 registers §6.3's runs
from topomark.reference.bench.plan import (EXPERIMENTS, FAMILIES, HEAVY_GRAPHS, HEAVY_MAX_SIZE, Experiment, Part, Run, fits,
                         is_heavy, plan, world_for)
from topomark.reference.bench.reports.chapter34 import reduction, summarize
from topomark.reference.bench.reports.stats import latest
from topomark.reference.bench.runs import Progress, run_one, run_sweep
from topomark.reference.bench.run_store import CSV_FIELDS

__all__ = ["FAMILIES", "EXPERIMENTS", "Experiment", "Part", "Run", "plan", "world_for", "fits", "is_heavy",
           "run_one", "run_sweep", "Progress", "write_report", "summarize", "latest", "reduction", "CSV_FIELDS",
           "HEAVY_GRAPHS", "HEAVY_MAX_SIZE"]


def write_report(experiment: str, out: Path, wall: float | None = None, plots: bool = True) -> Path:
    """Generate ``out/EXPERIMENT.md`` (and plots) from ``out/runs.csv``; ``all`` also writes ``lighthouses.md``."""
    if experiment == "lighthouses":
        return lighthouses.write_report(out, wall, plots)
    if experiment == chapter5.NAME:
        return chapter5.write_report(out, wall, plots)
    if experiment in section62.REPORTS:
        return section62.write_report(experiment, out, wall, plots)
    if experiment == marker_classes.NAME:
        return marker_classes.write_report(out, wall, plots)
    if experiment in section63.REPORTS:
        return section63.write_report(experiment, out, wall, plots)
    if experiment == "all":
        lighthouses.write_report(out, None, plots)
    return chapter34.write_report(experiment, out, wall, plots)

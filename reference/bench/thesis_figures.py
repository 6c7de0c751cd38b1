"""The thesis's published numbers, transcribed from Chapters 3 and 4, each with its source.

Only numbers printed in the text or in tables are transcribed; Figures 3.10-3.12
and 4.2-4.8 are plots whose values are not printed (except the ones quoted in
§4.1's text), so for them the benchmark report leaves the thesis column empty.

Sizes are the thesis's vertex counts: lattice-hole 72 ... 360, complete-hole
24 ... 55 (Tables 4.1-4.8).  Percentages are the "average percent cost
reductions" against the basic algorithm (Algorithm 3.1).
"""

from __future__ import annotations

__all__ = ["ABSOLUTE", "REDUCTIONS", "TABLE_SOURCES", "LATTICE_HOLE_SIZES", "COMPLETE_HOLE_SIZES",
           "thesis_cost", "thesis_reduction"]

LATTICE_HOLE_SIZES = (72, 90, 108, 152, 202, 230, 260, 324, 360)
COMPLETE_HOLE_SIZES = (24, 28, 32, 36, 40, 44, 48, 52, 55)

ABSOLUTE: dict[tuple[str, str, int], tuple[int, str]] = {
    # (world family, algorithm, size) -> (mean cost in edge traversals, source)
    ("lattice-hole", "basic", 90): (13_800, "§4.1 Enhancement-1 text (Figure 4.2(a))"),
    ("lattice-hole", "basic", 260): (152_000, "§4.1 Enhancement-1 text (Figure 4.2(a))"),
    ("lattice-hole", "enh1", 90): (4_600, "§4.1 Enhancement-1 text (Figure 4.2(a))"),
    ("lattice-hole", "enh1", 260): (37_000, "§4.1 Enhancement-1 text (Figure 4.2(a))"),
    ("lattice-hole", "enh2", 90): (3_400, "§4.1 Enhancement-2 text (Figure 4.4(a))"),
    ("lattice-hole", "enh2", 260): (24_000, "§4.1 Enhancement-2 text (Figure 4.4(a))"),
    ("lattice-hole", "enh3", 90): (2_650, "§4.1 Enhancement-3 text (Figure 4.6(a))"),
    ("lattice-hole", "enh3", 260): (15_000, "§4.1 Enhancement-3 text (Figure 4.6(a))"),
}

_L, _C = LATTICE_HOLE_SIZES, COMPLETE_HOLE_SIZES


def _row(sizes, values):
    return dict(zip(sizes, values))


REDUCTIONS: dict[tuple[str, str], tuple[dict[int, float], str]] = {
    # (world family, algorithm) -> ({size: percent reduction}, source)
    ("lattice-hole", "enh1"): (_row(_L, (67.5, 67.8, 68.4, 70.1, 74.5, 75.5, 75.7, 77.4, 78.0)), "Table 4.1"),
    ("lattice-hole", "enh2"): (_row(_L, (73.5, 75.3, 78.0, 80.2, 84.3, 86.0, 86.4, 87.8, 89.0)), "Table 4.1"),
    ("lattice-hole", "enh3"): (_row(_L, (81.7, 82.8, 83.6, 86.0, 88.8, 89.9, 90.4, 91.9, 93.0)),
                               "Tables 4.1, 4.7"),
    ("complete-hole", "enh1"): (_row(_C, (45.7, 53.7, 53.8, 53.8, 57.0, 57.4, 58.9, 63.7, 63.4)), "Table 4.2"),
    ("complete-hole", "enh2"): (_row(_C, (69.7, 76.5, 78.5, 78.7, 81.2, 83.3, 84.7, 87.5, 86.5)), "Table 4.2"),
    ("complete-hole", "enh3"): (_row(_C, (75.0, 82.9, 83.3, 84.1, 86.6, 89.0, 89.9, 90.7, 91.2)),
                                "Tables 4.2, 4.8"),
    ("lattice-hole", "enh4"): (_row(_L, (36.5, 37.7, 36.8, 38.0, 34.8, 33.8, 30.2, 37.7, 35.3)),
                               "Tables 4.3, 4.5"),
    ("complete-hole", "enh4"): (_row(_C, (72.3, 73.7, 74.2, 78.7, 79.9, 81.2, 83.2, 86.1, 84.6)),
                                "Tables 4.4, 4.6, 4.8"),
    ("lattice-hole", "enh5-d1"): (_row(_L, (58.9, 55.7, 66.7, 68.1, 69.0, 72.1, 68.2, 69.5, 68.9)), "Table 4.5"),
    ("lattice-hole", "enh5-d2"): (_row(_L, (68.6, 71.2, 77.3, 82.6, 86.6, 87.9, 87.8, 89.4, 91.2)),
                                  "Tables 4.5, 4.7"),
    # Table 4.6 has no column for size 24.
    ("complete-hole", "enh5-d1"): (_row(_C[1:], (37.3, 31.9, 21.5, 34.1, 42.0, 41.5, 37.9, 39.7)), "Table 4.6"),
    ("complete-hole", "enh5-d2"): (_row(_C[1:], (-1145, -1454, -1944, -1805, -1970, -1962, -2291, -2372)),
                                   "Table 4.6"),
    ("lattice-hole", "enh3+5"): (_row(_L, (83.1, 83.1, 85.1, 87.6, 90.1, 90.8, 91.9, 93.0, 94.0)), "Table 4.7"),
    ("complete-hole", "enh3+4"): (_row(_C, (78.9, 86.7, 86.7, 86.8, 89.3, 91.4, 91.9, 92.1, 92.8)), "Table 4.8"),
}

TABLE_SOURCES: dict[str, tuple[str, tuple[str, ...]]] = {
    # table -> (world family, algorithms it lists)
    "4.1": ("lattice-hole", ("enh1", "enh2", "enh3")),
    "4.2": ("complete-hole", ("enh1", "enh2", "enh3")),
    "4.3": ("lattice-hole", ("enh4",)),
    "4.4": ("complete-hole", ("enh4",)),
    "4.5": ("lattice-hole", ("enh4", "enh5-d1", "enh5-d2")),
    "4.6": ("complete-hole", ("enh4", "enh5-d1", "enh5-d2")),
    "4.7": ("lattice-hole", ("enh3", "enh5-d2", "enh3+5")),
    "4.8": ("complete-hole", ("enh3", "enh4", "enh3+4")),
}


def thesis_cost(world_family: str, algorithm: str, size: int) -> tuple[int, str] | None:
    return ABSOLUTE.get((world_family, algorithm, size))


def thesis_reduction(world_family: str, algorithm: str, size: int) -> tuple[float, str] | None:
    row = REDUCTIONS.get((world_family, algorithm))
    if row is None or size not in row[0]:
        return None
    return row[0][size], row[1]

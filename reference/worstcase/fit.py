"""How the worst cost found grows: least-squares exponents on log-log axes (thesis §7.2).

§7.2 asks whether the O(m²n) bound of Algorithm 3.1 is tight and suggests bounds in terms of the
diameter and the maximum degree as well as m and n (§7.2).  Given the worst worlds found at several sizes,
:func:`fit_exponents` measures the growth: for each of m, n, the diameter and the maximum degree, the slope
of log(cost) against log(x) (``numpy.polyfit``, degree 1) with its R² and, over three rows or more, the
95 % confidence interval of the slope (Student's t with rows − 2 degrees of freedom), and the two-factor fit
cost ≈ c·m^a·n^b (``numpy.linalg.lstsq`` on [1, log m, log n]).  A factor with fewer than two distinct values
(or a two-factor fit with no more rows than its three parameters — three points fit any c, a, b exactly, with
R² = 1 — or collinear log m and log n) has no fit: ``None``.

>>> rows = [{"n": n, "m": m, "diameter": 3, "max_degree": 4, "cost": 3 * m * m}
...         for n, m in ((4, 5), (8, 12), (16, 30))]
>>> fit = fit_exponents(rows)
>>> fit["m"]
{'exponent': 2.0, 'r2': 1.0, 'ci95': [2.0, 2.0]}
>>> fit["diameter"] is None
True
>>> rows = [{"n": n, "m": m, "diameter": 1, "max_degree": 3, "cost": 2 * m**2 * n}
...         for n, m in ((4, 5), (8, 9), (6, 14), (10, 20))]
>>> fit_exponents(rows)["m_n"]
{'c': 2.0, 'a': 2.0, 'b': 1.0, 'r2': 1.0}
"""

from __future__ import annotations

from typing import Any, Iterable, Mapping

import numpy as np

from topomark.spec.errors import InvalidInput

__all__ = ["fit_exponents", "FACTORS"]

FACTORS = ("m", "n", "diameter", "max_degree")
_DIGITS = 6
_T975 = (12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.16, 2.145, 2.131,
         2.12, 2.11, 2.101, 2.093, 2.086, 2.08, 2.074, 2.069, 2.064, 2.06, 2.056, 2.052, 2.048, 2.045, 2.042)
"""The 97.5 % quantile of Student's t with 1 … 30 degrees of freedom (past 30: 1.96, the normal's)."""


def _r2(y: np.ndarray, predicted: np.ndarray) -> float | None:
    total = float(np.sum((y - y.mean()) ** 2))
    if total == 0.0:
        return None
    return round(1.0 - float(np.sum((y - predicted) ** 2)) / total, _DIGITS)


def _one_factor(x: np.ndarray, y: np.ndarray) -> dict[str, Any] | None:
    if len(set(x.tolist())) < 2:
        return None
    slope, intercept = np.polyfit(x, y, 1)
    out: dict[str, Any] = {"exponent": round(float(slope), _DIGITS), "r2": _r2(y, slope * x + intercept)}
    if len(x) >= 3:  # one degree of freedom left for the residuals
        df = len(x) - 2
        spread = float(np.sum((y - (slope * x + intercept)) ** 2)) / df / float(np.sum((x - x.mean()) ** 2))
        half = (_T975[df - 1] if df <= len(_T975) else 1.96) * spread ** 0.5
        out["ci95"] = [round(float(slope) - half, _DIGITS), round(float(slope) + half, _DIGITS)]
    return out


def _two_factor(logm: np.ndarray, logn: np.ndarray, y: np.ndarray) -> dict[str, Any] | None:
    design = np.column_stack([np.ones_like(logm), logm, logn])
    if len(y) <= 3 or np.linalg.matrix_rank(design) < 3:
        return None
    (b0, a, b), *_ = np.linalg.lstsq(design, y, rcond=None)
    c = float(f"{float(np.exp(b0)):.{_DIGITS}g}")
    return {"c": c, "a": round(float(a), _DIGITS), "b": round(float(b), _DIGITS),
            "r2": _r2(y, design @ np.array([b0, a, b]))}


def _column(rows: list[Mapping[str, Any]], key: str) -> np.ndarray:
    values = []
    for k, row in enumerate(rows):
        x = row.get(key) if isinstance(row, Mapping) else None
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not x > 0:
            raise InvalidInput(f"fit_exponents: row {k} needs a positive number {key!r}, got {x!r}")
        values.append(float(x))
    return np.log(np.array(values))


def fit_exponents(rows: Iterable[Mapping[str, Any]]) -> dict[str, Any]:
    """The exponents of ``cost`` against each of :data:`FACTORS` and the fit cost ≈ c·m^a·n^b, as plain dicts
    rounded to 6 decimals (``c`` to 6 significant digits): ``{factor: {"exponent", "r2"} or None,
    "m_n": {"c", "a", "b", "r2"} or None, "rows": count}``.  ``r2`` is None where log(cost) does not vary.
    A row missing a positive number for a factor or the cost is bad input."""
    rows = list(rows)
    if not rows:
        raise InvalidInput("fit_exponents needs at least one row")
    y = _column(rows, "cost")
    logs = {f: _column(rows, f) for f in FACTORS}
    out: dict[str, Any] = {f: _one_factor(logs[f], y) for f in FACTORS}
    out["m_n"] = _two_factor(logs["m"], logs["n"], y)
    out["rows"] = len(rows)
    return out

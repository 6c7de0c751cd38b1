"""The registry of exploration algorithms selectable with ``topomark explore --algorithm NAME``.

Each entry is an explorer class taking ``(robot, policies, observer)`` and
offering ``start()``, ``iterate()``, ``S``, ``position`` and ``iterations``
like :class:`~topomark.reference.lighthouse.LighthouseExplorer` (Algorithm 3.1,
``basic``).  Variants register themselves here.
"""

from __future__ import annotations

from .lighthouse import LighthouseExplorer

__all__ = ["ALGORITHMS"]

ALGORITHMS: dict[str, type] = {"basic": LighthouseExplorer}

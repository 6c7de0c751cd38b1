"""The registry of exploration algorithms selectable with ``topomark explore --algorithm NAME``.

Each entry is an explorer class taking ``(robot, policies, observer)`` and
offering ``start()``, ``iterate()``, ``S``, ``position`` and ``iterations``
like :class:`~topomark.reference.lighthouse.LighthouseExplorer` (Algorithm 3.1,
``basic``).  Variants register themselves here.
"""

from __future__ import annotations

from .enhancements import EXPLORERS
from .lighthouse import LighthouseExplorer

__all__ = ["ALGORITHMS"]

ALGORITHMS: dict[str, type] = {"basic": LighthouseExplorer, **EXPLORERS}
"""``basic`` (Algorithm 3.1) and the Chapter 4 enhancements: ``enh1``, ``enh2``, ``enh3``, ``enh4``,
``enh5-d1``, ``enh5-d2``, ``enh3+4``, ``enh3+5`` (see :mod:`topomark.reference.enhancements`)."""

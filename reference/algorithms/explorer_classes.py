"""The registry of exploration algorithms selectable with ``topomark explore --algorithm NAME``.

Each entry is an explorer class taking ``(robot, policies, observer)`` and
offering ``start()``, ``iterate()``, ``S``, ``position`` and ``iterations``
like :class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`
(Algorithm 3.1, ``basic``); the Chapter 4 algorithms are compositions of
techniques on its template (:mod:`topomark.reference.explorers.compositions`).
"""

from __future__ import annotations

from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.compositions import EXPLORERS

__all__ = ["ALGORITHMS"]

ALGORITHMS: dict[str, type] = {"basic": LighthouseExplorer, **EXPLORERS}
"""``basic`` (Algorithm 3.1) and the Chapter 4 enhancements: ``enh1``, ``enh2``, ``enh3``, ``enh4``,
``enh5-d1``, ``enh5-d2``, ``enh3+4``, ``enh3+5`` (see :mod:`topomark.reference.explorers.compositions`)."""

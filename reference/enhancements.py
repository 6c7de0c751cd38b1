"""Re-export of the Chapter 4 enhancements (thesis §4.1–4.3), now in :mod:`topomark.reference.explorers`.

The template and its hooks: :mod:`~topomark.reference.explorers.algorithm31`;
the techniques: :mod:`~topomark.reference.explorers.overlap`,
:mod:`~topomark.reference.explorers.tracing`,
:mod:`~topomark.reference.explorers.records`,
:mod:`~topomark.reference.explorers.expansion`; the explorer over the
execution trie: :mod:`~topomark.reference.explorers.enhanced`; the named
algorithms: :mod:`~topomark.reference.explorers.compositions`.  Kept for the
modules that still import from here.
"""

from __future__ import annotations

from .explorers.compositions import ENHANCEMENTS, EXPLORERS
from .explorers.enhanced import EnhancedExplorer, EnhancedHypothesis, EnhancedIteration, Enhancement

__all__ = ["EnhancedExplorer", "ENHANCEMENTS", "EXPLORERS", "EnhancedHypothesis", "EnhancedIteration", "Enhancement"]

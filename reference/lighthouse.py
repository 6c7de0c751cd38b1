"""Re-export of Algorithm 3.1 (thesis §3.3), now :mod:`topomark.reference.explorers.algorithm31`.

Kept for the modules that still import from here; import from
``topomark.reference.explorers.algorithm31`` in new code.
"""

from __future__ import annotations

from .explorers.algorithm31 import V0, Hypothesis, Iteration, LighthouseExplorer

__all__ = ["Hypothesis", "Iteration", "LighthouseExplorer", "V0"]

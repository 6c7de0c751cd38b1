"""Hypothesis strategies for random worlds and extended-isomorphic copies (thesis §3.1.1, §3.1.3).

The strategies of :mod:`topomark.reference.worlds.strategies`, for other implementations' test suites:
:func:`worlds` draws valid worlds (connected, simple, every degree >= 1, random clockwise orders), with
markers and a start if asked; :func:`relabelled` and :func:`rotated` copy a world under a vertex renaming or a
change of reference exits, which a correct mapper must not tell apart from the original.

Examples
--------
>>> from hypothesis import given, settings
>>> import topomark
>>> @settings(max_examples=5, deadline=None)
... @given(worlds(max_vertices=4))
... def test(w):
...     assert topomark.isomorphic(w, w) is not None
>>> test()
"""

from __future__ import annotations

from topomark.reference.worlds.strategies import MARKER_KINDS, relabelled, rotated, worlds

__all__ = ["worlds", "relabelled", "rotated", "MARKER_KINDS"]

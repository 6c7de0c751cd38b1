"""Moved: marker classes are the spec concept :mod:`topomark.spec.markerclass` (issue 10).

This module re-exports them for code written against the old location.
"""

from topomark.spec.markerclass import MARKER_CLASSES, MarkerClass, marker_class

__all__ = ["MarkerClass", "MARKER_CLASSES", "marker_class"]

"""Moved: marker classes are the spec concept :mod:`topomark.spec.kit` (issue 10).

This module re-exports them for code written against the old location.
"""

from topomark.spec.kit import MARKER_CLASSES, Kit, MarkerClass, marker_class

__all__ = ["MarkerClass", "MARKER_CLASSES", "marker_class", "Kit"]

"""Timing and measurement scripts, each run as ``python -m topomark.reference.bench.measure.NAME``."""

"""Registrations of the algorithm families beyond Algorithm 3.1 and Chapter 4, one module per family.

Each module defines ``SPECS``, a tuple of
:class:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec` naming its explorer
class (which lives in :mod:`topomark.reference.explorers`, behind the wall).
:mod:`topomark.reference.algorithms.registry` lists this folder, so adding a family
touches no shared file.
"""

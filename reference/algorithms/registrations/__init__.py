"""Registrations of every algorithm, one module per family: Algorithm 3.1 and Chapter 4 (:mod:`.algorithm31`),
the movable marker (:mod:`.movable`, §2.3.1), the model tree (:mod:`.model_tree`, §5.2.2), the multiple markers of
§6.2 (:mod:`.markers_62`, :mod:`.markers_621`, :mod:`.markers_622`, :mod:`.markers_case5`) and the threads
(:mod:`.threads`, §6.3).

Each module defines ``SPECS``, a tuple of
:class:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec` (every field given by name) naming its
explorer class, which lives in :mod:`topomark.reference.explorers`, behind the wall.
:mod:`topomark.reference.algorithms.registry` lists this folder, so adding an algorithm touches no shared file
(``docs/adding-an-algorithm.md``).
"""

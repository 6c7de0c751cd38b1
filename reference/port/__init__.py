"""The port-labelled robot's jobs beyond its definition (:mod:`topomark.spec.port_world`, :mod:`topomark.spec.port_plan`):
judging two maps exactly, minimising a map, running plans, reading and writing the contest's files.

This folder sits beside the thesis's run core and imports only :mod:`topomark.spec`, :mod:`topomark.proofs` and
:mod:`topomark.reference.files`; nothing of the thesis's explorers depends on it.
"""

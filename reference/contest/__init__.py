"""A local server speaking the ICFP Contest 2025's HTTP interface (``/select``, ``/explore``, ``/guess``), judging
guesses exactly with :mod:`topomark.reference.port`."""

"""The bench's reports: one module per part of the thesis, each written by :mod:`.kit` (the report skeleton) with
:mod:`.stats`, :mod:`.text` and :mod:`.plots` (the statistics, formatting and plot style every report shares)."""

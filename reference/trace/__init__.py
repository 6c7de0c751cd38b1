"""The trace format (``spec/trace.md``): :mod:`.records` (format names and record builders),
:mod:`.header`, :mod:`.families` (each algorithm family's algorithm layer), :mod:`.reader` and :mod:`.sink`."""

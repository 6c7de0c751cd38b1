"""The thesis's experiments, checked and resumable (``topomark bench``).

:mod:`.experiments` (the command's entry), :mod:`.plan` and :mod:`.plan_threads` (what each sweep runs),
:mod:`.runs` (one checked run), :mod:`.run_store` (results on disk), :mod:`.thesis_figures` (the thesis's
published numbers); :mod:`.reports` writes the reports; :mod:`.measure` holds the ``python -m`` timing scripts.
"""

"""Worlds: :mod:`.generators` (the named generators of ``topomark world``) over :mod:`.deterministic`,
:mod:`.holes`, :mod:`.random_worlds` and :mod:`.embedding`; :mod:`.argument` (a world named on the command line);
:mod:`.strategies` (hypothesis strategies for other test suites)."""

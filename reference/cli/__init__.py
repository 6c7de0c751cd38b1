"""The ``topomark`` command line: :mod:`.main` parses and dispatches, one ``cmd_*`` module per command."""

"""The options of every command: one module per ``cmd_*`` module, with its ``register(subparsers)``.

These modules import only argparse, :mod:`..parser`, :mod:`..args` and :mod:`..facts` (the names and limits
the help lists), so ``topomark COMMAND --help`` imports nothing the command needs to run; the command's own
module (``cmd_*``) is imported when it runs, by its handler (:class:`..parser.Later`).
"""

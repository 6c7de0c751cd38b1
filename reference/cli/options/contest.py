"""The options of ``topomark contest ACTION`` (:mod:`..cmd_contest`): a local server speaking the ICFP Contest
2025's HTTP interface, judging guesses exactly."""

from __future__ import annotations

from topomark.reference.cli.args import seed
from topomark.reference.cli.options import add_force
from topomark.reference.cli.parser import Later, Parser

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser("contest", description="The ICFP Contest 2025 (\"Aedificium\") on the local host: a server "
                                              "speaking the contest's HTTP interface, for explorers written for it.")
    actions = p.add_subparsers(dest="action", metavar="ACTION", parser_class=Parser)
    s = actions.add_parser(
        "serve", help="serve /register, /select, /explore and /guess; Ctrl-C stops it",
        description="Serve the contest's HTTP interface (POST /register, /select, /explore, /guess, JSON bodies "
                    "as the contest's) until Ctrl-C (then exit 130, as every command interrupted). Problems: the "
                    "contest's names (probatio 3 rooms, primus 6, secundus 12, tertius 18, quartus 24, quintus 30; "
                    "aleph..he 2 copies and vau..iod 3 copies of 6..30 rooms), a random map of the problem at each "
                    "/select, from --maps DIR or generated from --seed; and worlds by file (--world). Guesses are "
                    "judged exactly; a wrong one's answer carries a witness plan with both records. A malformed "
                    "request is answered 400 with one message, and the server goes on serving.")
    s.add_argument("--host", default="127.0.0.1",
                   help="the address to listen on (default 127.0.0.1; a non-loopback address needs --allow-remote)")
    s.add_argument("--port", type=int, default=8000, help="the port (default 8000; 0 takes a free one, printed)")
    s.add_argument("--allow-remote", action="store_true",
                   help="serve on a non-loopback --host (the server has no authentication: anyone who reaches it "
                        "can play)")
    s.add_argument("--maps", metavar="DIR",
                   help="a directory of contest map files; each /select draws one of the problem's maps (the problem "
                        "from MANIFEST.tsv's problem column when there is one, else each file's problemName); "
                        "default: maps generated from --seed")
    s.add_argument("--world", action="append", default=[], metavar="NAME=FILE",
                   help="serve the port world in FILE (a contest map file or map) as problem NAME (letters, digits, "
                        "_ and -); repeatable; NAME may be a contest problem's, replacing it")
    s.add_argument("--round", choices=("full", "lightning"), default="full",
                   help="the plan limit: full (6 doors a room, charcoal marks allowed; the default) or lightning "
                        "(18 doors a room, no marks)")
    s.add_argument("--no-echo", action="store_true",
                   help="records without an entry for each charcoal mark (default: each mark is echoed, as the "
                        "contest's server did)")
    s.add_argument("--seed", type=seed, default=0, help="the seed of the maps drawn (default 0)")
    s.add_argument("--log-dir", metavar="DIR",
                   help="write one JSON log per problem played there (every request and answer, the hidden map, the "
                        "verdict); made if missing")
    add_force(s, help="write logs into a non-empty --log-dir, replacing earlier logs (default: refuse, exit 2)")
    s.add_argument("--json", action="store_true", help="print the address and setup as one JSON object")
    s.set_defaults(handler=Later("cmd_contest", "serve_command"))
    p.set_defaults(handler=lambda args: _no_action(sorted(actions.choices)))


def _no_action(names: list[str]) -> int:
    from topomark.spec.errors import InvalidInput

    raise InvalidInput("contest needs an action: " + ", ".join(names))

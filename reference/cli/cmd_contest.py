"""``topomark contest serve``: the contest's HTTP interface on the local host (:mod:`topomark.reference.contest`).

Its options are :mod:`topomark.reference.cli.options.contest`'s; this module is imported when it runs."""

from __future__ import annotations

import re
import sys

from topomark.spec.errors import clip, require_input
from topomark.spec.port_world import PortWorld

from topomark.reference.cli.parser import emit
from topomark.reference.contest.app import build_app
from topomark.reference.contest.game import Contest
from topomark.reference.contest.log import LOG_GLOB
from topomark.reference.contest.problems import Problems
from topomark.reference.contest.serve import check_host, listen, serve, url_of
from topomark.reference.files.outputs import check_output_dir
from topomark.reference.files.overwrite import claim_dir
from topomark.reference.port.files import load_port_file
from topomark.reference.port.judge import judge

__all__ = ["serve_command", "parse_worlds"]

_NAME = re.compile(r"[A-Za-z0-9_-]{1,64}")


def parse_worlds(given: list[str]) -> dict[str, PortWorld]:
    """``--world NAME=FILE`` options as problem name: port world."""
    worlds: dict[str, PortWorld] = {}
    for item in given:
        name, sep, path = item.partition("=")
        require_input(bool(sep) and bool(path), f"--world {clip(item, 80, quote=True)}: give NAME=FILE")
        require_input(bool(_NAME.fullmatch(name)), f"--world {clip(name, 80, quote=True)}: a problem name is 1 to 64 "
                      "letters, digits, _ and -")
        require_input(name not in worlds, f"--world {name}: the name is given twice")
        worlds[name] = load_port_file(path)[1]
    return worlds


def serve_command(args) -> int:
    check_host(args.host, args.allow_remote)
    problems = Problems(seed=args.seed, maps=args.maps, worlds=parse_worlds(args.world))
    log_dir = None
    if args.log_dir is not None:
        claim_dir(args.log_dir, "--log-dir", args.force, replace=(LOG_GLOB,))
        log_dir = str(check_output_dir(args.log_dir))
    contest = Contest(problems, judge, round_name=args.round, echo_marks=not args.no_echo, log_dir=log_dir)
    sock = listen(args.host, args.port)
    url = url_of(sock)
    names = problems.names()
    source = f"maps from {args.maps}" if args.maps else f"maps generated from seed {args.seed}"
    emit(args, {"url": url, "problems": names, "round": args.round, "echo_marks": not args.no_echo,
                "maps": args.maps, "seed": args.seed, "log_dir": log_dir},
         f"serving the ICFP Contest 2025 interface on {url} ({len(names)} problems, {source}; {args.round} round, "
         f"marks {'not ' if args.no_echo else ''}echoed{f'; logs in {log_dir}' if log_dir else ''}); Ctrl-C stops it")
    sys.stdout.flush()
    try:
        serve(build_app(contest), sock)  # Ctrl-C: the server stops, then the interrupt ends the command (exit 130)
    finally:
        sock.close()
    return 0

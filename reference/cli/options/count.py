"""The options of ``topomark census-count`` (:mod:`..cmd_count`)."""

from __future__ import annotations

from topomark.reference.cli.facts import fact
from topomark.reference.cli.parser import Later

__all__ = ["register"]


def register(sub) -> None:
    p = sub.add_parser(
        "census-count",
        description="Count connected graphs of max degree D and the embedded worlds on them (up to extended "
                    "isomorphism) for every size up to N, by Burnside's lemma over each graph's automorphism "
                    "group, without enumerating the worlds. Exit 0 on success, 2 on bad input, 3 if "
                    "--enumerate finds a different count.")
    p.add_argument("--max-vertices", type=int, required=True, metavar="N",
                   help=f"largest world size, 2..{fact('graphs_max_vertices')} (time grows fast with D: n = 9 at D = 4 "
                        "takes about a minute)")
    p.add_argument("--max-degree", type=int, required=True, metavar="D", help="largest vertex degree, >= 1")
    p.add_argument("--min-vertices", type=int, default=2, metavar="M", help="smallest world size (default 2)")
    p.add_argument("--enumerate", action="store_true",
                   help=f"also list the worlds and check the counts agree (N <= {fact('enumerate_max_vertices')}; slow)")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(handler=Later("cmd_count", "count_command"))

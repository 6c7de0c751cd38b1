"""What the commands' ``--help`` lists from the modules that define it, cheap to read: names and limits.

``explore --help`` names every algorithm, its options and the lighthouses; ``world --help`` the generators;
``bench --help`` the experiments; ``search --help`` the largest world Z3 is asked about.  The modules that
define them are the ones that run the command: the registry imports every explorer, the generators networkx,
the search Z3.  So that ``--help`` starts as fast as Python itself does, it reads them from
:mod:`.facts_table`, a table *generated* from those modules (they stay the one place each is defined):

    python -m topomark.reference.cli.facts > reference/cli/facts_table.py

and checked against them by the tests.  Only ``--help`` reads the table (:func:`for_help`): a command that
runs reads the modules (it imports them anyway), so what it parses is what they hold.  A module already
imported is read too, so an algorithm registered in-process (``registry.register``) is in ``--help``.

>>> with for_help(False):
...     fact("lighthouses")[0]
'directional-vertex'
"""

from __future__ import annotations

import contextlib
import importlib
import sys
from typing import Any, Callable, Iterator

__all__ = ["SOURCES", "fact", "for_help", "table", "source", "main"]

_REGISTRY = "topomark.reference.algorithms.registry"
_LIGHTHOUSES = "topomark.reference.explorers.lighthouses"
_POLICIES = "topomark.reference.explorers.policies"
_ENUMERATE = "topomark.proofs.enumerate"
_CENSUS = "topomark.proofs.census_exec"


def _parameters(registry: Any) -> tuple[tuple[str, str, Any, str], ...]:
    """Every algorithm option (``explore --NAME``): its name, help, default and every algorithm that takes an
    option of that name — matched by name, as the CLI offers one ``--NAME`` to all of them — each with its own
    default where they differ (then the default given is None)."""
    out = []
    for p in registry.parameters().values():
        takers = [(s.name, q.default) for s in registry.REGISTRY.values() for q in s.parameters if q.name == p.name]
        same = len({repr(d) for _, d in takers}) == 1
        names = ", ".join(n if same else f"{n} (default {d})" for n, d in takers)
        out.append((p.name, p.help, p.default if same else None, names))
    return tuple(out)


SOURCES: dict[str, tuple[str, Callable[[Any], Any]]] = {  # fact: (the module defining it, how to read it there)
    "algorithms": (_REGISTRY, lambda m: tuple(m.REGISTRY)),
    "parameters": (_REGISTRY, _parameters),
    "lighthouses": (_LIGHTHOUSES, lambda m: tuple(m.LIGHTHOUSES)),
    "max_marker_count": ("topomark.reference.oracle.marker_messages", lambda m: m.MAX_COUNT),
    "max_thread": ("topomark.reference.oracle.marker_messages", lambda m: m.MAX_THREAD),
    "max_walk_limit": (_LIGHTHOUSES, lambda m: m.MAX_WALK_LIMIT),
    "max_trace_records": ("topomark.reference.trace.reader", lambda m: m.MAX_TRACE_RECORDS),
    "max_trace_line_bytes": ("topomark.reference.trace.reader", lambda m: m.MAX_LINE_BYTES),
    "max_neighbourhood": (_LIGHTHOUSES, lambda m: m.MAX_NEIGHBOURHOOD),
    "max_threshold": (_LIGHTHOUSES, lambda m: m.MAX_THRESHOLD),
    "edge_policies": (_POLICIES, lambda m: tuple(m.EDGE_CHOICES)),  # the built-in and the registered ones
    "hypothesis_policies": (_POLICIES, lambda m: m.HYPOTHESIS_POLICIES),
    "path_policies": (_POLICIES, lambda m: m.PATH_POLICIES),
    "generators": ("topomark.reference.worlds.generators", lambda m: m.PARAMETERS),
    "conformance_families": ("topomark.reference.oracle.conformance", lambda m: tuple(m.FAMILIES)),
    "experiments": ("topomark.reference.bench.experiments", lambda m: tuple(m.EXPERIMENTS)),
    "heavy_graphs": ("topomark.reference.bench.experiments", lambda m: m.HEAVY_GRAPHS),
    "heavy_max_size": ("topomark.reference.bench.experiments", lambda m: m.HEAVY_MAX_SIZE),
    "marker_classes": ("topomark.spec.markerclass", lambda m: tuple(m.MARKER_CLASSES)),
    "enumerate_max_vertices": (_ENUMERATE, lambda m: m.MAX_VERTICES),
    "graphs_max_vertices": ("topomark.proofs.graphs", lambda m: m.MAX_VERTICES),
    "draw_max_vertices": ("topomark.proofs.drawing", lambda m: m.MAX_DRAW_VERTICES),
    "search_max_vertices": ("topomark.proofs.z3search", lambda m: m.MAX_VERTICES),
    "connect_timeout": (_CENSUS, lambda m: m.CONNECT_TIMEOUT),
    "worker_wait": (_CENSUS, lambda m: m.WORKER_WAIT),
    "objectives": ("topomark.reference.worstcase.search", lambda m: m.OBJECTIVES),
    "engines": ("topomark.reference.engine", lambda m: m.ENGINES),
    "restart_families": ("topomark.reference.worstcase.structural", lambda m: m.RESTART_FAMILIES),
}

_help = [False]  # whether the parser being built is only to print help (:func:`for_help`)


@contextlib.contextmanager
def for_help(only_help: bool) -> Iterator[None]:
    """While building a parser: ``True`` when it is only to print ``--help``, so :func:`fact` may read the table."""
    before, _help[0] = _help[0], only_help
    try:
        yield
    finally:
        _help[0] = before


def fact(name: str) -> Any:
    """The fact ``name`` of :data:`SOURCES`: from the table for ``--help`` while its module is not imported;
    else from the module."""
    module, read = SOURCES[name]
    if _help[0] and module not in sys.modules:
        from topomark.reference.cli.facts_table import TABLE

        return TABLE[name]
    return read(importlib.import_module(module))


def table() -> dict[str, Any]:
    """Every fact read from its module (which this imports): what :mod:`.facts_table` must hold."""
    return {name: read(importlib.import_module(module)) for name, (module, read) in SOURCES.items()}


def source() -> str:
    """The text of :mod:`.facts_table`, generated from the modules."""
    return ('"""What ``--help`` lists, read from the modules that define it: generated by\n'
            "``python -m topomark.reference.cli.facts > reference/cli/facts_table.py`` (edit those modules, never\n"
            'this file; the tests check it is current).  See :mod:`topomark.reference.cli.facts`."""\n\n'
            "from typing import Any\n\n"
            "TABLE: dict[str, Any] = {\n" + "".join(_entry(name, value) for name, value in table().items()) + "}\n")


def _entry(name: str, value: Any) -> str:
    """One line (or more, indented) of the table: ``    'name': value,``."""
    import pprint  # here: it imports dataclasses, which --help has no use for

    key = f"    {name!r}: "
    lines = pprint.pformat(value, width=116 - len(key), compact=True, sort_dicts=False).split("\n")
    return key + f"\n{' ' * len(key)}".join(lines) + ",\n"


def main() -> int:
    """Print the table's module on stdout."""
    print(source(), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""topomark.spec — the executable definition of the thesis's formal model.

*Exploring topological environments* (York University, 2014), Chapter 3:

=================  ======================================================
module             concept (thesis section)
=================  ======================================================
``world``          the world as a rotation system (§3.1.1)
``marker``         vertex and edge markers (§3.1.1, §6.1)
``signature``      what the robot senses, in thesis notation (§3.1.1)
``robot``          states, motions, perception sequences (§3.1.1)
``mapstate``       the partial map S and unexplored darts U (§3.1.3)
``isomorphism``    extended isomorphism, anchored implementation (§3.1.3)
``dartgraph``      extended isomorphism, independent networkx implementation
``invariants``     loop invariants I-1 and I-2 (§3.4)
``worldfile``      the ``topomark/world@1`` JSON format and its schema
``errors``         invalid input (exit 2) vs failed checks (exit 1)
``violation``      a failed check described: condition, place, expected, found
``spelling``       how a message names an option: ``--flag`` or ``keyword`` (the API)
=================  ======================================================

Everything else in topomark uses these predicates and restates none of them.
"""

import importlib
from typing import Any

_EXPORTS = {  # name: the module of this package that defines it
    **dict.fromkeys(("CheckFailure", "InvalidInput", "InvalidWorld"), "errors"),
    "Violation": "violation",
    **dict.fromkeys(("IsoResult", "Witness", "find_isomorphism", "verify_witness"), "isomorphism"),
    **dict.fromkeys(("EdgeMarker", "VertexMarker"), "marker"),
    **dict.fromkeys(("perceive", "sense", "step"), "robot"),
    **dict.fromkeys(("Signature", "signature_at"), "signature"),
    **dict.fromkeys(("Start", "World"), "world"),
    **dict.fromkeys(("dumps_world", "load_world", "loads_world", "save_world"), "worldfile"),
}

__all__ = list(_EXPORTS)


def __getattr__(name: str) -> Any:
    """Each name is imported from its module when first used (PEP 562): importing one module of the package,
    as the command line does to start, does not import them all."""
    if name in _EXPORTS:
        value = getattr(importlib.import_module(f"{__name__}.{_EXPORTS[name]}"), name)
        globals()[name] = value
        return value
    try:
        return importlib.import_module(f"{__name__}.{name}")
    except ModuleNotFoundError as exc:
        if exc.name != f"{__name__}.{name}":  # the module exists but needs one that is missing: say that
            raise
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))

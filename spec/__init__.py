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
=================  ======================================================

Everything else in topomark uses these predicates and restates none of them.
"""

from topomark.spec.errors import CheckFailure, InvalidInput, InvalidWorld, Violation
from topomark.spec.isomorphism import IsoResult, Witness, find_isomorphism, verify_witness
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.robot import perceive, sense, step
from topomark.spec.signature import Signature, signature_at
from topomark.spec.world import Start, World
from topomark.spec.worldfile import dumps_world, load_world, loads_world, save_world

__all__ = [
    "CheckFailure", "InvalidInput", "InvalidWorld", "Violation",
    "IsoResult", "Witness", "find_isomorphism", "verify_witness",
    "EdgeMarker", "VertexMarker", "perceive", "sense", "step",
    "Signature", "signature_at", "Start", "World",
    "dumps_world", "load_world", "loads_world", "save_world",
]

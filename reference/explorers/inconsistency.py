"""What an explorer raises when it finds its own map, or what it senses, inconsistent.

Never the checker's :class:`~topomark.spec.errors.CheckFailure`: an explorer judges nothing but itself.
Two cases, told apart by the thesis:

* the thesis *predicts* the inconsistency — a lighthouse whose place or back-link may not be explicit
  (the marker-less lighthouses of §5.2.1) "detects some signature inconsistencies (due to wrong loop
  closing) and thus cannot proceed reporting failure" (§5.2.1): :class:`~topomark.spec.errors.AlgorithmFailed`,
  the outcome ``failed`` (exit 1);
* the thesis *proves* it cannot happen — with a lighthouse of explicit place and back-link, an accepted
  hypothesis is the true place and entry (§3.4, Lemma 1): :class:`~topomark.spec.errors.ExplorerFault`,
  a bug (exit 3).
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed, ExplorerFault, TopomarkError

__all__ = ["inconsistent"]


def inconsistent(light, message: str, proof: str) -> TopomarkError:
    """The error for an explorer's own inconsistency ``message``: :class:`AlgorithmFailed` when ``light`` (a
    :class:`~topomark.reference.explorers.lighthouses.Lighthouse`, or None) is not certain to give explicit
    place and back-link information (§5.2.1), else :class:`ExplorerFault` naming the ``proof`` it breaks."""
    if light is not None and not getattr(light, "certain", True):
        return AlgorithmFailed(f"{message}: the lighthouse {light.name} is not explicit, a loop was closed wrongly "
                               "(§5.2.1)")
    return ExplorerFault(f"{message}, which {proof} rules out: a bug in the explorer")

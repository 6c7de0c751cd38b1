"""A prior over worlds and the ranking of the model tree's completed models by it (thesis §5.3).

§5.3 suggests that "the world models in the tree can be ranked in terms of
their overall likelihood" given "the probabilistic distribution of some
environmental properties" (§5.3; also §7.2: distributions of n, of the
diameter, of degrees).  It names no distribution.  **Decision**: the prior

    P(G) ∝ 2^−(n + m + g)

over embedded graphs, n vertices, m edges and g the genus of the embedding:
each vertex, each edge and each handle halves the prior — fewer places (the
Occam's razor ranking of the earlier work, §2.3.2, which counts vertices),
fewer edges, and planar embeddings first.  Every completed model explains
the robot's perceptions alike (the model tree voids every model that does
not, Algorithm 5.1), so the likelihood is the same for each and

    P(model | perceptions) = prior(model) / Σ prior(completed models).

Ties keep completion order (the order of the models written by ``--models``).

Examples
--------
>>> log2_prior(5, 8, 0), log2_prior(5, 8, 1)
(-13, -14)
>>> [round(p, 3) for _, p in posteriors([(5, 8, 1), (5, 8, 0)])]
[0.667, 0.333]
"""

from __future__ import annotations

__all__ = ["log2_prior", "posteriors"]


def log2_prior(n: int, m: int, genus: int) -> int:
    """log₂ of the unnormalised prior 2^−(n + m + g) of a world of n vertices, m edges and genus g."""
    return -(n + m + genus)


def posteriors(models: list[tuple[int, int, int]]) -> list[tuple[int, float]]:
    """(completion index from 0, P(model | perceptions)) for each (n, m, genus), the most probable first."""
    logs = [log2_prior(*nmg) for nmg in models]
    weights = [2 ** (x - min(logs)) for x in logs]  # exact integers: the prior times 2^-(least log)
    total = sum(weights)
    ranked = sorted(range(len(models)), key=lambda k: -weights[k])  # stable: ties in completion order
    return [(k, weights[k] / total) for k in ranked]

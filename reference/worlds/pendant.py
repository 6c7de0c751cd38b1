"""The pendant strip: a closed strip hung at the far end of a long stem, a family of worlds on which the
cost of the Chapter 4 enhancements grows as m²n, as far as the runs go (thesis §4.1–4.3, §7.2).

§7.2 asks whether the O(m²n) bound of Algorithm 3.1 is tight; Chapter 4's
enhancements keep that bound.  On the families that make ``basic`` cubic
(:mod:`~topomark.reference.worlds.expensive`,
:mod:`~topomark.reference.worlds.rewired`) the enhancements' cost / bound falls
with n: every hypothesis there is validated along a path of S that the robot's
first walk laid down, and the first walk leaves each place by the exit next to
the one it came in by, so those paths all turn alike.  Their motion sequences
are then prefixes of one another, and Enhancement-1's execution trie (§4.1)
walks what they share once.

:func:`pendant_strip` makes the paths differ near their start and stay long:

* the **stem**: places 0 … J on a path, and the places of J's parity also
  joined to the next such place (i to i + 2: the chords).  A place of J's
  parity lists clockwise i − 1, i + 1, i − 2, i + 2 (those that exist), the
  others i − 1, i + 1, so the robot's first walk runs up the stem, 0, 1, …, J,
  and closes its first loop at J (J's exit 1 is J − 2).  Its next loops are
  the other chords, near the start, where the validation walks are short;
  once they are closed, the path of S from J to the start runs down the
  chords, J/2 edges through places of degree 4.
* the **pendant**: the closed strip ``strip:n=M,cap=1`` on the places
  J + 1 … J + M (strip place p is place J + 1 + p) less its edge (0, M − 1),
  both ends of which are joined to J instead: J lists J − 1, J − 2, J + 1,
  J + M.  Every pendant place has degree 4.

The robot enters the pendant from J last.  The path of S from a pendant
place it has walked to runs back along its walk there, turning alike at
every place, turns once otherwise near J, and runs down the stem's chords to
the start: its motion sequence is f·3^k·1·3^… (k is how far along the walk
the place lies).  Two such sequences part at the motion where the shorter
one turns, so each is a branch of its own in Enhancement-1's execution trie,
and each runs the whole tail of J/2 motions from another place of the
pendant.  Every place it reaches there has degree 4 and no marker, as P^E
expects, so each walk runs on until P^E expects the end of the stem (place 1,
of degree 3, or the start): to within one motion of its end.  A non-loop
iteration in the pendant thus costs about 2 × (open exits) × J/2 traversals,
Θ(n²), and there are Θ(n) of them: the cost is cubic for ``enh1``, ``enh2``
and ``enh3`` alike (``topomark explore pendant-strip:n=N --algorithm enh1
--breakdown`` shows it iteration by iteration).  The places of the stem off
the chords only carry the first walk: with degree 2 they add few edges (m
counts in the bound).  The stem's length J = ⌊9n/25⌋, or one more so that
M = n − 1 − J is even, is the best of the fractions tried at n = 200 and 300
(0.30 to 0.50).  No formula is claimed, and cost / bound is measured, not
proved, to rise.

m = J + ⌊J/2⌋ + 2M + 1, maximum degree 4; started at place 0 facing place 1.

Examples
--------
>>> w = pendant_strip(20)
>>> (w.n, w.m, w.start_state(), stem_length(20))
(20, 35, ('0', 0), 7)
>>> w.rotation["7"], w.rotation["8"], w.rotation["19"]
(('6', '5', '8', '19'), ('9', '7', '18', '13'), ('18', '14', '13', '7'))
"""

from __future__ import annotations

from topomark.spec.world import Start, World, check_size

from topomark.reference.worlds.deterministic import integer_param
from topomark.reference.worlds.expensive import strip

__all__ = ["pendant_strip", "stem_length", "PENDANT_FROM"]

PENDANT_FROM = 13
"""The least n: a stem 0 … 4 under a pendant of 8 places, the smallest closed strip."""


def stem_length(n: int) -> int:
    """J, the stem's last place: ⌊9n/25⌋, or one more so that the pendant's n − 1 − J places are even in number."""
    j = 9 * n // 25
    return j + (n - 1 - j) % 2


def pendant_strip(n: int) -> World:
    """The stem 0 … J (i joined to i + 1, and to i + 2 where i and J have one parity) with ``strip:n=M,cap=1``
    (M = n − 1 − J) on places J + 1 … J + M less its edge (0, M − 1), whose ends are joined to J;
    n ≥ :data:`PENDANT_FROM`; started at place 0 facing place 1."""
    n = integer_param("n", n, PENDANT_FROM)
    j = stem_length(n)
    pendant = n - 1 - j
    check_size(n, j + j // 2 + 2 * pendant + 1, f"pendant-strip:n={n}")
    rotation: dict[int, list[int]] = {i: [x for x in ((i - 1, i + 1, i - 2, i + 2) if (i - j) % 2 == 0 else
                                                      (i - 1, i + 1)) if 0 <= x <= j] for i in range(j + 1)}
    for p, ns in strip(pendant, 1).rotation.items():
        rotation[j + 1 + int(p)] = [j + 1 + int(x) for x in ns]
    first, last = j + 1, j + pendant
    rotation[first][rotation[first].index(last)] = j  # the strip's edge (0, M − 1) is cut …
    rotation[last][rotation[last].index(first)] = j
    rotation[j] += [first, last]  # … and both its ends hung at J
    world = World({str(v): tuple(str(x) for x in rotation[v]) for v in sorted(rotation)}, (), Start("0", "1"))
    assert world.m == j + j // 2 + 2 * pendant + 1 and max(world.degree(v) for v in world.vertices) == 4, \
        "stem J + ⌊J/2⌋, pendant 2M + 1"
    return world

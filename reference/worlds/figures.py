"""Worlds rebuilt from the captions and text of the thesis's figures whose drawings are lost: the worlds
where the failing marker savings of §6.2 fail (Figure 6.10, §6.2.1 Case 4; Figure 6.15, §6.2.2).

* ``figure-6.10`` (:func:`figure_6_10`): Figure 6.10(b)'s caption has the robot
  enter "v_k' (node 2) and its neighbor (node 1)", both showing the signature
  ``[3,A,E1-1]`` (Figure 6.10): two places of degree 3 joined by the edge carrying
  one marker, their only marked edge.  The complete graph K_4 (every place of
  degree 3) embedded in the plane, the robot at ``"0"`` facing ``"1"``, is the
  smallest world where it happens: the first edge, from the unmarked v0, gets the one marker; its
  far end, already marked, leaves its next edge blank; the place found there is
  unmarked and its closest-first edge leads back to v0 — whose only marked edge
  is the one to its neighbour, which shows the same signature from its own
  unexplored edge.  (K_4 embedded on the circle, as ``complete:n=4``, leads the
  robot elsewhere: there the variant maps a place it left unmarked as new.)
* ``figure-6.15`` (:func:`figure_6_15`): Figure 6.15(b)–(c) (§6.2.2): a
  loop edge explored from a v_k that has no marked edge yet, then
  closest-first from v_k', "leaving v_k unmarked"; a later entry into v_k
  senses no marked edge.  K_4 without the edge ``"0"``–``"1"``, the robot at
  ``"2"`` facing ``"0"``, is the smallest world that shows it (no start of the
  3- or 4-cycle does).

Both worlds are bare (no marker): each algorithm drops its own.

Examples
--------
>>> w = figure_6_10()
>>> (w.n, w.m, w.start.at, w.start.facing, w.genus())
(4, 6, '0', '1', 0)
>>> w = figure_6_15()
>>> (w.n, w.m, w.start.at, w.start.facing)
(4, 5, '2', '0')
"""

from __future__ import annotations

from topomark.spec.world import Start, World

from topomark.reference.worlds.deterministic import complete

__all__ = ["figure_6_10", "figure_6_15"]

PLANAR_K4 = {"0": ("1", "3", "2"), "1": ("0", "2", "3"), "2": ("1", "0", "3"), "3": ("2", "0", "1")}
"""K_4 embedded in the plane: each place lists its neighbours clockwise (genus 0)."""


def figure_6_10() -> World:
    """Planar K_4 from ``"0"`` facing ``"1"``: where the undirected saving of Case 3b meets Figure 6.10(b)."""
    return World(dict(PLANAR_K4), (), Start("0", "1"))


def figure_6_15() -> World:
    """K_4 less the edge ``"0"``–``"1"``, from ``"2"`` facing ``"0"``: Figure 6.15(b)–(c)."""
    rotation = {v: tuple(w for w in ns if {v, w} != {"0", "1"}) for v, ns in complete(4).rotation.items()}
    return World(rotation, (), Start("2", "0"))

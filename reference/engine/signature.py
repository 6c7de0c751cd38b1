"""The compiled signature: what the robot senses at a place, as one integer (thesis §3.1.1, Figure 3.2; §6.1; §6.3.1).

The engine's counterpart of :class:`~topomark.spec.signature.Signature`
for the marks a deterministic lighthouse leaves (:data:`LIMITS`): a vertex
marker (a count, and the exit a directional one points at), at most two
marked incident edges (each its exit, count and which end of a directional
edge marker is here) and an ε thread tied here (the exit it is laid out
toward, and whether its free end lies here).  The degree is sensed apart.

A *code* packs these with every exit counted from one entry edge; the code of
an unmarked place is 0.  The same marks sensed from another entry give the
code :func:`rotate` makes: every exit shifted, the two edge items in order
of their exit, as ``E-p`` items are sorted in the thesis's notation — so two
codes are equal exactly when the two signatures are.  The robot keeps each
place's code counted from world exit 0 (:mod:`.robot`), the explorer's map
each map vertex's counted from map exit 0 (:mod:`.mapstate`), and both
rotate it to the entry asked about.

Examples
--------
>>> d = 3
>>> v0 = add_edge_mark(encode(0, -1, 0), 0, edge_mark(1, 1))  # Figure 6.1(b): E-0-H at v0, from exit 0
>>> decode_edges(rotate(v0, d, 2)), decode_edges(rotate(v0, d, 0))
((1, 5, -1, 0), (0, 5, -1, 0))
>>> rotate(encode(1, 2, 0), 4, 1) == encode(1, 1, 0), rotate(0, 4, 3)
(True, 0)
"""

from __future__ import annotations

from topomark.reference.engine.compiled import step

__all__ = ["encode", "rotate", "add_edge_mark", "edge_mark", "with_thread", "thread_of", "decode_edges", "EXITS", "LIMITS"]

EXITS = 4096
"""Each exit field holds exit + 1 in 12 bits: the engine senses places of degree < 4095."""
_VDIR, _EA, _EB, _THREAD = 4, 4 * EXITS, 4 * EXITS * EXITS * 16, 4 * EXITS * (EXITS * 16) ** 2
LIMITS = {"vertex markers": 3, "marked edges": 2, "edge markers per edge": 3}
"""What one place's code can hold: the marks of every deterministic lighthouse the engine runs."""


@step
def encode(vertex_count: int, vertex_head: int, thread: int) -> int:
    """The code of a place with ``vertex_count`` vertex markers (directional toward exit ``vertex_head``, or -1)
    and the thread field ``thread`` (0: none; see :func:`with_thread`), no marked edge."""
    return vertex_count + _VDIR * (vertex_head + 1) + _THREAD * thread


@step
def edge_mark(count: int, end: int) -> int:
    """The mark of ``count`` edge markers on one edge, ``end`` 0 (undirected), 1 (the head here: ``H``) or 2
    (the tail here: ``T``)."""
    return count * 4 + end


@step
def with_thread(code: int, toward: int, free_end: int) -> int:
    """``code`` with an ε thread tied here toward exit ``toward`` (-1: not tied) and its free end here
    (``free_end`` 1) or not."""
    return code % _THREAD + _THREAD * ((toward + 1) * 2 + free_end)


@step
def thread_of(code: int) -> tuple:
    """The thread field of ``code``: (the exit it is tied toward, -1 if not tied here; 1 if its free end is here)."""
    thread = code // _THREAD
    return thread // 2 - 1, thread % 2


@step
def decode_edges(code: int) -> tuple:
    """The two edge items of ``code``: (exit, mark, exit, mark), exit -1 where there is none."""
    a, b = (code // _EA) % (EXITS * 16), (code // _EB) % (EXITS * 16)
    return a // 16 - 1, a % 16, b // 16 - 1, b % 16


@step
def _with_edges(code: int, pa: int, ma: int, pb: int, mb: int) -> int:
    """``code`` with its edge items replaced by (pa, ma) and (pb, mb), the smaller exit first, none last."""
    if pa < 0 or (0 <= pb < pa):
        pa, ma, pb, mb = pb, mb, pa, ma
    rest = code % _EA + _THREAD * (code // _THREAD)
    return rest + _EA * ((pa + 1) * 16 + ma) + _EB * ((pb + 1) * 16 + mb)


@step
def add_edge_mark(code: int, exit_: int, mark: int) -> int:
    """``code`` with the edge at ``exit_`` marked ``mark`` (:func:`edge_mark`); -1 if it already has two."""
    pa, ma, pb, mb = decode_edges(code)
    if pb >= 0:
        return -1
    if pa < 0:
        return _with_edges(code, exit_, mark, -1, 0)
    return _with_edges(code, pa, ma, exit_, mark)


@step
def rotate(code: int, degree: int, by: int) -> int:
    """The code sensed from entry ``by`` of a place of ``degree`` whose code from exit 0 is ``code``: every exit
    ``x`` becomes ``(x - by) mod degree``."""
    if code == 0:
        return 0
    vc, vh = code % 4, (code // _VDIR) % EXITS - 1
    if vh >= 0:
        vh = (vh - by) % degree
    toward, free_end = thread_of(code)
    if toward >= 0:
        toward = (toward - by) % degree
    out = encode(vc, vh, 0)
    if code >= _THREAD:
        out = with_thread(out, toward, free_end)
    pa, ma, pb, mb = decode_edges(code)
    if pa < 0:
        return out
    pa = (pa - by) % degree
    if pb >= 0:
        pb = (pb - by) % degree
    return _with_edges(out, pa, ma, pb, mb)

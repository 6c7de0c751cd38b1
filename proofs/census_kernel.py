"""The census's per-world kernel, compiled: every placement's language code on one world (thesis §3.1.1, §3.2).

The same computation as :func:`topomark.proofs.census_map.world_records`
(the reference, and the definition), on a world given as arrays
(:mod:`topomark.proofs.world_arrays`), for the marker classes whose markers
are all vertex markers (``none``, ``undirected-vertex``, ``directional-vertex``,
``two-undirected-vertex``, ``three-undirected-vertex``; §3.2–§3.3, §3.7):

* the robot's Moore machine, outputs as small ints standing for the
  signature texts of :mod:`topomark.spec.signature`, and Moore equivalence
  (:mod:`topomark.proofs.census_moore`);
* the quotient, its anchors and the least anchored breadth-first code of
  :mod:`topomark.proofs.census_language`, written byte for byte as
  :func:`~topomark.proofs.census_language.anchored_code` writes it (output
  texts, NUL, little-endian uint32 successor numbers), so the BLAKE2b digests
  taken of it by :mod:`topomark.proofs.census_compiled` are today's;
* the iso key's layout code: the least, over the world's automorphisms, of
  the layout's items ``(0, σ(at), count, σ(points_to) or -1)``, sorted
  (``census_map._layout_code``).

The anchors' rarest output breaks ties by the least text and the codes
compare as bytes, so the kernel compares outputs by their texts' ranks
(``signature_table``), which is the byte order of the concatenated texts: a
signature text ends at its only ``]``, so no text is a prefix of another.
Every anchor's code has as many blocks (the quotient is strongly connected).

The marker layouts of :mod:`topomark.spec.markerclass` are read here as
arrays (:data:`CLASS_CODES`, ``_layout``), in ``MarkerClass.placements``
order; ``tests/test_census_kernel.py`` checks every record (placement
indices, digests, iso keys) against the reference on every world of n ≤ 6,
D ≤ 4, so a layout read otherwise than the spec's is a failing test.

Examples
--------
>>> import numpy as np
>>> from topomark.proofs.census_moore import back_of, signature_table
>>> offsets, nbr = np.array([0, 2, 4, 6], np.int32), np.array([1, 2, 2, 0, 0, 1], np.int32)
>>> texts, ranks = signature_table(2)
>>> identity = np.arange(3, dtype=np.int32).reshape(1, 3)
>>> codes, ends, iso, nitems, rows, placements = world_codes(
...     offsets, nbr, back_of(offsets, nbr), CLASS_CODES["undirected-vertex"], identity, 2, texts, ranks)
>>> int(placements), len(ends), rows.tolist()  # 3 vertices x 2 facings; a start per layout (both alike)
(6, 3, [[0, 0, 0], [1, 2, 0], [2, 4, 0]])
>>> bytes(codes[:ends[0]])[:16]
b'[2,V,A][2,A,A][2'
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.blake2b_compiled import blake2b16
from topomark.proofs.census_moore import COMPILED, machine_arrays, njit, outputs, refine

__all__ = ["CLASS_CODES", "COMPILED", "world_codes", "world_digests", "batch_digests"]

CLASS_CODES = {"none": 0, "undirected-vertex": 1, "directional-vertex": 2, "two-undirected-vertex": 3,
               "three-undirected-vertex": 4}
"""The marker classes the kernel computes (vertex markers only), by the code :func:`_layout` reads."""


@njit(cache=True)
def _le_less(a, b):  # pragma: no cover - compiled
    """Whether uint32 ``a`` is below ``b`` compared as little-endian bytes (as the code bytes compare)."""
    for shift in range(0, 32, 8):
        x, y = (a >> shift) & 255, (b >> shift) & 255
        if x != y:
            return x < y
    return False


@njit(cache=True)
def _bfs(qsucc, qdeg, anchor, number, order, flat):  # pragma: no cover - compiled
    """Breadth-first numbering of the quotient from ``anchor`` (``anchored_code``); returns len(flat)."""
    number[:] = -1
    number[anchor] = 0
    order[0] = anchor
    seen, f, head = 1, 0, 0
    while head < seen:
        b = order[head]
        head += 1
        for motion in range(qdeg[b]):
            c = qsucc[b, motion]
            if number[c] < 0:
                number[c] = seen
                order[seen] = c
                seen += 1
            flat[f] = number[c]
            f += 1
    return f


@njit(cache=True)
def _compare(rank, qout, order, flat, best_order, best_flat, q, f):  # pragma: no cover - compiled
    """-1, 0 or 1 as the code of (order, flat) is below, equal to or above the best one, as bytes."""
    for i in range(q):
        x, y = rank[qout[order[i]]], rank[qout[best_order[i]]]
        if x != y:
            return -1 if x < y else 1
    for i in range(f):
        if flat[i] != best_flat[i]:
            return -1 if _le_less(flat[i], best_flat[i]) else 1
    return 0


@njit(cache=True)
def _quotient(out, succ, deg, block, rep, q):  # pragma: no cover - compiled
    """Successor blocks, degree and output of every block (``census_language.quotient``)."""
    qsucc = np.zeros((q, succ.shape[1]), np.int32)
    qdeg = np.empty(q, np.int32)
    qout = np.empty(q, np.int32)
    for b in range(q):
        s = rep[b]
        qdeg[b], qout[b] = deg[s], out[s]
        for motion in range(deg[s]):
            qsucc[b, motion] = block[succ[s, motion]]
    return qsucc, qdeg, qout


@njit(cache=True)
def _least_code(qsucc, qdeg, qout, rank):  # pragma: no cover - compiled
    """The least anchored code over the anchors (the blocks of the rarest output, ties by least text):
    ``(order, flat, f, x)`` with ``x[b]`` the least number of block ``b`` over the least code's numberings."""
    q = qout.size
    counts = np.zeros(rank.size, np.int32)
    for b in range(q):
        counts[qout[b]] += 1
    rare = -1
    for b in range(q):
        o = qout[b]
        if rare < 0 or counts[o] < counts[rare] or (counts[o] == counts[rare] and rank[o] < rank[rare]):
            rare = o
    size = qdeg.sum()
    number, order, flat = np.empty(q, np.int32), np.empty(q, np.int32), np.empty(size, np.int32)
    best_order, best_flat, x = np.empty(q, np.int32), np.empty(size, np.int32), np.empty(q, np.int32)
    found = False
    for a in range(q):
        if qout[a] != rare:
            continue
        f = _bfs(qsucc, qdeg, a, number, order, flat)
        c = -1 if not found else _compare(rank, qout, order, flat, best_order, best_flat, q, f)
        if c < 0:
            best_order[:], best_flat[:], x[:] = order, flat, number
            found = True
        elif c == 0:
            x[:] = np.minimum(x, number)
    return best_order, best_flat, size, x


@njit(cache=True)
def _write_code(buf, at, qout, order, flat, f, text, toff):  # pragma: no cover - compiled
    """Write ``anchored_code``'s bytes (output texts, NUL, little-endian uint32 numbers) at ``buf[at:]``."""
    for i in range(order.size):
        o = qout[order[i]]
        for j in range(toff[o], toff[o + 1]):
            buf[at] = text[j]
            at += 1
    buf[at] = 0
    at += 1
    for i in range(f):
        for shift in range(0, 32, 8):
            buf[at] = (flat[i] >> shift) & 255
            at += 1
    return at


@njit(cache=True)
def _layout(cls, offsets, nbr, v, i, marks):  # pragma: no cover - compiled
    """Layout ``i`` at vertex ``v`` of class ``cls`` (spec/markerclass.py) into ``marks``; its number of
    markers, or -1 past v's last layout."""
    d = offsets[v + 1] - offsets[v]
    if cls <= 1:  # none, undirected-vertex: one layout per vertex
        if i > 0:
            return -1
        marks[0, 0], marks[0, 1], marks[0, 2] = v, 1, -1
        return cls
    if i >= d:
        return -1
    if cls == 2:  # directional-vertex: the marker at v pointing at exit i
        marks[0, 0], marks[0, 1], marks[0, 2] = v, 1, i
        return 1
    w = nbr[offsets[v] + i]  # two- and three-undirected-vertex: v and its i-th neighbour
    marks[0, 0], marks[0, 1], marks[0, 2] = v, 1, -1
    marks[1, 0], marks[1, 1], marks[1, 2] = w, cls - 2, -1
    return 2


@njit(cache=True)
def _sort_rows(items, k):  # pragma: no cover - compiled
    """Sort the first ``k`` (≤ 2) rows of ``items`` lexicographically, in place."""
    if k == 2:
        for j in range(items.shape[1]):
            if items[0, j] != items[1, j]:
                if items[1, j] < items[0, j]:
                    for t in range(items.shape[1]):
                        items[0, t], items[1, t] = items[1, t], items[0, t]
                break


@njit(cache=True)
def _iso_items(offsets, nbr, marks, k, autos, best):  # pragma: no cover - compiled
    """The layout code of ``census_map._iso_key``: least over ``autos`` of the sorted image items."""
    items = np.empty((2, 4), np.int32)
    for a in range(autos.shape[0]):
        sigma = autos[a]
        for r in range(k):
            at, head = marks[r, 0], marks[r, 2]
            items[r, 0], items[r, 1], items[r, 2] = 0, sigma[at], marks[r, 1]
            items[r, 3] = -1 if head < 0 else sigma[nbr[offsets[at] + head]]
        _sort_rows(items, k)
        c = 0
        if a > 0:
            for t in range(k * 4):
                x, y = items[t // 4, t % 4], best[t // 4, t % 4]
                if x != y:
                    c = -1 if x < y else 1
                    break
        if a == 0 or c < 0:
            best[:k] = items[:k]


@njit(cache=True)
def _same_key(keys, nkeys, q, marks, k):  # pragma: no cover - compiled
    """Whether layout key ``q`` (sorted marks) equals the sorted ``marks[:k]`` (``census.marker_key``)."""
    if nkeys[q] != k:
        return False
    for r in range(k):
        for j in range(3):
            if keys[q, r, j] != marks[r, j]:
                return False
    return True


@njit(cache=True)
def _key_code(offsets, succ, deg, marks, k, width, rank, text, toff, buf, at):  # pragma: no cover - compiled
    """Machine, refinement, least code of one layout: writes the code at ``buf[at:]``; (end, block, x)."""
    out = outputs(offsets, marks, k, width)
    block, rep, q = refine(out, succ, deg)
    qsucc, qdeg, qout = _quotient(out, succ, deg, block, rep, q)
    order, flat, f, x = _least_code(qsucc, qdeg, qout, rank)
    return _write_code(buf, at, qout, order, flat, f, text, toff), block, x


@njit(cache=True)
def world_codes(offsets, nbr, back, cls, autos, max_degree, texts, rank):  # pragma: no cover - compiled
    """Every placement of class ``cls`` (:data:`CLASS_CODES`) on the world of ``offsets, nbr, back``.

    Returns ``(codes, code_ends, iso, nitems, rows, placements)``: per distinct layout key ``q`` (first
    occurrence order) its anchored code ``codes[code_ends[q-1]:code_ends[q]]`` and iso items
    ``iso[q, :nitems]``; ``rows[r] = (q, placement index, x)`` for every start whose block is new for its
    key (``census_map.world_records``: equivalent starts of one layout once, the first); the placements.
    """
    text, toff = texts
    n = offsets.size - 1
    size = offsets[n]
    succ, deg = machine_arrays(offsets, nbr, back, max_degree)
    width = max_degree + 1
    layouts = max(n, size)
    keys, nkeys = np.empty((layouts, 2, 3), np.int32), np.zeros(layouts, np.int32)
    iso = np.zeros((layouts, 2, 4), np.int32)
    blocks, xs = np.empty((layouts, size), np.int32), np.empty((layouts, size), np.int32)
    seen = np.zeros((layouts, size), np.bool_)
    longest = 0
    for o in range(toff.size - 1):
        longest = max(longest, toff[o + 1] - toff[o])
    codes = np.empty(layouts * (size * (longest + 4 * max_degree) + 1), np.uint8)
    code_ends = np.empty(layouts, np.int64)
    rows = np.empty((layouts * max_degree, 3), np.int32)
    marks = np.empty((2, 3), np.int32)
    nq, nrows, placements, at = 0, 0, 0, 0
    for v in range(n):
        d = offsets[v + 1] - offsets[v]
        i = 0
        while True:
            k = _layout(cls, offsets, nbr, v, i, marks)
            if k < 0:
                break
            i += 1
            _sort_rows(marks, k)
            q = 0
            while q < nq and not _same_key(keys, nkeys, q, marks, k):
                q += 1
            if q == nq:
                keys[q, :k], nkeys[q] = marks[:k], k
                at, block, x = _key_code(offsets, succ, deg, marks, k, width, rank, text, toff, codes, at)
                code_ends[q], blocks[q], xs[q] = at, block, x[block]
                _iso_items(offsets, nbr, marks, k, autos, iso[q])
                nq += 1
            for j in range(d):
                s = offsets[v] + j
                if not seen[q, blocks[q, s]]:
                    seen[q, blocks[q, s]] = True
                    rows[nrows, 0], rows[nrows, 1], rows[nrows, 2] = q, placements + j, xs[q, s]
                    nrows += 1
            placements += d
    return codes[:at], code_ends[:nq], iso[:nq], nkeys[:nq], rows[:nrows], placements


@njit(cache=True)
def _put(buf, at, text):  # pragma: no cover - compiled
    for c in text:
        buf[at] = ord(c)
        at += 1
    return at


@njit(cache=True)
def _put_int(buf, at, x):  # pragma: no cover - compiled
    """``str(x)`` in ASCII at ``buf[at:]``."""
    if x < 0:
        buf[at] = 45  # "-"
        at, x = at + 1, -x
    digits = 1
    while x >= 10 ** digits:
        digits += 1
    for j in range(digits - 1, -1, -1):
        buf[at + j] = 48 + x % 10
        x //= 10
    return at + digits


@njit(cache=True)
def _iso_repr(buf, world_id, items, k):  # pragma: no cover - compiled
    """``repr((world_id, tuple of the k items))`` (``census_map._iso_key``'s text) in ``buf``; its length."""
    at = _put(buf, 0, "((")
    for j in range(3):
        at = _put_int(buf, at, world_id[j])
        at = _put(buf, at, ", " if j < 2 else "), (")
    for r in range(k):
        at = _put(buf, at, "(" if r == 0 else ", (")
        for j in range(4):
            at = _put_int(buf, at, items[r, j])
            at = _put(buf, at, ", " if j < 3 else ")")
    return _put(buf, at, ",))" if k == 1 else "))")


@njit(cache=True)
def world_digests(offsets, nbr, back, cls, autos, max_degree, texts, rank, world_id):  # pragma: no cover
    """:func:`world_codes` hashed: per record ``(d0, d1, k, i0, i1)`` — the language digest
    (``census_language.start_digests``), the placement index and the iso key (``census_map._iso_key``) as
    little-endian words — as an ``(R, 5)`` uint64 array, and the placements."""
    codes, ends, iso, nitems, rows, placements = world_codes(offsets, nbr, back, cls, autos, max_degree, texts,
                                                             rank)
    q = ends.size
    heads, isos = np.empty((q, 2), np.uint64), np.empty((q, 2), np.uint64)
    text = np.empty(128, np.uint8)
    start = 0
    for j in range(q):
        heads[j, 0], heads[j, 1] = blake2b16(codes, start, ends[j])
        isos[j, 0], isos[j, 1] = blake2b16(text, 0, _iso_repr(text, world_id, iso[j], nitems[j]))
        start = ends[j]
    out = np.empty((rows.shape[0], 5), np.uint64)
    msg = np.empty(20, np.uint8)
    for r in range(rows.shape[0]):
        j, x = rows[r, 0], rows[r, 2]
        for b in range(16):
            msg[b] = (heads[j, b >> 3] >> np.uint64(8 * (b & 7))) & np.uint64(255)
        for b in range(4):
            msg[16 + b] = (x >> (8 * b)) & 255
        out[r, 0], out[r, 1] = blake2b16(msg, 0, 20)
        out[r, 2] = rows[r, 1]
        out[r, 3], out[r, 4] = isos[j, 0], isos[j, 1]
    return out, placements


@njit(cache=True)
def batch_digests(offsets, nbr, back, cls, images, stab_offsets, stab, max_degree, texts, rank, n, gi,
                  ranks):  # pragma: no cover - compiled
    """:func:`world_digests` of every row of a batch of one graph's worlds (``world_batches.WorldBatch``: row
    ``i`` is ``nbr[i]``, ``back[i]``, named ``(n, gi, ranks[i])``, its automorphisms
    ``images[stab[stab_offsets[i]:stab_offsets[i + 1]]]``): the records of all rows in row order, each
    row's number of records, and the placements."""
    k = ranks.size
    parts = []
    counts = np.empty(k, np.int64)
    placements, total = 0, 0
    world_id = np.empty(3, np.int64)
    world_id[0], world_id[1] = n, gi
    for i in range(k):
        world_id[2] = ranks[i]
        autos = images[stab[stab_offsets[i]:stab_offsets[i + 1]]]
        out, count = world_digests(offsets, nbr[i], back[i], cls, autos, max_degree, texts, rank, world_id)
        parts.append(out)
        counts[i] = out.shape[0]
        placements += count
        total += out.shape[0]
    flat = np.empty((total, 5), np.uint64)
    at = 0
    for out in parts:
        flat[at:at + out.shape[0]] = out
        at += out.shape[0]
    return flat, counts, placements

"""BLAKE2b with a 16-byte digest, compiled: the census's digests without a Python call per record.

The census (:mod:`topomark.proofs.census_language`, ``census_map._iso_key``)
takes ``hashlib.blake2b(data, digest_size=16)`` of its codes.  The compiled
engine (:mod:`topomark.proofs.census_compiled`) takes the same digests inside
the kernel with :func:`blake2b16`, BLAKE2b as RFC 7693 defines it (no key,
16-byte output), returning the digest as its two little-endian 64-bit words
(the ``d0, d1`` / ``i0, i1`` of a census record).  ``tests/test_census_kernel.py``
compares it with :mod:`hashlib` on messages of every length up to three blocks.

Examples
--------
>>> import hashlib
>>> import numpy as np
>>> data = np.frombuffer(b"abc", np.uint8)
>>> d0, d1 = blake2b16(data, 0, 3)
>>> (int(d0).to_bytes(8, "little") + int(d1).to_bytes(8, "little")) == hashlib.blake2b(b"abc", digest_size=16).digest()
True
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.census_moore import njit

__all__ = ["blake2b16"]

_IV = np.array([0x6A09E667F3BCC908, 0xBB67AE8584CAA73B, 0x3C6EF372FE94F82B, 0xA54FF53A5F1D36F1,
                0x510E527FADE682D1, 0x9B05688C2B3E6C1F, 0x1F83D9ABFB41BD6B, 0x5BE0CD19137E2179], np.uint64)
_SIGMA = np.array([
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15], [14, 10, 4, 8, 9, 15, 13, 6, 1, 12, 0, 2, 11, 7, 5, 3],
    [11, 8, 12, 0, 5, 2, 15, 13, 10, 14, 3, 6, 7, 1, 9, 4], [7, 9, 3, 1, 13, 12, 11, 14, 2, 6, 5, 10, 4, 0, 15, 8],
    [9, 0, 5, 7, 2, 4, 10, 15, 14, 1, 11, 12, 6, 8, 3, 13], [2, 12, 6, 10, 0, 11, 8, 3, 4, 13, 7, 5, 15, 14, 1, 9],
    [12, 5, 1, 15, 14, 13, 4, 10, 0, 7, 6, 3, 9, 2, 8, 11], [13, 11, 7, 14, 12, 1, 3, 9, 5, 0, 15, 4, 8, 6, 2, 10],
    [6, 15, 14, 9, 11, 3, 0, 8, 12, 2, 13, 7, 1, 4, 10, 5], [10, 2, 8, 4, 7, 6, 1, 5, 15, 11, 9, 14, 3, 12, 13, 0],
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15], [14, 10, 4, 8, 9, 15, 13, 6, 1, 12, 0, 2, 11, 7, 5, 3]],
    np.int64)
_ROT = np.array([32, 24, 16, 63], np.uint64)
_G = np.array([[0, 4, 8, 12], [1, 5, 9, 13], [2, 6, 10, 14], [3, 7, 11, 15],
               [0, 5, 10, 15], [1, 6, 11, 12], [2, 7, 8, 13], [3, 4, 9, 14]], np.int64)


@njit(cache=True)
def _rotr(x, n):  # pragma: no cover - compiled
    return (x >> n) | (x << (np.uint64(64) - n))


@njit(cache=True)
def _compress(h, m, counter, last, v):  # pragma: no cover - compiled
    """RFC 7693's F: mix message block ``m`` (16 words) into state ``h`` (``v`` is scratch)."""
    for i in range(8):
        v[i], v[i + 8] = h[i], _IV[i]
    v[12] ^= counter
    if last:
        v[14] = ~v[14]
    for r in range(12):
        s = _SIGMA[r]
        for g in range(8):
            a, b, c, d = _G[g, 0], _G[g, 1], _G[g, 2], _G[g, 3]
            v[a] = v[a] + v[b] + m[s[2 * g]]
            v[d] = _rotr(v[d] ^ v[a], _ROT[0])
            v[c] = v[c] + v[d]
            v[b] = _rotr(v[b] ^ v[c], _ROT[1])
            v[a] = v[a] + v[b] + m[s[2 * g + 1]]
            v[d] = _rotr(v[d] ^ v[a], _ROT[2])
            v[c] = v[c] + v[d]
            v[b] = _rotr(v[b] ^ v[c], _ROT[3])
    for i in range(8):
        h[i] ^= v[i] ^ v[i + 8]


@njit(cache=True)
def blake2b16(data, start, end):  # pragma: no cover - compiled
    """``hashlib.blake2b(bytes(data[start:end]), digest_size=16)`` as two little-endian uint64 words."""
    h = _IV.copy()
    h[0] ^= np.uint64(0x01010010)  # digest length 16, no key, fanout 1, depth 1
    m = np.zeros(16, np.uint64)
    v = np.zeros(16, np.uint64)
    at = start
    while True:
        take = min(128, end - at)
        m[:] = 0
        for j in range(take):
            m[j >> 3] |= np.uint64(data[at + j]) << np.uint64(8 * (j & 7))
        at += take
        last = at >= end
        _compress(h, m, np.uint64(at - start), last, v)
        if last:
            return h[0], h[1]

"""Worlds from Python: read, write and generate them (thesis §3.1.1; the world file of ``spec/world.schema.json``).

A world is a rotation system — each vertex's exits in clockwise order — with markers and a start
(:class:`topomark.spec.world.World`).  :func:`generate` builds the named families of ``topomark world``
(§3.5.3's lattices, complete graphs and small worlds, Figure 3.4's wheels, ...); :func:`load_world` and
:func:`save_world` read and write the world file, refusing a bad file or an unwritable path as
:class:`~topomark.spec.errors.InvalidInput` naming it.  :func:`resolve` turns what a user typed — a world file
or ``GENERATOR[:NAME=VALUE,...]`` — into a world, as every command does with its world argument.

Examples
--------
>>> w = generate("cycle", n=4)
>>> (w.n, w.m)
(4, 4)
>>> resolve("lattice:rows=2,cols=3").n
6
"""

from __future__ import annotations

import os
from typing import Any, TypeAlias

from topomark.reference.files.outputs import write_output
from topomark.reference.worlds.argument import resolve_world
from topomark.reference.worlds.generators import generate as _generate
from topomark.spec.errors import InvalidInput
from topomark.spec.world import World
from topomark.spec.worldfile import dumps_world, load_world as _load_world

__all__ = ["load_world", "save_world", "generate", "resolve", "World", "WorldLike"]

WorldLike: TypeAlias = "World | str | os.PathLike[str]"
"""What a function of the API takes as a world: a World, a world file, or a generator text."""


def load_world(path: str | os.PathLike[str]) -> World:
    """The world in the world file ``path``; a missing or malformed file is InvalidInput naming what is wrong.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> with tempfile.TemporaryDirectory() as d:
    ...     path = pathlib.Path(d) / "w.json"
    ...     save_world(generate("complete", n=4), path)
    ...     load_world(path).m
    6
    """
    return _load_world(os.fspath(path))


def save_world(world: World, path: str | os.PathLike[str]) -> None:
    """Write ``world`` to ``path`` in the world-file format; an unwritable path is InvalidInput naming it.

    Examples
    --------
    >>> save_world(generate("chain", n=3), "/nonexistent-dir/w.json")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: ...nonexistent-dir/w.json...
    """
    write_output(os.fspath(path), dumps_world(world))


def generate(name: str, **params: Any) -> World:
    """The world of the generator ``name`` (``topomark world --help`` lists them and their defaults).

    Parameters not given take their defaults; ``seed=`` picks the random generators' world.

    Examples
    --------
    >>> generate("lattice", rows=3, cols=3).n
    9
    >>> generate("lattice-hole", rows=4, cols=4, seed=2).n  # 10% of the cells removed, staying connected
    14
    >>> generate("torus")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: unknown generator 'torus' (choose from cycle, chain, lattice, ...)
    """
    return _generate(name, **params)


def resolve(world: WorldLike) -> World:
    """``world`` itself, or the world a world file or a ``GENERATOR[:NAME=VALUE,...]`` text names.

    Examples
    --------
    >>> resolve(generate("cycle", n=3)).n
    3
    >>> resolve("wheel-a").n  # Figure 3.4's wheel
    5
    """
    if isinstance(world, World):
        return world
    if isinstance(world, (str, os.PathLike)):
        return resolve_world(os.fspath(world))
    raise InvalidInput(f"a world must be a World, a world file or a generator text, not {type(world).__name__}")

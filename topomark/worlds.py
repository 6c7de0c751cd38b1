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
import sys
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeAlias, Union

from topomark.arguments import flag, keywords_checked, path as checked_path
from topomark.keywords import check_keywords
from topomark.reference.files.outputs import write_output
from topomark.reference.files.overwrite import claim_file
from topomark.reference.worlds.argument import parse_generator, resolve_world
from topomark.reference.worlds.generators import GENERATORS, PARAMETERS, generate as _generate
from topomark.spec.errors import InvalidInput, clip
from topomark.spec.world import World
from topomark.spec.worldfile import dumps_world, load_world as _load_world

if TYPE_CHECKING:
    import networkx as nx

__all__ = ["load_world", "save_world", "generate", "resolve", "World", "WorldLike"]

WorldLike: TypeAlias = Union[World, str, os.PathLike[str], Mapping[Any, Sequence[Any]], "nx.PlanarEmbedding[Any]"]
"""What a function of the API takes as a world: a World, a world file, a generator text
(``GENERATOR[:NAME=VALUE,...]``), a mapping from each vertex to its neighbours in clockwise order, or a
networkx ``PlanarEmbedding``."""

NO_ROTATION = ("a networkx {kind} has no rotation system (each vertex's neighbours in clockwise order, §3.1.1), "
               "which a world needs: give a networkx PlanarEmbedding (networkx.check_planarity(graph) returns one "
               "for a planar graph) or a dict mapping each vertex to the list of its neighbours in clockwise order")
"""The refusal of a networkx graph that carries no embedding."""


@keywords_checked
def load_world(path: str | os.PathLike[str]) -> World:
    """The world in the world file ``path``; a missing or malformed file, or a ``path`` that is not a path (None,
    an int, an empty string), is InvalidInput naming what is wrong.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> with tempfile.TemporaryDirectory() as d:
    ...     path = pathlib.Path(d) / "w.json"
    ...     save_world(generate("complete", n=4), path)
    ...     load_world(path).m
    6
    """
    return _load_world(checked_path("path", path))


@keywords_checked
def save_world(world: World, path: str | os.PathLike[str], *, force: bool = False) -> None:
    """Write ``world`` to ``path`` in the world-file format; an unwritable path, a ``path`` that is not a path,
    a file already at ``path`` (unless ``force=True``, as ``world -o`` refuses it without ``--force``) and a
    ``world`` that is not a World (:func:`generate` or :func:`load_world` makes one) are InvalidInput.

    Examples
    --------
    >>> save_world(generate("chain", n=3), "/nonexistent-dir/w.json")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: ...nonexistent-dir/w.json...
    """
    if not isinstance(world, World):
        raise InvalidInput(f"save_world() writes a World (generate() or load_world() makes one), "
                           f"not {type(world).__name__}")
    target = checked_path("path", path)
    claim_file(target, "path", flag("force", force))
    write_output(target, dumps_world(world))


@keywords_checked
def generate(name: str | os.PathLike[str], **params: Any) -> World:
    """The world ``name`` names: a generator (``topomark world --help`` lists them and their defaults), a
    generator text such as ``"lattice-hole:rows=5,cols=5"``, or a world file — what ``explore`` and the
    command line take.

    Keywords are the generator's parameters, added to those of the text; parameters not given take their
    defaults, and ``seed=`` picks the random generators' world.  A keyword the generator does not take is
    :class:`~topomark.spec.errors.InvalidKeyword` (a TypeError too), with the closest parameter names; a
    keyword's value of the wrong type (a str or a bool for a number, a number for a word) or out of range is
    InvalidInput naming it.  Only the text's parameters are words to be read as numbers.

    Examples
    --------
    >>> generate("lattice", rows=3, cols=3).n
    9
    >>> generate("lattice-hole:rows=4,cols=4", seed=2).n  # 10% of the cells removed, staying connected
    14
    >>> generate("lattice", colls=3)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidKeyword: generate() got an unexpected keyword argument 'colls'; did you mean 'cols'? ...
    >>> generate("torus")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: 'torus' is neither a world file nor a generator ...
    """
    if not isinstance(name, (str, os.PathLike)):
        raise InvalidInput(f"a world name must be a generator, a generator text or a world file, "
                           f"not {type(name).__name__}")
    text = os.fspath(name)
    if not params:
        return resolve_world(text)
    base, given = parse_generator(text)
    if base not in GENERATORS or os.path.exists(text):
        if os.path.exists(text) or text.endswith(".json"):
            raise InvalidInput(f"{clip(text, 80)} is a world file: it takes no generator parameters "
                               f"(given: {', '.join(params)})")
        return resolve_world(text)  # names what is wrong with the text, with the closest generators
    accepted = ", ".join(PARAMETERS[base]) or "no parameters"
    check_keywords("generate", params, PARAMETERS[base], f"the generator {base} takes {accepted}")
    for key, value in params.items():
        _check_parameter(base, key, value, PARAMETERS[base][key])
    twice = sorted(given.keys() & params.keys())
    if twice:
        raise InvalidInput(f"parameter {twice[0]!r} given twice: in {clip(text, 80, quote=True)} and as a keyword")
    return _generate(base, **given, **params)


def _check_parameter(generator: str, name: str, value: Any, default: Any) -> None:
    """Refuse a keyword's ``value`` whose type is not its ``default``'s: a str or a bool for a number, a number
    for a word (an int stands for a float)."""
    kind = type(default)
    fits = isinstance(value, str) if kind is str else (
        not isinstance(value, (bool, str)) and isinstance(value, int if kind is int else (int, float)))
    if not fits:
        raise InvalidInput(f"generate(): the generator {generator}'s parameter {name} must be {kind.__name__}, "
                           f"not {type(value).__name__} ({clip(repr(value), 60)})")


def resolve(world: WorldLike) -> World:
    """``world`` itself, or the world a world file, a ``GENERATOR[:NAME=VALUE,...]`` text, a rotation
    (vertex ↦ its neighbours in clockwise order) or a networkx ``PlanarEmbedding`` gives.

    A ``PlanarEmbedding`` gives each vertex's neighbours in its clockwise order
    (``neighbors_cw_order``, networkx's ``cw`` attributes: clockwise as networkx draws the embedding with y
    pointing north, the convention of ``spec/world.py``).  Vertex names that are not strings become strings
    (``0`` → ``"0"``; a tuple's parts joined by commas).  A plain networkx graph has no rotation: it is
    refused, saying how to give one.

    Examples
    --------
    >>> resolve(generate("cycle", n=3)).n
    3
    >>> resolve("wheel-a").n  # Figure 3.4's wheel
    5
    >>> resolve({0: [1, 2], 1: [2, 0], 2: [0, 1]}).rotation["0"]
    ('1', '2')
    """
    if isinstance(world, World):
        return world
    if isinstance(world, (str, os.PathLike)):
        return resolve_world(os.fspath(world))
    if isinstance(world, Mapping):
        from topomark.reference.worlds.embedding import from_rotation
        return from_rotation(world)
    nx = sys.modules.get("networkx")  # a networkx graph exists only once networkx is imported
    if nx is not None and isinstance(world, nx.Graph):
        from topomark.reference.worlds.embedding import from_embedding
        if isinstance(world, nx.PlanarEmbedding):
            return from_embedding(world)
        raise InvalidInput(NO_ROTATION.format(kind=type(world).__name__))
    raise InvalidInput(f"a world must be a World, a world file, a generator text, a mapping of each vertex to "
                       f"its neighbours in clockwise order or a networkx PlanarEmbedding, not {type(world).__name__}")

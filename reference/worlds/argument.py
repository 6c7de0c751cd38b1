"""Reading a world argument: a world file or ``GENERATOR[:NAME=VALUE,...]``.

``topomark explore lattice-hole:rows=10,cols=10 --seed 3`` and
``topomark explore world.json`` both name a world.  ``--seed`` goes to the
generator's ``seed`` parameter; giving one where it has no effect (a file, or
a generator without a seed) is refused rather than ignored.

An argument that is both a generator spec and an existing file is the file.
Whether a file exists is asked without failing (:func:`_is_existing_path`):
``lattice-hole:rows=<4,400 digits>`` is a name the operating system refuses
(``ENAMETOOLONG``), which just means "not a file", so it reaches the generator
and its parameter check.
"""

from __future__ import annotations

from pathlib import Path

from topomark.spec.errors import InvalidInput, clip, did_you_mean
from topomark.spec.world import World
from topomark.spec.worldfile import load_world
from topomark.spec.spelling import option

from topomark.reference.worlds.generators import GENERATORS, PARAMETERS, generate

__all__ = ["resolve_world", "parse_generator"]


def _is_existing_path(text: str) -> bool:
    """Whether ``text`` names something that exists; a string that cannot be a path
    (too long, an embedded NUL byte, a component the OS refuses) is simply not one."""
    try:
        return Path(text).exists()
    except (OSError, ValueError):
        return False


def parse_generator(text: str) -> tuple[str, dict[str, str]]:
    """Split ``name:k=v,k=v`` into the name and its parameters."""
    name, _, rest = text.partition(":")
    params: dict[str, str] = {}
    for item in filter(None, rest.split(",")):
        key, eq, value = item.partition("=")
        if not eq or not key:
            raise InvalidInput(f"generator parameter {item!r} in {text!r} is not NAME=VALUE")
        if key in params:
            raise InvalidInput(f"generator parameter {key!r} given twice in {text!r}")
        params[key] = value
    return name, params


def resolve_world(text: str, seed: int | None = None) -> World:
    """The world a command-line argument names."""
    name, params = parse_generator(text)
    exists = _is_existing_path(text)
    if name in GENERATORS and not exists:
        if seed is not None:
            if "seed" not in PARAMETERS[name]:
                raise InvalidInput(f"{option('seed')} has no effect: generator {name!r} is not random")
            if "seed" in params:
                raise InvalidInput(f"seed given twice: {option('seed', seed)} and seed={params['seed']} in {text!r}")
            params["seed"] = str(seed)
        try:
            return generate(name, **params)
        except InvalidInput as exc:  # name the argument: "lattice-hole:rows=3000,cols=3000: ..."
            raise exc.__class__(f"{clip(text, 80)}: {exc}") from None
    if exists or text.endswith(".json"):
        if seed is not None:
            raise InvalidInput(f"{option('seed')} has no effect on a world file ({text})")
        return load_world(text)
    raise InvalidInput(f"{clip(text, 80, quote=True)} is neither a world file nor a generator"
                       f"{did_you_mean(name, GENERATORS)} (generators: {', '.join(GENERATORS)})")

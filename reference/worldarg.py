"""Reading a world argument: a world file or ``GENERATOR[:NAME=VALUE,...]``.

``topomark explore lattice-hole:rows=10,cols=10 --seed 3`` and
``topomark explore world.json`` both name a world.  ``--seed`` goes to the
generator's ``seed`` parameter; giving one where it has no effect (a file, or
a generator without a seed) is refused rather than ignored.
"""

from __future__ import annotations

from pathlib import Path

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World
from topomark.spec.worldfile import load_world

from .generators import GENERATORS, PARAMETERS, generate

__all__ = ["resolve_world", "parse_generator"]


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
    if name in GENERATORS and not Path(text).exists():
        if seed is not None:
            if "seed" not in PARAMETERS[name]:
                raise InvalidInput(f"--seed has no effect: generator {name!r} is not random")
            if "seed" in params:
                raise InvalidInput(f"seed given twice: --seed {seed} and seed={params['seed']} in {text!r}")
            params["seed"] = str(seed)
        return generate(name, **params)
    if Path(text).exists() or text.endswith(".json"):
        if seed is not None:
            raise InvalidInput(f"--seed has no effect on a world file ({text})")
        return load_world(text)
    raise InvalidInput(f"{text!r} is neither a world file nor a generator (generators: {', '.join(GENERATORS)})")

"""The typed face of ``import topomark``: what a type checker, ``dir``, ``repr`` and a misspelt keyword tell a user.

* ``mypy --strict`` on a user's script sees every public name (a misspelt one is an error, not ``Any``), and the
  README's Python block passes it;
* ``dir(topomark)`` is the public names, the types a program annotates with are among them, and importing
  ``topomark`` still imports none of the heavy libraries;
* every public result type has a docstring and a ``repr`` of one short line that says what it is, the data
  staying attributes (an exploration's trace is never in its ``repr``);
* a keyword a function does not take is named as Python names it, with the closest keywords;
* ``generate`` takes the world text ``explore`` and the command line take;
* ``explore`` takes a networkx ``PlanarEmbedding`` in its clockwise order, and says how to give one.
"""

from __future__ import annotations

import inspect
import math
import re
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import networkx as nx
import pytest

import topomark
from topomark.reference.worlds.argument import resolve_world
from topomark.reference.worlds.embedding import from_positions
from topomark.spec import errors
from topomark.worlds import resolve

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
REPR_LIMIT = 1000
RESULT_TYPES = ("Outcome", "MapVerdict", "Witness", "ReplayResult", "Distinction", "SearchResult", "ProofReport",
                "CensusResult", "AdversarialResult", "AlgorithmSpec", "Listed")

MISSPELT = 'import topomark\nrun = topomark.explor("cycle:n=4")\n'
ANNOTATED = '''\
import networkx as nx
import topomark
from topomark import (AdversarialResult, CensusResult, Distinction, InvalidInput, InvalidKeyword, MapVerdict,
                      Outcome, ProofReport, ReplayResult, SearchResult, Witness, World, WorldLike)


def explored(world: WorldLike) -> Outcome:
    return topomark.explore(world, algorithm="basic")


world: World = topomark.generate("lattice-hole:rows=5,cols=5")
run = explored(world)
assert run.map is not None
verdict: MapVerdict = topomark.check_map(world, run.map)
witness: Witness | None = topomark.isomorphic(run.map, world, markers=False)
replayed: ReplayResult = topomark.replay(world, run.trace)
embedding: nx.PlanarEmbedding[int] = nx.PlanarEmbedding()
try:
    topomark.explore(embedding)
except (InvalidInput, InvalidKeyword) as exc:
    print(exc)
found: SearchResult = topomark.search("none", max_vertices=3, max_degree=2)
proof: ProofReport = topomark.prove("none", max_vertices=3, max_degree=2)
census: CensusResult = topomark.census("none", max_vertices=3, max_degree=2)
told: Distinction | None = topomark.distinguish(world, world)
worst: AdversarialResult = topomark.adversarial_search("basic", n=6, evaluations=4)
'''


def readme_python_block() -> str:
    (code,) = re.findall(r"^```python\n(.*?)^```", README.read_text(encoding="utf-8"), re.MULTILINE | re.DOTALL)
    return code


def mypy_strict(tmp_path: Path, scripts: dict[str, str]) -> dict[str, list[str]]:
    """``mypy --strict`` on each user script, as a user who installed topomark runs it: from the checkout's root
    (so that it is this checkout's topomark), without the project's own mypy settings, topomark's own modules
    followed silently as an installed package's are.  The error lines, per script."""
    for name, text in scripts.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    (tmp_path / "mypy.ini").write_text("[mypy]\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "mypy", "--config-file", str(tmp_path / "mypy.ini"), "--strict",
                           "--follow-imports=silent", "--cache-dir", str(tmp_path / "cache"),
                           *(str(tmp_path / name) for name in scripts)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert done.returncode in (0, 1), done.stderr + done.stdout  # 2: mypy itself could not run
    lines = done.stdout.splitlines()
    return {name: [line for line in lines if line.startswith(str(tmp_path / name) + ":")] for name in scripts}


@pytest.mark.slow
def test_mypy_strict_sees_every_public_name_and_the_readme_block_passes(tmp_path):
    found = mypy_strict(tmp_path, {"misspelt.py": MISSPELT, "annotated.py": ANNOTATED,
                                   "readme.py": readme_python_block()})
    assert len(found["misspelt.py"]) == 1 and ':2: error: Module has no attribute "explor"' in found["misspelt.py"][0]
    assert found["annotated.py"] == [] and found["readme.py"] == []


def test_dir_is_the_public_names_and_the_version_is_the_installed_one():
    public = [name for name in dir(topomark) if not name.startswith("__")]
    assert public == sorted(name for name in topomark.__all__ if not name.startswith("__"))
    assert not {"Any", "importlib", "annotations", "TYPE_CHECKING", "version"} & set(dir(topomark))
    assert "__version__" in dir(topomark) and topomark.__version__ == version("topomark")
    with pytest.raises(AttributeError, match="no attribute 'importlib'"):
        topomark.importlib  # noqa: B018


def test_the_types_users_annotate_with_are_importable_from_topomark():
    from topomark import InvalidInput, MapVerdict, Outcome, World  # noqa: F401 - the import is the test
    from topomark.reference.run.outcome import Outcome as Home
    from topomark.spec.world import World as WorldHome

    assert Outcome is Home and World is WorldHome and InvalidInput is errors.InvalidInput
    raised = {name for name in errors.__all__
              if isinstance(getattr(errors, name), type) and issubclass(getattr(errors, name), errors.TopomarkError)}
    assert raised | {"Violation"} <= set(topomark.__all__)
    for name in (*RESULT_TYPES, "Policies", "Start", "WorldLike"):
        assert name in topomark.__all__ and getattr(topomark, name) is not None


def test_import_topomark_imports_no_heavy_library():
    code = ("import sys, topomark; print(sorted(m for m in sys.modules if m.split('.')[0] in "
            "('networkx', 'numpy', 'z3', 'scipy') or m.startswith('topomark.')))")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.stdout.strip() == "[]", done.stderr


def short(thing: object, *words: str) -> str:
    text = repr(thing)
    assert len(text) < REPR_LIMIT and text.startswith(type(thing).__name__ + "(") and "\n" not in text, text
    assert all(word in text for word in words), text
    return text


def test_an_explorations_repr_says_what_it_is_and_leaves_the_trace_out():
    world = "lattice-hole:rows=10,cols=10"
    run = topomark.explore(world)
    text = short(run, "algorithm='basic'", f"world n={run.n} m={run.m}", f"cost={run.cost}", "correct", "verified",
                 f"{run.checks} checks")
    assert len(run.trace) > 1000 and "event" not in text and "perception" not in text
    assert run.map is not None and run.map.n == run.n  # the data stay attributes
    short(topomark.check_map(world, run.map), "isomorphic", "witness verified")
    short(topomark.check_map("cycle:n=6", run.map), "not isomorphic", "mismatch")
    short(topomark.isomorphic(run.map, run.map), f"{run.n} vertices")
    short(topomark.replay(world, run.trace), "ok", f"cost={run.cost}")
    tampered = [dict(r) for r in run.trace]
    tampered[-1]["cost"] += 1
    short(topomark.replay(world, tampered), "diverged at line")
    stopped = topomark.explore("lattice:rows=3,cols=3", algorithm="case-0")
    short(stopped, "failed", "not verified", "reason: ")


def test_every_other_result_has_a_short_repr_that_says_what_it_is():
    found = topomark.search("none", max_vertices=4, max_degree=3)
    short(found, "found", "marker='none'", "worlds n=3 and n=4")
    short(topomark.prove("directional-vertex", max_vertices=3, max_degree=2), "proved")
    short(topomark.census("none", max_vertices=4, max_degree=3), "counterexample n=3 and n=4")
    short(topomark.distinguish("wheel-a:marker=undirected", "wheel-a:marker=directional"), "motions=()")
    short(topomark.adversarial_search("basic", n=8, max_degree=3, evaluations=20, seed=4), "best cost=")
    for spec in topomark.algorithms():
        short(spec, repr(spec.name))


def test_every_public_type_has_a_docstring():
    types = {name for name in topomark.__all__ if isinstance(getattr(topomark, name), type)}
    assert set(RESULT_TYPES) <= types
    for name in sorted(types):
        doc = inspect.getdoc(getattr(topomark, name)) or ""
        assert doc and not doc.startswith(name + "("), f"{name} has no docstring of its own"


def test_a_misspelt_keyword_is_named_as_python_names_it_with_the_closest_keyword():
    with pytest.raises(TypeError) as caught:
        topomark.explore("cycle:n=4", algoritm="basic")
    assert isinstance(caught.value, errors.InvalidInput) and type(caught.value) is errors.InvalidKeyword
    assert str(caught.value).startswith(
        "explore() got an unexpected keyword argument 'algoritm'; did you mean 'algorithm'? (explore() takes world,")
    with pytest.raises(errors.InvalidKeyword, match=r"'max_step'; did you mean 'max_steps'\?"):
        topomark.explore("cycle:n=4", algorithm="model-tree", max_step=10)
    with pytest.raises(errors.InvalidKeyword, match=r"argument 'colour' \(explore\(\) takes .* options: none\)"):
        topomark.explore("cycle:n=4", colour="red")
    with pytest.raises(errors.InvalidKeyword, match=r"^generate\(\) got .* 'colls'; did you mean 'cols'\? "
                                                    r"\(the generator lattice takes rows, cols\)"):
        topomark.generate("lattice", colls=3)
    assert topomark.explore("cycle:n=4", algorithm="model-tree", max_steps=10).outcome == "limit"


def test_generate_takes_the_world_text_explore_and_the_command_line_take(tmp_path):
    text = "lattice-hole:rows=5,cols=5"
    assert topomark.generate(text).rotation == resolve_world(text).rotation == resolve(text).rotation
    assert topomark.explore(text).n == topomark.generate(text).n
    assert (topomark.generate("lattice-hole:rows=5,cols=5", seed=2).rotation
            == topomark.generate("lattice-hole", rows=5, cols=5, seed=2).rotation
            == resolve_world("lattice-hole:rows=5,cols=5,seed=2").rotation)
    topomark.save_world(topomark.generate("wheel-a"), tmp_path / "w.json")
    assert topomark.generate(tmp_path / "w.json").rotation == topomark.generate("wheel-a").rotation
    assert topomark.generate(str(tmp_path / "w.json")).n == 5
    with pytest.raises(errors.InvalidInput, match="is a world file: it takes no generator parameters"):
        topomark.generate(tmp_path / "w.json", rows=3)
    with pytest.raises(errors.InvalidInput, match="parameter 'rows' given twice"):
        topomark.generate(text, rows=4)
    with pytest.raises(errors.InvalidInput, match="neither a world file nor a generator"):
        topomark.generate("torus", n=3)


def cyclically_equal(a: tuple[str, ...], b: tuple[str, ...]) -> bool:
    return len(a) == len(b) and any(a[i:] + a[:i] == b for i in range(len(a)))


def test_explore_takes_a_planar_embedding_in_its_clockwise_order():
    graph = nx.Graph([(0, 1), (1, 2), (2, 0), (0, 3), (3, 4), (4, 0), (1, 5), (0, 5)])
    planar, embedding = nx.check_planarity(graph)
    assert planar
    drawn = from_positions(graph, nx.combinatorial_embedding_to_pos(embedding))  # clockwise as drawn, y north
    world = resolve(embedding)
    assert set(world.rotation) == set(drawn.rotation)
    assert all(cyclically_equal(world.rotation[v], drawn.rotation[v]) for v in drawn.rotation)
    assert any(not cyclically_equal(tuple(reversed(ns)), ns) for ns in world.rotation.values())  # a mirror differs
    run = topomark.explore(embedding)
    assert run.verified and run.map is not None and topomark.check_map(drawn, run.map).isomorphic


def test_a_hand_made_embedding_and_a_rotation_dict_give_the_world_they_describe():
    star = nx.PlanarEmbedding()  # leaves n, e, s, w around c; clockwise from north: n, e, s, w
    star.add_half_edge("c", "n")
    star.add_half_edge("c", "e", ccw="n")  # ccw=r: just clockwise of r
    star.add_half_edge("c", "s", ccw="e")
    star.add_half_edge("c", "w", cw="n")  # cw=r: just counter-clockwise of r
    for leaf in "nesw":
        star.add_half_edge(leaf, "c")
    assert cyclically_equal(resolve(star).rotation["c"], ("n", "e", "s", "w"))
    given = resolve({0: [1, 2, 3], 1: [0], 2: [0], 3: [0]})
    assert given.rotation == {"0": ("1", "2", "3"), "1": ("0",), "2": ("0",), "3": ("0",)}
    assert topomark.explore({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}).verified


@pytest.mark.parametrize("world, message", [
    (nx.cycle_graph(4), "a networkx Graph has no rotation system .* give a networkx PlanarEmbedding .* or a dict "
                        "mapping each vertex to the list of its neighbours in clockwise order"),
    (nx.DiGraph([(0, 1), (1, 0)]), "a networkx DiGraph has no rotation system"),
    ({0: {1, 2}, 1: [0], 2: [0]}, "neighbours of vertex '0' are given as a set, which has no order"),
    ({0: [1], 1: [0], "0": [1]}, "both have the vertex name '0'"),
    ({0: [1], 1: [2]}, "not a vertex"),
    (math.pi, "not float"),
])
def test_a_world_without_a_rotation_is_refused_saying_how_to_give_one(world, message):
    with pytest.raises(errors.InvalidInput, match=message):
        topomark.explore(world)

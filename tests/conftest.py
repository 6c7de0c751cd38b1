"""What the tests share: the small worlds they explore, and one way to build a world from its text.

A test world is written as ``topomark explore`` takes it on the command line -- a generator and its
parameters, ``GENERATOR[:NAME=VALUE,...]`` -- and built by topomark's own reader of that text
(:func:`topomark.reference.worlds.argument.resolve_world`), so a failing test's id is the world to
run again by hand::

    tests/test_registry.py::test_every_registered_algorithm_maps_generated_worlds[random:n=7,fraction=0.5,seed=3-basic]
    $ topomark explore random:n=7,fraction=0.5,seed=3 --algorithm basic

Parametrize over the texts, and build each world in the test::

    from conftest import SMALL_WORLDS, bare, make_world

    @pytest.mark.parametrize("text", SMALL_WORLDS)
    def test_it_maps(text):
        w = bare(make_world(text))  # the Figure 3.4 wheels carry their figure's marker: the robot brings its own

Worlds that no generator text names (a chosen start, a hand-written rotation) stay
:class:`~topomark.spec.world.World` objects in the test file that needs them.  Hypothesis strategies over every
family are in ``tests/families.py``.  The docstring examples of every module run from
``tests/test_docstring_examples.py``.
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
import sys
from pathlib import Path
from typing import Iterator

import pytest

from topomark.reference.worlds.argument import resolve_world
from topomark.spec.world import World

__all__ = ["SMALL_WORLDS", "FIGURE_3_4", "make_world", "bare", "default_suite", "tree_digest"]


def pytest_addoption(parser):
    parser.addoption("--all", action="store_true", dest="run_all",
                     help="run every test, the slow ones (@pytest.mark.slow) included; CI does")


def pytest_collection_modifyitems(config, items):
    """``python3 -m pytest`` runs the fast tests; ``--all`` (or ``-m`` naming the marker) runs the slow ones too.

    A test is marked slow when its cases together take 2 s or more on an idle machine: subprocess-heavy
    hostile inputs, Z3 and census cross-checks, fresh installs, whole conformance suites.  The slow tests are
    deselected, not skipped, and the summary line counts them.
    """
    if config.getoption("run_all") or config.getoption("markexpr"):
        return
    slow = [item for item in items if item.get_closest_marker("slow")]
    if slow:
        config.hook.pytest_deselected(items=slow)
        items[:] = [item for item in items if not item.get_closest_marker("slow")]


def pytest_report_header(config):
    if not (config.getoption("run_all") or config.getoption("markexpr")):
        return "fast tests only: the slow ones (@pytest.mark.slow) are deselected; run them with --all"
    return None


def make_world(text: str) -> World:
    """The world ``topomark explore TEXT`` explores: a generator text (or a world file), read by the CLI's reader."""
    return resolve_world(text)


def bare(w: World) -> World:
    """``w`` with no markers, at the same start: what a robot that brings its own markers explores."""
    return World(w.rotation, (), w.start)


FIGURE_3_4 = ("wheel-a", "wheel-b")
"""Figures 3.4 / 3.6: the wheel pair that one undirected vertex marker cannot tell apart (§3.2.2).  Each carries
its figure's marker: explore ``bare(make_world(text))`` where the robot brings its own."""

SMALL_WORLDS = (
    # lattices with holes: rows x cols, round(fraction * cells) cells (default 0.1) or edges removed, kept connected
    "lattice-hole:rows=3,cols=4,seed=2",
    "lattice-hole:rows=4,cols=4,seed=1",
    "lattice-hole:rows=4,cols=4,seed=2",
    "lattice-hole:rows=4,cols=4,remove=edges,seed=3",
    "lattice-hole:rows=4,cols=5,seed=1",
    "lattice-hole:rows=4,cols=5,seed=3",
    "lattice-hole:rows=4,cols=5,fraction=0.2,remove=edges,seed=7",
    # random graphs: n vertices, round(fraction * n(n-1)/2) edges, connected
    "random:n=7,fraction=0.5,seed=3",
    "random:n=8,fraction=0.4,seed=1",
    "random:n=9,fraction=0.3,seed=2",
    "random:n=9,fraction=0.4,seed=2",
    "random:n=10,fraction=0.3,seed=2",
    # K_n, and K_n with holes: round(fraction * n(n-1)/2) edges (default 0.1) removed, kept connected
    "complete:n=6",
    "complete-hole:n=6,seed=1",
    "complete-hole:n=6,seed=2",
    "complete-hole:n=6,seed=3",
    "complete-hole:n=6,fraction=0.2,seed=1",
    "complete-hole:n=7,seed=1",
    "complete-hole:n=7,seed=3",
    # small worlds: a ring of n, each vertex joined to its k nearest, with a shortcut per ring edge at probability p
    "small-world:n=10,k=2,p=0.2,seed=4",
    "small-world:n=10,k=4,p=0.1,seed=0",
    "small-world:n=10,k=4,p=0.2,seed=3",
    "small-world:n=12,k=4,p=0.2,seed=1",
    "small-world:n=12,k=4,p=0.2,seed=3",
    *FIGURE_3_4,
)
"""The thesis's families (§3.5.3) at sizes every algorithm maps in milliseconds, and the Figure 3.4 wheels: the
worlds that the tests of "every algorithm maps every family" run on.  Explore ``bare(make_world(text))``."""


SCRIPTED = """import json, sys, time
pause, linger = float(sys.argv[2]), float(sys.argv[3])
for msg in json.loads(sys.argv[1]):
    if msg == "hello":
        sys.stdin.readline(); continue
    time.sleep(pause)
    sys.stdout.write(json.dumps(msg) + "\\n"); sys.stdout.flush()
    if msg["type"] in ("move", "drop", "pick_up", "thread"):
        sys.stdin.readline()
time.sleep(linger)
"""


@pytest.fixture(scope="session", autouse=True)
def fault_reports(tmp_path_factory):
    """Where the fault reports of the tests that make topomark fail (exit 3) go: a directory of the session's,
    never the checkout.  Set in the environment, so the CLI run in a subprocess writes there too; the folder."""
    folder = tmp_path_factory.mktemp("fault-reports")
    saved = os.environ.get("TOPOMARK_FAULT_DIR")
    os.environ["TOPOMARK_FAULT_DIR"] = str(folder)
    yield folder
    if saved is None:
        os.environ.pop("TOPOMARK_FAULT_DIR", None)
    else:
        os.environ["TOPOMARK_FAULT_DIR"] = saved


@pytest.fixture(scope="session")
def default_suite(tmp_path_factory, worker_id) -> Iterator[Path]:
    """The conformance suite ``topomark conformance export DIR`` writes with no options (every case, every
    algorithm suite), exported once for the whole run and shared by the tests that only read it: under
    pytest-xdist its workers share one copy (the first to ask exports it, under a lock; the others wait for it).
    A test that damages a suite copies it first; one that writes into the shared copy fails the run at teardown."""
    from topomark.reference.cli.main import main
    # under xdist each worker's base folder is pytest-N/popen-gwK: their parent is this run's alone
    shared = tmp_path_factory.getbasetemp() if worker_id == "master" else tmp_path_factory.getbasetemp().parent
    suite = shared / "default-suite"
    with open(shared / "default-suite.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not suite.is_dir():
            partial = shared / f"default-suite.{os.getpid()}"  # renamed only once whole: never half a suite
            assert main(["conformance", "export", str(partial)]) == 0, "conformance export failed"
            (shared / "default-suite.sha256").write_text(tree_digest(partial))
            partial.rename(suite)
    yield suite
    exported = (shared / "default-suite.sha256").read_text()
    assert tree_digest(suite) == exported, f"a test changed the shared conformance suite {suite}: copy it first"


def tree_digest(folder: Path) -> str:
    """One digest of every file under ``folder``: its relative path and bytes."""
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


@pytest.fixture
def scripted(tmp_path):
    """A protocol client that reads ``hello``, then sends ``messages`` (``pause`` seconds before each), reading the
    answer to each move and marker or thread operation, then waits ``linger`` seconds: a program under test."""
    path = tmp_path / "scripted.py"
    path.write_text(SCRIPTED)
    return lambda *messages, pause=0.0, linger=5.0: [sys.executable, str(path), json.dumps(["hello", *messages]),
                                                    str(pause), str(linger)]


def needs_engine(why: str) -> None:
    """Skip a test that needs the compiled engine where numba has no wheels (the reason says what the test could not
    do); under CI (env ``CI`` set) never: numba is installed there, and without it the test runs uncompiled."""
    from topomark.reference.engine import available
    if not available() and not os.environ.get("CI"):
        pytest.skip(f"numba is not installed: the compiled engine (equal to the reference) cannot {why}")

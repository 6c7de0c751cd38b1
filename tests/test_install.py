"""The package installs from the repository, normally and editable, and its console script runs.

Each install goes into a fresh venv made with ``--system-site-packages`` (so the
runtime dependencies -- networkx, z3, hypothesis -- come from the running
interpreter, or, when the tests run in a venv themselves, from that venv) with
``pip install --no-deps --no-build-isolation``.  Without build
isolation the venv must already hold the build backend the project declares
(``[build-system] requires``), so it is installed into the venv first, through
pip as configured on this machine.

The layout these tests pin: ``topomark/`` is the package, and its ``spec``,
``reference`` and ``proofs`` are links to the root folders of those names, so
the checkout imports as ``topomark`` and the wheel is built straight from it.
"""

from __future__ import annotations

import contextlib
import fcntl
import json
import os
import site
import subprocess
import sys
import tempfile
import tomllib
import venv
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
BUILD_REQUIRES = tomllib.loads((ROOT / "pyproject.toml").read_text())["build-system"]["requires"]

CHECK = """
import importlib.metadata, json, sys
import topomark.spec, topomark.reference, topomark.proofs
from topomark.spec.worldfile import loads_world
dist = importlib.metadata.distribution("topomark")
direct = dist.read_text("direct_url.json")
print(json.dumps({
    "spec": topomark.spec.__file__,
    "reference": topomark.reference.__file__,
    "proofs": topomark.proofs.__file__,
    "dist": str(dist.locate_file("")),
    "editable": bool(direct and json.loads(direct).get("dir_info", {}).get("editable")),
    "prefix": sys.prefix,
}))
"""


def _env():
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return env


def _run(cmd, cwd):
    p = subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True, env=_env(), timeout=300)
    assert p.returncode == 0, f"{cmd} failed ({p.returncode}):\n{p.stdout[-3000:]}\n{p.stderr[-3000:]}"
    return p


def _site_packages(python: Path) -> Path:
    out = _run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"], cwd=python.parent)
    return Path(out.stdout.strip())


def _share_running_environment(python: Path, tmp: Path) -> None:
    """Let the new venv see the packages of the environment running the tests, except topomark itself.

    ``--system-site-packages`` shares the *base* interpreter's packages.  When the
    tests themselves run in a venv (as CI's do) the runtime dependencies live in
    that venv instead, so they are linked into a folder the new venv reads through
    a ``.pth`` file, after its own site-packages.  topomark's own files are left
    out: an installed copy of topomark would otherwise shadow the editable one.
    """
    if sys.prefix == sys.base_prefix:
        return  # the running interpreter is the base one: --system-site-packages already shares it
    deps = tmp / "running-env"
    deps.mkdir()
    for sp in site.getsitepackages():
        for entry in sorted(Path(sp).iterdir()):
            name = entry.name
            if name.endswith(".pth") or name.startswith(("topomark", "__editable__.topomark",
                                                          "__editable___topomark")):
                continue
            if not (deps / name).exists():
                (deps / name).symlink_to(entry)
    (_site_packages(python) / "zz_running_env.pth").write_text(f"{deps}\n")


def _make_venv(where: Path) -> Path:
    venv.EnvBuilder(system_site_packages=True, with_pip=True, clear=True).create(where)
    python = where / "bin" / "python"
    _share_running_environment(python, where.parent)
    _run([python, "-m", "pip", "install", "-q", *BUILD_REQUIRES], cwd=where)
    return python


@contextlib.contextmanager
def _build_lock():
    """One install of ROOT at a time, across processes (a build reads the tree while another may write to it)."""
    with open(Path(tempfile.gettempdir()) / "topomark-install-test.lock", "w") as fh:
        fcntl.flock(fh, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def _install_root(python: Path, outside: Path, *options: str) -> None:
    with _build_lock():
        _run([python, "-m", "pip", "install", "-q", "--no-deps", "--no-build-isolation", *options, ROOT],
             cwd=outside)


def _installed(python: Path, outside: Path) -> dict:
    return json.loads(_run([python, "-c", CHECK], cwd=outside).stdout)


def _console_script(venv_dir: Path, outside: Path):
    world = outside / "w.json"
    world.write_text('{"format": "topomark/world@1", "rotation": {"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}}')
    script = venv_dir / "bin" / "topomark"
    assert script.exists()
    p = _run([script, "world", "--show", world.name], cwd=outside)
    assert "n=3 m=3 genus=0" in p.stdout and "Traceback" not in p.stderr
    bad = subprocess.run([str(script), "world", "--show", "missing.json"], cwd=outside, capture_output=True,
                         text=True, env=_env(), timeout=120)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and "missing.json" in bad.stderr


@pytest.fixture
def outside(tmp_path):
    d = tmp_path / "elsewhere"
    d.mkdir()
    assert ROOT not in d.resolve().parents
    return d


@pytest.mark.slow
def test_install_into_a_fresh_venv(tmp_path, outside):
    venv_dir = tmp_path / "venv"
    python = _make_venv(venv_dir)
    _install_root(python, outside)
    info = _installed(python, outside)
    venv_root = venv_dir.resolve()
    for key in ("spec", "reference", "proofs"):
        path = Path(info[key]).resolve()
        assert venv_root in path.parents, (key, path)
        assert ROOT not in path.parents
    assert Path(info["spec"]).parent.name == "spec" and Path(info["spec"]).parent.parent.name == "topomark"
    assert not info["editable"]
    assert Path(info["prefix"]).resolve() == venv_root
    # the schema is package data: it must be installed with the code
    assert (Path(info["spec"]).parent / "world.schema.json").is_file()
    _console_script(venv_dir, outside)


@pytest.mark.slow
def test_editable_install_into_a_fresh_venv(tmp_path, outside):
    venv_dir = tmp_path / "venv"
    python = _make_venv(venv_dir)
    _install_root(python, outside, "-e")
    info = _installed(python, outside)
    assert info["editable"]
    assert venv_dir.resolve() in Path(info["dist"]).resolve().parents  # the metadata lives in the venv
    assert Path(info["spec"]).resolve() == ROOT / "spec" / "__init__.py"
    assert Path(info["reference"]).resolve() == ROOT / "reference" / "__init__.py"
    assert Path(info["proofs"]).resolve() == ROOT / "proofs" / "__init__.py"
    _console_script(venv_dir, outside)


LINKS = ("spec", "reference", "proofs")
"""The root folders that ``topomark/`` reaches through links of the same name."""


def checkout_files() -> set[str]:
    """Every file of the package in the checkout, as its path inside the wheel (``topomark/spec/world.py``)."""
    found = set()
    for path in (ROOT / "topomark").rglob("*"):
        if path.is_file() and "__pycache__" not in path.parts:
            found.add(str(path.relative_to(ROOT)))
    for link in LINKS:
        for path in (ROOT / link).rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts:
                found.add(str(Path("topomark") / path.relative_to(ROOT)))
    return found


def test_repository_layout_is_the_package():
    for link in LINKS:
        path = ROOT / "topomark" / link
        assert path.is_symlink() and path.resolve() == ROOT / link, f"topomark/{link} must link to ../{link}"
        assert (ROOT / link / "__init__.py").is_file()
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert meta["tool"]["hatch"]["build"]["targets"]["wheel"]["packages"] == ["topomark"]
    assert meta["project"]["scripts"]["topomark"] == "topomark.reference.cli.main:main"
    # every folder holding modules is a package, or it would import as a namespace package from the checkout
    for top in ("topomark", *LINKS):
        for path in (ROOT / top).rglob("*.py"):
            if "examples" not in path.parts and "__pycache__" not in path.parts:
                assert (path.parent / "__init__.py").is_file(), f"{path.parent} holds modules but no __init__.py"
    assert sys.version_info >= (3, 11)


def test_the_wheel_holds_exactly_the_checkouts_files(tmp_path):
    """A module deleted from the checkout is gone from the wheel, a new one is in it: no stale build copy."""
    with _build_lock():
        _run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", "-w", tmp_path, ROOT],
             cwd=tmp_path)
    (wheel,) = tmp_path.glob("topomark-*.whl")
    with zipfile.ZipFile(wheel) as z:
        names = {n for n in z.namelist() if ".dist-info/" not in n}
    assert names == checkout_files(), (sorted(names - checkout_files()), sorted(checkout_files() - names))

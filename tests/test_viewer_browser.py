"""The run viewer's pages in a real browser: Debian's Chromium driven by Selenium (``topomark view``).

Each page is opened from disk in headless Chromium (the system's ``chromium`` and ``chromedriver``: nothing
downloads a browser), stepped to several lines, and what it shows — the robot's vertex, the markers, the number
of map vertices, the cost — must be what the specification gives at that line (``viewer_truth.py``); a
JavaScript error (a SEVERE browser log entry) fails the test.  A screenshot of each kind of page is kept in
``$TOPOMARK_ARTEFACTS`` (CI's artefact directory) or a temporary directory the test prints.

Without Chromium, its driver or Selenium these tests skip with the reason; under CI (env ``CI`` set, where
``.ci/run`` installs all three) they fail instead.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.replay.replay import parse_trace
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.worlds import generators as g
from topomark.spec.worldfile import dumps_world

from viewer_truth import truths

pytestmark = pytest.mark.slow
ROOT = Path(__file__).resolve().parents[1]
WRONG = str(ROOT / "tests" / "clients" / "wrong_client.py")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync", "--window-size=1500,1100")


def _missing() -> str | None:
    """Why the browser tests cannot run here, or None."""
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if browser is None or shutil.which("chromedriver") is None:
        return "Chromium and its driver are not installed (Debian: apt-get install chromium chromium-driver)"
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "Selenium is not installed (pip install -e '.[test]')"
    return None


@pytest.fixture(scope="module")
def browser():
    why = _missing()
    if why is not None:
        if os.environ.get("CI"):
            pytest.fail(f"CI installs the browser tests' tools, but: {why}")
        pytest.skip(why)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    os.environ["SE_OFFLINE"] = "true"  # Selenium's manager must never fetch a browser or a driver
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium") or shutil.which("chromium-browser") or ""
    profile = tempfile.mkdtemp(prefix="topomark-chromium-")
    for flag in (*FLAGS, f"--user-data-dir={profile}"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    yield driver
    driver.quit()
    shutil.rmtree(profile, ignore_errors=True)


@pytest.fixture(scope="module")
def artefacts():
    where = Path(os.environ.get("TOPOMARK_ARTEFACTS") or tempfile.mkdtemp(prefix="topomark-viewer-"))
    where.mkdir(parents=True, exist_ok=True)
    print(f"viewer screenshots in {where}")
    return where


def _errors(driver) -> list[str]:
    return [e["message"] for e in driver.get_log("browser") if e["level"] == "SEVERE"]


def _open(driver, path: Path) -> None:
    driver.get(path.resolve().as_uri())
    assert driver.execute_script("return typeof topomarkView") == "object", _errors(driver)


def _shown(driver, frame: int) -> dict[str, str]:
    driver.execute_script(f"topomarkView.go({frame})")
    return {k: driver.find_element("id", f"tm-{k}").text for k in ("robot-vertex", "markers", "map-vertices", "cost")}


def _check_lines(driver, world, records, frames, mapped: bool = True) -> None:
    """At each of ``frames``, the page shows the truth; ``mapped``: the trace has a map (Algorithm 3.1's
    family), else the page shows none."""
    truth = truths(world, records)
    for k in frames:
        shown, want = _shown(driver, k), truth[k]
        assert shown["robot-vertex"] == want.vertex and shown["markers"] == want.markers, (k, shown, want)
        assert shown["cost"] == str(want.cost), (k, shown, want)
        if not mapped:
            assert shown["map-vertices"] == "0", (k, shown)
        elif want.map_vertices is not None:
            assert shown["map-vertices"] == str(want.map_vertices), (k, shown, want)


def _write(tmp_path, world, trace) -> tuple[str, str, list[dict]]:
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "t.jsonl").write_text(dump_trace(trace))
    return str(tmp_path / "w.json"), str(tmp_path / "t.jsonl"), parse_trace(dump_trace(trace))


@pytest.mark.parametrize("lighthouse", ["directional-vertex", "directional-edge"])
def test_a_verified_run_shows_what_the_specification_gives(browser, artefacts, tmp_path, lighthouse):
    world = g.lattice(3, 4)
    w, t, records = _write(tmp_path, world, explore(world, lighthouse=LIGHTHOUSES[lighthouse]).trace)
    page = tmp_path / "v.html"
    assert main(["view", t, "--world", w, "-o", str(page)]) == 0
    _open(browser, page)
    n = len(records)
    _check_lines(browser, world, records, [0, 1, 2, 3, n // 5, n // 3, n // 2, (3 * n) // 4, n - 2, n - 1])
    step = browser.execute_script("return topomarkView.frameOfStep(20)")
    assert _shown(browser, step)["cost"] == "20"
    body = browser.find_element("tag name", "body")
    body.send_keys("\ue014")  # the right arrow key: one line on
    assert browser.execute_script("return topomarkView.frame()") == step + 1
    assert "VERIFIED" in browser.find_element("id", "tm-verdict").text
    browser.execute_script(f"topomarkView.go({n // 2})")
    browser.save_screenshot(str(artefacts / f"viewer-verified-{lighthouse}.png"))
    assert _errors(browser) == []


def test_a_diverging_trace_shows_the_run_up_to_the_divergence(browser, artefacts, tmp_path):
    world = g.lattice(3, 3)
    trace = explore(world).trace
    moves = [r for r in trace if r["event"] == "move"]
    moves[25]["perception"] = "[3,V-2,A]"
    w, t, records = _write(tmp_path, world, trace)
    page = tmp_path / "d.html"
    assert main(["replay", w, t, "--view", str(page)]) == 1
    _open(browser, page)
    bad = records.index(next(r for r in records if r.get("step") == 26 and r["event"] == "move"))
    assert browser.execute_script("return topomarkView.frame()") == bad  # it opens at the divergence
    assert browser.execute_script("return topomarkView.frames") == bad + 1  # the run up to it
    assert browser.find_element("id", "tm-found").text == "perception [3,V-2,A]"
    assert browser.find_element("id", "tm-expected").text.startswith("perception [")
    assert "replay" in browser.find_element("id", "tm-checks").text
    _check_lines(browser, world, records, [0, 5, bad // 2, bad - 1])
    browser.execute_script(f"topomarkView.go({bad})")
    browser.save_screenshot(str(artefacts / "viewer-diverged.png"))
    assert _errors(browser) == []


def test_a_failing_conformance_case_is_drawn(browser, artefacts, tmp_path):
    suite, views = tmp_path / "suite", tmp_path / "views"
    assert main(["conformance", "export", str(suite), "--algorithm", "basic"]) == 0
    assert main(["conformance", "run", str(suite), "-k", "lattice-3x3", "--view-failures", str(views), "--",
                 sys.executable, WRONG, "mirror-map"]) == 1
    page = views / "lattice-3x3.html"
    _open(browser, page)
    assert "FAILED extended isomorphism" in browser.find_element("id", "tm-verdict").text
    assert browser.find_element("id", "tm-found").text and browser.find_element("id", "tm-expected").text
    world = g.lattice(3, 3)  # the suite's world is the lattice generator's (checked: the trace replays on it)
    records = parse_trace((views / "lattice-3x3.jsonl").read_text())
    _check_lines(browser, world, records, [0, 1, 10, len(records) - 1], mapped=False)
    browser.save_screenshot(str(artefacts / "viewer-conformance-failure.png"))
    assert _errors(browser) == []


def test_a_script_error_is_caught(browser, tmp_path):
    """The seeded fault of the JavaScript-error check: a page whose data is cut short throws, and the browser's
    log says so."""
    world = g.cycle(5)
    w, t, _ = _write(tmp_path, world, explore(world).trace)
    page = tmp_path / "v.html"
    assert main(["view", t, "--world", w, "-o", str(page)]) == 0
    html = page.read_text()
    page.write_text(html.replace('"cols":{"kind":"', '"cols":{"kind":"!'))  # not base 64: atob throws
    browser.get(page.resolve().as_uri())
    seen: list[str] = []
    deadline = time.monotonic() + 10  # the log can reach the driver after get() returns, on a loaded machine
    while not any("atob" in e or "InvalidCharacterError" in e or "Uncaught" in e for e in seen):
        assert time.monotonic() < deadline, f"no script error logged in 10 s: {seen}"
        seen += _errors(browser)
        time.sleep(0.1)


def test_ci_installs_the_browser():
    """``.ci/run`` installs Chromium and its driver as it installs nauty (apt-get, as root)."""
    script = (ROOT / ".ci" / "run").read_text()
    assert "chromium chromium-driver" in script
    assert subprocess.run(["bash", "-n", str(ROOT / ".ci" / "run")]).returncode == 0

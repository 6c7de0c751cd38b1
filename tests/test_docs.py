"""The documentation's generated pages are what their generators write, and the site's navigation is whole.

``docs/cli.md`` comes from the parsers (:mod:`topomark.reference.cli.docgen`), ``docs/api.md`` from the
docstrings of ``topomark.__all__`` (:mod:`topomark.docgen`), ``docs/protocol.md`` and ``docs/trace.md``
from ``spec/`` (:mod:`topomark.specpages`), ``docs/results/`` from bench run stores
(:mod:`topomark.reference.bench.publish`); ``mkdocs.yml`` names only pages that exist.
"""

from __future__ import annotations

import gzip
import re
import shutil
from pathlib import Path

import pytest

from topomark import docgen as api_docgen
from topomark import specpages
from topomark.reference.bench import publish
from topomark.reference.cli import docgen as cli_docgen
from topomark.reference.cli.main import COMMANDS, main

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"


def test_docs_cli_md_is_what_the_generator_writes():
    assert (DOCS / "cli.md").read_text(encoding="utf-8") == cli_docgen.markdown(), \
        "docs/cli.md is out of date: run python -m topomark.reference.cli.docgen > docs/cli.md"


def test_docs_api_md_is_what_the_generator_writes():
    assert (DOCS / "api.md").read_text(encoding="utf-8") == api_docgen.markdown(), \
        "docs/api.md is out of date: run python -m topomark.docgen > docs/api.md"


@pytest.mark.parametrize("name", specpages.PAGES)
def test_each_specification_page_is_what_the_generator_writes(name):
    assert (DOCS / name).read_text(encoding="utf-8") == specpages.page(name), \
        f"docs/{name} is out of date: run python -m topomark.specpages docs (spec/{name} is the source)"
    assert f"`spec/{name}`" in specpages.page(name) and name in (ROOT / "mkdocs.yml").read_text(encoding="utf-8")


def test_a_specification_link_the_site_cannot_resolve_stops_the_generator(tmp_path, monkeypatch):
    (tmp_path / "trace.md").write_text("# T\n\n[protocol](protocol.md#hello), [api](../docs/api.md), [x](#y)\n")
    monkeypatch.setattr(specpages, "SPEC", tmp_path)
    assert "[protocol](protocol.md#hello), [api](api.md), [x](#y)" in specpages.page("trace.md")
    (tmp_path / "trace.md").write_text("# T\n\n[the code](world.py)\n")
    with pytest.raises(ValueError, match="world.py"):
        specpages.page("trace.md")
    assert specpages.main([str(tmp_path / "missing")]) == 2


def test_the_cli_reference_has_every_command_and_every_option():
    text = cli_docgen.markdown()
    for name in COMMANDS:
        assert f"\n## topomark {name}\n" in text, name
    for option in ("`--graphs GRAPHS`", "`--report-only`", "`--marker CLASS`", "`--kit", "### topomark conformance run"):
        assert option in text, option


def test_the_api_reference_has_every_public_name_and_its_signature():
    import topomark

    text = api_docgen.markdown()
    for name in topomark.__all__:
        assert f"`topomark.{name}`" in text, name
    assert "explore(world: 'WorldLike', algorithm: 'str' = 'basic'" in text
    assert "`topomark.strategies.worlds`" in text  # a submodule's own names


def test_every_page_the_site_names_exists_and_every_hand_written_page_is_named():
    config = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    named = set(re.findall(r"[\w./-]+\.md", config))
    assert named and not [page for page in named if not (DOCS / page).is_file()]
    assert {p.name for p in DOCS.glob("*.md")} <= named


def test_a_small_sweep_is_published_under_its_command(tmp_path):
    out, docs = tmp_path / "out", tmp_path / "results"
    assert main(["bench", "figure-3.11", "--graphs", "1", "--sizes", "20", "--no-plots", "--quiet", "-o", str(out)]) == 0
    (out / "figure-3.11-extra.png").write_bytes(b"\x89PNG")  # a plot the report names by its prefix
    publish.publish(out, docs)
    page = (docs / "figure-3.11.md").read_text(encoding="utf-8")
    report = (out / "figure-3.11.md").read_text(encoding="utf-8")
    title, _, body = report.partition("\n")
    assert page.startswith(title + "\n\n> Produced by `topomark bench figure-3.11 --graphs 1 --sizes 20`")
    assert "**A small sweep**: 1 worlds per size" in page and body.rstrip("\n") in page
    assert "![figure-3.11-extra](figure-3.11-extra.png)" in page and (docs / "figure-3.11-extra.png").exists()
    publish.write_index(docs)
    index = (docs / "index.md").read_text(encoding="utf-8")
    assert "## Chapter 3" in index and "(figure-3.11.md)" in index


@pytest.mark.slow
def test_publishing_a_sweep_keeps_its_store_and_regenerates_the_pages_from_it(tmp_path, capsys):
    out, docs = tmp_path / "out", tmp_path / "results"
    assert main(["bench", "figure-3.11", "--graphs", "1", "--sizes", "20", "--no-plots", "--quiet", "-o", str(out)]) == 0
    (docs / "stale.md").parent.mkdir()
    (docs / "stale.md").write_text("# a page no store gives\n")
    assert publish.main([str(out), "--docs", str(docs)]) == 0
    store = docs / publish.STORES / "figure-3.11"
    assert sorted(p.name for p in store.iterdir()) == ["runs.csv.gz", "runs.json"]
    with gzip.open(store / "runs.csv.gz", "rb") as rows:
        assert rows.read() == (out / "runs.csv").read_bytes()
    archive = (store / "runs.csv.gz").read_bytes()
    publish.keep(out, docs)  # the same rows make the same archive: a re-published store is no change
    assert (store / "runs.csv.gz").read_bytes() == archive
    page = (docs / "figure-3.11.md").read_text(encoding="utf-8")
    assert "> Produced by `topomark bench figure-3.11 --graphs 1 --sizes 20`" in page
    assert not (docs / "stale.md").exists() and (docs / "index.md").is_file()


def test_a_full_sweep_says_so():
    text = publish.header({"experiment": "section-6.2", "graphs": 30, "sizes": None, "check": True})
    assert "The full experiment" in text and "small sweep" not in text


@pytest.mark.parametrize("what", ["no manifest", "no rows"])
def test_a_directory_that_is_not_a_bench_run_is_bad_input(tmp_path, what, capsys):
    out = tmp_path / "out"
    out.mkdir()
    if what == "no rows":
        assert main(["bench", "figure-3.11", "--graphs", "1", "--sizes", "20", "--no-plots", "--quiet",
                     "-o", str(out)]) == 0
        (out / "runs.csv").unlink()
    assert publish.main([str(out), "--docs", str(tmp_path / "docs")]) == 2
    assert str(out) in capsys.readouterr().err


def test_the_committed_results_name_their_command():
    pages = [p for p in (DOCS / "results").glob("*.md") if p.name != "index.md"]
    assert pages
    for page in pages:
        assert "\n\n> Produced by `topomark bench " in page.read_text(encoding="utf-8"), page.name


REGENERATE = "python -m topomark.reference.bench.publish --all --docs docs/results"


@pytest.mark.slow
def test_the_results_pages_are_what_their_stored_runs_give(tmp_path):
    """Every page and plot of docs/results, regenerated from the run stores kept in docs/results/runs/ by the
    current report code: the same files, the pages byte for byte (the plots are not compared pixel by pixel)."""
    results = DOCS / "results"
    publish.publish_all(results, tmp_path)
    made = {p.name for p in tmp_path.iterdir()}
    kept = {p.name for p in results.iterdir() if p.is_file()}
    assert made == kept, f"docs/results is stale (missing {sorted(made - kept)}, extra {sorted(kept - made)}): " \
                         f"run {REGENERATE}"
    for name in sorted(n for n in made if n.endswith(".md")):
        assert (tmp_path / name).read_bytes() == (results / name).read_bytes(), f"{name} is stale: run {REGENERATE}"


def test_the_stored_runs_are_the_run_stores_only_and_small():
    stores = [p for p in (DOCS / "results" / publish.STORES).iterdir()]
    assert stores and all(sorted(f.name for f in s.iterdir()) == ["runs.csv.gz", "runs.json"] for s in stores)
    assert sum(f.stat().st_size for s in stores for f in s.iterdir()) < 3 * 2 ** 20


def test_a_kept_store_that_is_not_gzip_is_bad_input(tmp_path, capsys):
    docs = tmp_path / "results"
    shutil.copytree(DOCS / "results" / publish.STORES / "figure-3.11", docs / publish.STORES / "figure-3.11")
    (docs / publish.STORES / "figure-3.11" / "runs.csv.gz").write_bytes(b"experiment,size\n")
    assert publish.main(["--all", "--docs", str(docs)]) == 2
    assert "runs.csv.gz: not a gzip archive of runs" in capsys.readouterr().err


def test_publish_all_leaves_only_the_pages_its_stores_give(tmp_path, capsys):
    docs = tmp_path / "results"
    shutil.copytree(DOCS / "results" / publish.STORES / "figure-3.11", docs / publish.STORES / "figure-3.11")
    (docs / "stale.md").write_text("# a page no store gives\n")
    (docs / "stale.png").write_bytes(b"\x89PNG")
    assert publish.main(["--all", "--docs", str(docs)]) == 0
    assert sorted(p.name for p in docs.iterdir()) == ["figure-3.11-small-world-k2-p10.png",
                                                      "figure-3.11-small-world-k4-p20.png", "figure-3.11.md",
                                                      "index.md", publish.STORES]


def test_publish_all_without_stores_is_bad_input(tmp_path, capsys):
    assert publish.main(["--all", "--docs", str(tmp_path)]) == 2
    assert str(tmp_path / publish.STORES) in capsys.readouterr().err
    with pytest.raises(SystemExit) as exc:
        publish.main(["--all", str(tmp_path), "--docs", str(tmp_path)])
    assert exc.value.code == 2

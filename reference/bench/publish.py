"""Publish bench reports as documentation pages: ``docs/results/``, generated, never copied by hand.

``topomark bench EXPERIMENT --out DIR`` writes its reports (``DIR/*.md``) and plots (``DIR/*.png``) next to
the run store (``DIR/runs.csv`` and its manifest ``DIR/runs.json``, :mod:`.run_manifest`).  This module copies
each report into ``DOCS/<report>.md`` under a header that says which command and which sizes produced it —
read from the manifest, so a small sweep says it is one — and copies the plots beside it, each shown at the end
of the page whose report lists it (its ``Plots:`` line), else of the page whose name it starts with, else of
the first page whose title names its figure or table, else of the page of the sweep's experiment.
``DOCS/index.md`` lists every page published there, grouped by chapter of the thesis.

    python -m topomark.reference.bench.publish OUT_DIR [OUT_DIR ...] --docs docs/results

The run stores behind the published pages are kept beside them, in ``DOCS/runs/NAME/`` (``runs.csv`` and
``runs.json`` only).  :func:`publish_all` regenerates every page from them with the current report code — each
store's reports written again (``topomark bench EXPERIMENT --report-only``) in a scratch directory, then
published — and leaves ``DOCS`` holding exactly those pages, their plots and the index:

    python -m topomark.reference.bench.publish --all --docs docs/results

A directory without a run-store manifest or without a report is bad input (exit 2), named.

>>> header({"experiment": "figure-3.11", "graphs": 2, "sizes": [20], "check": True})
'Produced by `topomark bench figure-3.11 --graphs 2 --sizes 20` (every run checked). **A small sweep**: 2 worlds per size (the full experiment: 30) and only the sizes 20; the full experiment is `topomark bench figure-3.11`.'
"""

from __future__ import annotations

import argparse
import re
import shutil
import sys
import tempfile
from pathlib import Path

from topomark.reference.bench.run_manifest import MANIFEST_NAME, read_manifest
from topomark.spec.errors import EXIT_BAD_INPUT, InvalidInput

__all__ = ["publish", "publish_all", "header", "write_index", "main", "CHAPTERS", "STORES"]

STORES = "runs"  # DOCS/runs/NAME/: the run stores the pages of DOCS are published from
STORE_FILES = ("runs.csv", MANIFEST_NAME)

FULL_GRAPHS = 30  # worlds per size in the thesis's experiments (§3.5.3) and the bench's default
CHAPTERS = (  # (chapter heading, report-name prefixes), in the order of the thesis
    ("Chapter 3: the basic algorithm (§3.5.3)", ("figure-3.", "lattice", "complete", "small-world", "random",
                                                 "all", "policies", "lighthouses")),
    ("Chapter 4: the enhancements", ("table-4.", "tables")),
    ("Chapter 5: mapping with less", ("chapter-5",)),
    ("Chapter 6: many markers, threads, movable markers", ("table-6.", "figure-6.", "section-6.", "comparison")),
)
INDEX_HEADER = ("# Results\n\nEach page is a report of `topomark bench`, published from its run store; its header "
                "gives the command and the sizes that produced it. Every run was checked (invariants after every "
                "iteration, extended isomorphism at the end) unless the header says otherwise. The run stores are "
                "kept beside the pages, in `runs/NAME/` (`runs.csv`, one row per run, and `runs.json`, the "
                "sweeps), and every page is regenerated from them by the current code with one command: "
                "`python -m topomark.reference.bench.publish --all --docs docs/results`.\n")


def header(sweep: dict) -> str:
    """One paragraph: the command of ``sweep`` (a manifest entry), and whether it was the full experiment."""
    experiment, graphs, sizes = sweep.get("experiment"), sweep.get("graphs", FULL_GRAPHS), sweep.get("sizes")
    command = f"topomark bench {experiment} --graphs {graphs}"
    command += f" --sizes {' '.join(map(str, sizes))}" if sizes else ""
    if not sweep.get("check", True):
        command += " --no-check"
    checked = "every run checked" if sweep.get("check", True) else "runs not checked"
    text = f"Produced by `{command}` ({checked})."
    if graphs < FULL_GRAPHS or sizes:
        scope = [f"{graphs} worlds per size (the full experiment: {FULL_GRAPHS})" if graphs < FULL_GRAPHS else "",
                 f"only the sizes {', '.join(map(str, sizes))}" if sizes else ""]
        text += (f" **A small sweep**: {' and '.join(s for s in scope if s)}; "
                 f"the full experiment is `topomark bench {experiment}`.")
    else:
        text += " The full experiment: every size, 30 worlds per size."
    return text


def publish(out_dir: str | Path, docs: str | Path) -> list[Path]:
    """Copy the reports and plots of the bench directory ``out_dir`` into ``docs``; the pages written."""
    out_dir, docs = Path(out_dir), Path(docs)
    manifest = read_manifest(out_dir)
    if manifest is None or not manifest.sweeps:
        raise InvalidInput(f"{out_dir}: no run store with a sweep (runs.json); run topomark bench there first")
    reports = sorted(p for p in out_dir.glob("*.md") if p.is_file())
    if not reports:
        raise InvalidInput(f"{out_dir}: no report (*.md); run topomark bench EXPERIMENT --report-only -o {out_dir}")
    docs.mkdir(parents=True, exist_ok=True)
    plots = sorted(p for p in out_dir.glob("*.png") if p.is_file())
    listed = {report: set(re.findall(r"`([^`/]+\.png)`", " ".join(
        line for line in report.read_text(encoding="utf-8").splitlines() if line.startswith("Plots:"))))
        for report in reports}
    claimed = {report: [p for p in plots if p.name in listed[report]] for report in reports}
    for plot in (p for p in plots if not any(p in ps for ps in claimed.values())):
        named = [r for r in reports if plot.stem.startswith(r.stem + "-")]
        if named:
            claimed[named[0]].append(plot)
    home = next((r for r in reports if r.stem == manifest.sweeps[-1].get("experiment")), reports[0])
    titles = {report: report.read_text(encoding="utf-8").partition("\n")[0] for report in reports}
    for plot in (p for p in plots if not any(p in ps for ps in claimed.values())):
        number = re.match(r"(?:figure|table)-(\d+\.\d+)", plot.stem)  # figure-6.11-...: the page titled 6.11
        named = [r for r in reports if number and re.search(rf"\b{re.escape(number[1])}\b", titles[r])]
        claimed[named[0] if named else home].append(plot)
    said = " ".join(header(sweep) for sweep in manifest.sweeps) + f" {manifest.rows:,} runs in the store."
    written = []
    for report in reports:
        body = report.read_text(encoding="utf-8")
        title, _, rest = body.partition("\n")
        page = [title, "", f"> {said} Version: topomark {manifest.topomark}.", rest.rstrip("\n")]
        if claimed[report]:
            page += ["", "## Plots", ""] + [f"![{p.stem}]({p.name})\n" for p in claimed[report]]
        for p in claimed[report]:
            shutil.copyfile(p, docs / p.name)
        target = docs / report.name
        target.write_text("\n".join(page).rstrip("\n") + "\n", encoding="utf-8")
        written.append(target)
    return written


def write_index(docs: str | Path) -> Path:
    """``docs/index.md``: every page in ``docs`` with its title, grouped by chapter."""
    docs = Path(docs)
    pages = sorted(p for p in docs.glob("*.md") if p.name != "index.md")
    lines = [INDEX_HEADER]
    done: set[Path] = set()
    for chapter, prefixes in CHAPTERS + (("Other experiments", ("",)),):
        mine = [p for p in pages if p not in done and p.stem.startswith(prefixes)]
        if mine:
            lines.append(f"\n## {chapter}\n")
            lines += [f"* [{_title(p)}]({p.name})" for p in mine]
            done.update(mine)
    index = docs / "index.md"
    index.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return index


def publish_all(docs: str | Path, into: str | Path | None = None) -> list[Path]:
    """Every page of ``docs`` regenerated from the run stores in ``docs/runs/``, written to ``into`` (default
    ``docs``), which then holds exactly those pages, their plots and the index; the files written."""
    from topomark.reference.bench.experiments import write_report
    from topomark.reference.bench.reports.plots import INSTALL_HINT, pyplot

    docs = Path(docs)
    into = docs if into is None else Path(into)
    root = docs / STORES
    stores = sorted(p for p in root.iterdir() if (p / MANIFEST_NAME).is_file()) if root.is_dir() else []
    if not stores:
        raise InvalidInput(f"{root}: no run store (NAME/runs.csv and NAME/runs.json) to publish from")
    if pyplot() is None:
        raise InvalidInput(f"the published pages show plots: matplotlib is needed ({INSTALL_HINT})")
    with tempfile.TemporaryDirectory(prefix="topomark-publish-") as scratch:
        pages = Path(scratch) / "pages"
        for store in stores:
            work = Path(scratch) / store.name
            work.mkdir()
            for name in STORE_FILES:
                shutil.copyfile(store / name, work / name)
            manifest = read_manifest(work)
            if manifest is None or not manifest.sweeps:
                raise InvalidInput(f"{store}: the run store records no sweep")
            write_report(str(manifest.sweeps[-1]["experiment"]), work, None, plots=True)
            publish(work, pages)
        write_index(pages)
        into.mkdir(parents=True, exist_ok=True)
        for stale in (p for p in into.iterdir() if p.suffix in (".md", ".png") and not (pages / p.name).exists()):
            stale.unlink()
        written = [Path(shutil.copyfile(p, into / p.name)) for p in sorted(pages.iterdir())]
    return written


def _title(page: Path) -> str:
    first = page.read_text(encoding="utf-8").partition("\n")[0]
    return re.sub(r"^#+\s*", "", first).strip() or page.stem


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m topomark.reference.bench.publish",
                                     description="Publish bench reports (DIR/*.md, DIR/*.png) as documentation "
                                                 "pages under a header naming the command that produced them.")
    parser.add_argument("out_dirs", nargs="*", metavar="OUT_DIR", help="a directory written by topomark bench")
    parser.add_argument("--docs", required=True, metavar="DIR", help="where the pages go (docs/results)")
    parser.add_argument("--all", action="store_true", help=f"regenerate every page of DIR from the run stores in "
                                                            f"DIR/{STORES}/ (no OUT_DIR)")
    args = parser.parse_args(argv)
    if bool(args.all) == bool(args.out_dirs):
        parser.error("give OUT_DIR ... or --all, not both")
    try:
        if args.all:
            written = publish_all(args.docs)
            print(f"wrote {len(written)} files in {args.docs} from {args.docs}/{STORES}/")
            return 0
        for out_dir in args.out_dirs:
            for page in publish(out_dir, args.docs):
                print(f"wrote {page}")
        print(f"wrote {write_index(args.docs)}")
    except InvalidInput as exc:
        print(f"publish: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    return 0


if __name__ == "__main__":
    sys.exit(main())

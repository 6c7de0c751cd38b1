"""Publish bench reports as documentation pages: ``docs/results/``, generated, never copied by hand.

``topomark bench EXPERIMENT --out DIR`` writes its reports (``DIR/*.md``) and plots (``DIR/*.png``) next to
the run store (``DIR/runs.csv`` and its manifest ``DIR/runs.json``, :mod:`.run_manifest`).  This module copies
each report into ``DOCS/<report>.md`` under a header that says which command and which sizes produced it —
read from the manifest, so a small sweep says it is one — and copies the plots beside it, each shown at the end
of the page whose report lists it (its ``Plots:`` line), else of the page whose name it starts with, else of
the first page whose title names its figure or table, else of the page of the sweep's experiment.
``DOCS/index.md`` lists every page published there, grouped by chapter of the thesis.

The run stores behind the published pages are kept beside them, in ``DOCS/runs/EXPERIMENT/`` (``runs.csv.gz``,
the rows compressed, and ``runs.json``, the sweeps).  Publishing a bench directory keeps its store there
(:func:`keep`, replacing an earlier store of the same experiment) and then regenerates every page:

    python -m topomark.reference.bench.publish OUT_DIR [OUT_DIR ...] --docs docs/results

:func:`publish_all` regenerates every page from the kept stores with the current report code — each store's
reports written again (``topomark bench EXPERIMENT --report-only``) in a scratch directory, then published — and
leaves ``DOCS`` holding exactly those pages, their plots and the index; after a change to the report code:

    python -m topomark.reference.bench.publish --all --docs docs/results

A directory without a run-store manifest or without a report is bad input (exit 2), named.

>>> header({"experiment": "figure-3.11", "graphs": 2, "sizes": [20], "check": True})
'Produced by `topomark bench figure-3.11 --graphs 2 --sizes 20` (every run checked). **A small sweep**: 2 worlds per size (the full experiment: 30) and only the sizes 20; the full experiment is `topomark bench figure-3.11`.'
"""

from __future__ import annotations

import argparse
import gzip
import re
import shutil
import sys
import tempfile
from pathlib import Path

from topomark.reference.bench.run_manifest import MANIFEST_NAME, read_manifest
from topomark.spec.errors import EXIT_BAD_INPUT, InvalidInput

__all__ = ["publish", "publish_all", "keep", "header", "write_index", "main", "CHAPTERS", "STORES"]

STORES = "runs"  # DOCS/runs/EXPERIMENT/: the run stores the pages of DOCS are published from
ROWS, KEPT_ROWS = "runs.csv", "runs.csv.gz"  # a bench directory's rows; the same, compressed, as kept in DOCS

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
                "kept beside the pages, in `runs/EXPERIMENT/` (`runs.csv.gz`, one row per run, and `runs.json`, "
                "the sweeps), and every page is regenerated from them by the current code with one command: "
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
        raise InvalidInput(f"{root}: no run store (EXPERIMENT/{KEPT_ROWS} and EXPERIMENT/{MANIFEST_NAME}) to "
                           "publish from")
    if pyplot() is None:
        raise InvalidInput(f"the published pages show plots: matplotlib is needed ({INSTALL_HINT})")
    with tempfile.TemporaryDirectory(prefix="topomark-publish-") as scratch:
        pages = Path(scratch) / "pages"
        for store in stores:
            work = Path(scratch) / store.name
            work.mkdir()
            shutil.copyfile(store / MANIFEST_NAME, work / MANIFEST_NAME)
            _unpack(store / KEPT_ROWS, work / ROWS)
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


def keep(out_dir: str | Path, docs: str | Path) -> Path:
    """Keep the run store of the bench directory ``out_dir`` in ``docs/runs/EXPERIMENT/`` (its last sweep's
    experiment), replacing an earlier one: the manifest as it is, the rows compressed (byte-for-byte the same
    archive for the same rows: no time stamp or name in it); the store's folder."""
    out_dir = Path(out_dir)
    manifest = read_manifest(out_dir)
    if manifest is None or not manifest.sweeps or not (out_dir / ROWS).is_file():
        raise InvalidInput(f"{out_dir}: no run store with a sweep ({ROWS}, {MANIFEST_NAME}); run topomark bench "
                           "there first")
    experiment = str(manifest.sweeps[-1]["experiment"])
    if not re.fullmatch(r"[a-z0-9][a-z0-9.-]*", experiment):
        raise InvalidInput(f"{out_dir / MANIFEST_NAME}: the experiment name {experiment!r} is not one")
    store = Path(docs) / STORES / experiment
    store.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(out_dir / MANIFEST_NAME, store / MANIFEST_NAME)
    with open(out_dir / ROWS, "rb") as rows, open(store / KEPT_ROWS, "wb") as raw, \
            gzip.GzipFile(filename="", mode="wb", fileobj=raw, mtime=0, compresslevel=9) as packed:
        shutil.copyfileobj(rows, packed)
    return store


def _unpack(kept: Path, rows: Path) -> None:
    if not kept.is_file():
        raise InvalidInput(f"{kept.parent}: the run store has no {KEPT_ROWS}")
    try:
        with gzip.open(kept, "rb") as packed, open(rows, "wb") as out:
            shutil.copyfileobj(packed, out)
    except (OSError, EOFError) as exc:
        raise InvalidInput(f"{kept}: not a gzip archive of runs ({exc})") from None


def _title(page: Path) -> str:
    first = page.read_text(encoding="utf-8").partition("\n")[0]
    return re.sub(r"^#+\s*", "", first).strip() or page.stem


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m topomark.reference.bench.publish",
                                     description="Keep the run stores of bench directories beside the results "
                                                 "pages and regenerate every page from the kept stores, each under a "
                                                 "header naming the command that produced it.")
    parser.add_argument("out_dirs", nargs="*", metavar="OUT_DIR",
                        help=f"a directory written by topomark bench: its store is kept in DIR/{STORES}/EXPERIMENT/ "
                             "(replacing an earlier one) and every page regenerated")
    parser.add_argument("--docs", required=True, metavar="DIR", help="where the pages go (docs/results)")
    parser.add_argument("--all", action="store_true", help=f"regenerate every page of DIR from the run stores in "
                                                            f"DIR/{STORES}/ (no OUT_DIR)")
    args = parser.parse_args(argv)
    if bool(args.all) == bool(args.out_dirs):
        parser.error("give OUT_DIR ... or --all, not both")
    try:
        for out_dir in args.out_dirs:
            print(f"kept the run store of {out_dir} in {keep(out_dir, args.docs)}")
        written = publish_all(args.docs)
        print(f"wrote {len(written)} files in {args.docs} from {args.docs}/{STORES}/")
    except InvalidInput as exc:
        print(f"publish: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    return 0


if __name__ == "__main__":
    sys.exit(main())

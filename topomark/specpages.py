"""The specification pages of the documentation site, ``docs/protocol.md`` and ``docs/trace.md``.

The protocol and the trace format are specified in ``spec/protocol.md`` and ``spec/trace.md``, beside the
code and schemas they describe; the site shows them as pages of its own, generated from those files (never
copied by hand; ``tests/test_docs.py`` fails when a page is out of date).  Each page is its source with a
line naming that source first, and its links made to work in the site: a link to the other specification
page stays as it is (both pages sit side by side in ``docs/``), a link into ``docs/`` loses its ``../docs/``,
an anchor or an absolute address is kept; any other relative link would not resolve in the site and stops
the generator (:class:`ValueError`, naming it).

    python -m topomark.specpages docs    # writes docs/protocol.md and docs/trace.md

>>> "Generated from `spec/trace.md`" in page("trace.md")
True
>>> _link("[the schema](world.schema.json)", "protocol.md")
Traceback (most recent call last):
...
ValueError: spec/protocol.md: the link 'world.schema.json' would not resolve in the site
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

__all__ = ["PAGES", "page", "main"]

SPEC = Path(__file__).resolve().parent / "spec"
PAGES = ("protocol.md", "trace.md")
"""The files of ``spec/`` that are pages of the site, under the same names in ``docs/``."""
_LINK = re.compile(r"(?<!!)\[([^\]]*)\]\(([^)\s]+)\)")


def _target(target: str, source: str) -> str:
    """``target`` of a link in ``spec/source`` as the site resolves it from ``docs/``."""
    path, _, anchor = target.partition("#")
    if not path or re.match(r"[a-z]+:", path) or path in PAGES:
        return target
    if path.startswith("../docs/"):
        return target.removeprefix("../docs/")
    raise ValueError(f"spec/{source}: the link {target!r} would not resolve in the site")


def _link(text: str, source: str) -> str:
    return _LINK.sub(lambda m: f"[{m.group(1)}]({_target(m.group(2), source)})", text)


def page(name: str) -> str:
    """The site's page ``docs/NAME``: ``spec/NAME`` under a line naming it, its links made to resolve."""
    text = (SPEC / name).read_text(encoding="utf-8")
    title, _, body = text.partition("\n")
    note = (f"\n\n> Generated from `spec/{name}` (`python -m topomark.specpages docs`), the specification beside "
            "the code and schemas it describes: edit that file, not this page.\n")
    return _link(title + note + body, name)


def main(argv: list[str] | None = None) -> int:
    """``python -m topomark.specpages DOCS_DIR``: write every page into DOCS_DIR; exit 0, 2 for bad input."""
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1 or not Path(args[0]).is_dir():
        print("usage: python -m topomark.specpages DOCS_DIR (an existing folder)", file=sys.stderr)
        return 2
    for name in PAGES:
        (Path(args[0]) / name).write_text(page(name), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""The Python API reference, ``docs/api.md``, generated from the docstrings of ``topomark.__all__``.

One section per public name, in ``__all__``'s order: its signature (from :func:`inspect.signature`) and its
docstring, whose prose becomes Markdown (Sphinx roles and double back-quotes become code spans) and whose
``>>>`` examples become a Python block — the same examples the test suite runs.  A submodule of the API
(``topomark.strategies``) gets its docstring and a section per name of its own ``__all__``.  Nothing is
fetched from the network and no documentation plug-in is needed.

    python -m topomark.docgen > docs/api.md

>>> text = markdown()
>>> "## `topomark.explore`" in text and "```python" in text
True
"""

from __future__ import annotations

import inspect
import re
import sys
import types

import topomark

__all__ = ["markdown", "main"]

HEADER = ("# Python API reference\n\n"
          "Generated from the docstrings of `topomark.__all__` (`python -m topomark.docgen`). "
          "`import topomark` is fast: each name is imported when first used. Bad input raises "
          "`topomark.spec.errors.InvalidInput`; a fault of topomark's own checks raises "
          "`topomark.spec.errors.CheckFailure`.\n\n")
_ROLE = re.compile(r":(?:func|class|mod|data|meth|attr|exc):`~?([^`]+)`")


def markdown() -> str:
    """The whole reference: the package's docstring, then one section per public name."""
    parts = [HEADER, _docstring(topomark.__doc__ or "", level=2)]
    for name in topomark.__all__:
        parts.append(_section(f"topomark.{name}", getattr(topomark, name), level=2))
    return "".join(parts)


def _section(qualified: str, obj: object, level: int) -> str:
    heading = "#" * level
    if isinstance(obj, types.ModuleType):
        out = [f"\n{heading} `{qualified}`\n\n", _docstring(obj.__doc__ or "", level + 1)]
        for name in getattr(obj, "__all__", ()):
            out.append(_section(f"{qualified}.{name}", getattr(obj, name), level + 1))
        return "".join(out)
    if not callable(obj):
        value = "the installed package's version" if qualified.endswith("__version__") else f"`{obj!r}`"
        return f"\n{heading} `{qualified}`\n\nA `{type(obj).__name__}`: {value}.\n"
    try:
        signature = str(inspect.signature(obj))
    except (TypeError, ValueError):
        signature = "(...)"
    short = qualified.rsplit(".", 1)[-1]
    return (f"\n{heading} `{qualified}`\n\n```python\n{short}{signature}\n```\n\n"
            + _docstring(inspect.getdoc(obj) or "", level + 1))


def _docstring(doc: str, level: int) -> str:
    """Prose as Markdown paragraphs, every ``>>>`` example (with its output) as a Python block."""
    out: list[str] = []
    block: list[str] = []
    lines = inspect.cleandoc(doc).splitlines() + [""]
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.strip() == "Examples" and i + 1 < len(lines) and set(lines[i + 1].strip()) == {"-"}:
            out.append("Examples:\n\n")
            i += 2
            continue
        if line.lstrip().startswith(">>>"):
            while i < len(lines) and lines[i].strip():
                block.append(lines[i])
                i += 1
            out.append("```python\n" + "\n".join(block) + "\n```\n\n")
            block = []
            continue
        if line.startswith("=====") or not line.strip():
            out.append(_table(lines, i) if line.startswith("=====") else "")
            i = _skip_table(lines, i) if line.startswith("=====") else i + 1
            continue
        paragraph: list[str] = []
        while i < len(lines) and lines[i].strip() and not lines[i].lstrip().startswith(">>>"):
            if paragraph and lines[i].lstrip().startswith(("* ", "- ")):
                break  # a list item starts its own paragraph
            paragraph.append(lines[i].strip())
            i += 1
        text = " ".join(paragraph)
        out.append((f"```text\n{text.removesuffix('::')}\n```\n\n" if paragraph[0].startswith("python ")
                    else _inline(text) + "\n\n"))
    return "".join(out)


def _table(lines: list[str], i: int) -> str:
    """An RST simple table of two columns (name, meaning) as a Markdown table."""
    width = len(lines[i].split()[0])
    rows = []
    for line in lines[i + 1:_skip_table(lines, i) - 1]:
        rows.append(f"| {_cell(line[:width])} | {_cell(line[width:])} |")
    return "| name | what it is |\n|---|---|\n" + "\n".join(rows) + "\n\n"


def _skip_table(lines: list[str], i: int) -> int:
    """The index after the table whose first rule is at ``i``."""
    j = i + 1
    while j < len(lines) and not lines[j].startswith("====="):
        j += 1
    return j + 1


def _inline(text: str) -> str:
    text = _ROLE.sub(lambda m: f"`{m.group(1)}`", text)
    return text.replace("``", "`")


def _cell(text: str) -> str:
    return _inline(text.strip()).replace("|", "\\|")


def main() -> int:
    sys.stdout.write(markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main())

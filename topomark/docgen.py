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

import ast
import dataclasses
import inspect
import re
import sys
import types
import typing

import topomark

__all__ = ["markdown", "main"]

HEADER = ("# Python API reference\n\n"
          "Generated from the docstrings of `topomark.__all__` (`python -m topomark.docgen`). "
          "`import topomark` is fast: each name is imported when first used. Bad input raises "
          "`topomark.spec.errors.InvalidInput`; a fault of topomark's own checks raises "
          "`topomark.spec.errors.CheckFailure`.\n\n")
_PARAMETER = re.compile(r"^\s*(\w+) : ")  # ``name : meaning``, a parameter of a numpydoc list
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
    short = qualified.rsplit(".", 1)[-1]
    if typing.get_origin(obj) is typing.Union:
        alias = " | ".join(_type_name(arg) for arg in typing.get_args(obj))
        return (f"\n{heading} `{qualified}`\n\n```python\n{short} = {alias}\n```\n\n"
                + _docstring(_attribute_doc(short), level + 1))
    if not callable(obj):
        value = "the installed package's version" if qualified.endswith("__version__") else f"`{obj!r}`"
        return f"\n{heading} `{qualified}`\n\nA `{type(obj).__name__}`: {value}.\n"
    if isinstance(obj, type) and (dataclasses.is_dataclass(obj) or issubclass(obj, BaseException)):
        bases = ", ".join(b.__name__ for b in obj.__bases__ if b is not object)
        header = f"class {short}({bases})" if bases else f"class {short}"  # a result's fields: its docstring
        return f"\n{heading} `{qualified}`\n\n```python\n{header}\n```\n\n" + _docstring(_own_doc(obj), level + 1)
    try:
        signature = str(inspect.signature(obj))
    except (TypeError, ValueError):
        signature = "(...)"
    kind = "class " if isinstance(obj, type) else ""
    return (f"\n{heading} `{qualified}`\n\n```python\n{kind}{short}{signature}\n```\n\n"
            + _docstring(_own_doc(obj), level + 1))


def _own_doc(obj: object) -> str:
    """``obj``'s docstring; none rather than the one a class inherits from Exception or object."""
    doc = obj.__doc__ if isinstance(obj, type) else inspect.getdoc(obj)
    return inspect.cleandoc(doc or "")


def _type_name(arg: object) -> str:
    """One member of a type alias as it is written: ``World``, ``os.PathLike[str]``, ``nx.PlanarEmbedding[Any]``."""
    if isinstance(arg, typing.ForwardRef):
        return arg.__forward_arg__
    if isinstance(arg, type) and not typing.get_args(arg):
        return arg.__name__
    return re.sub(r"\b(?:typing|collections\.abc)\.", "", repr(arg))


def _attribute_doc(name: str) -> str:
    """The docstring written under the assignment of ``name`` in the module that defines it, or ``""``."""
    module = sys.modules[getattr(topomark, "_HOME", {}).get(name, "topomark")]
    body = ast.parse(inspect.getsource(module)).body
    for node, after in zip(body, body[1:]):
        target = node.target if isinstance(node, ast.AnnAssign) else None
        if isinstance(target, ast.Name) and target.id == name and isinstance(after, ast.Expr) \
                and isinstance(after.value, ast.Constant) and isinstance(after.value.value, str):
            return after.value.value
    return ""


def _docstring(doc: str, level: int) -> str:
    """Prose as Markdown paragraphs, every ``>>>`` example (with its output) as a Python block."""
    out: list[str] = []
    block: list[str] = []
    lines = inspect.cleandoc(doc).splitlines() + [""]
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.strip() and i + 1 < len(lines) and set(lines[i + 1].strip()) == {"-"}:  # a numpydoc heading
            out.append(f"{line.strip()}:\n\n")
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
            if paragraph and (lines[i].lstrip().startswith(("* ", "- ")) or _PARAMETER.match(lines[i])):
                break  # a list item, or a parameter of a numpydoc list, starts its own paragraph
            paragraph.append(lines[i].strip())
            i += 1
        text = _PARAMETER.sub(r"- `\1`: ", " ".join(paragraph))
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

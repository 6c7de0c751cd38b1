"""Every command block of the README and of the tutorial runs as written and prints what the page shows.

A page is followed as a reader follows it: its fenced ``sh`` blocks run in order, in one empty temporary
folder (the blocks build on each other's files), each line one shell command, ``topomark`` being this
checkout's (``python -m topomark`` with the checkout first on ``PYTHONPATH``, whatever the folder).  The
rules, each visible in the page itself:

* **Install blocks are not run.**  A ``sh`` block whose every command starts ``python3 -m pip install``
  changes the environment rather than showing topomark; it is reported as excluded, never run.
* **Exit codes.**  A command exits 0 unless its line's comment says ``exit N``.
* **Output.**  A ``text`` block that comes next after a ``sh`` block (prose between is fine) is what the
  commands of that block print, standard output and standard error together as a terminal shows them.  A
  line ``...`` in it stands for any number of lines; trailing spaces are ignored.  A ``text`` block that
  follows no ``sh`` block is an error: every output shown is produced by a command shown.
* **Masked.**  Durations are the only run-dependent numbers: a number followed by `` s`` (seconds) is
  compared as ``<n> s`` (:data:`DURATION`).
* **The checkout's files.**  The folder holds a link ``reference`` to the checkout's folder of that name, as
  the checkout's root does (the pages copy the example client from it): :data:`CHECKOUT_LINKS`.
"""

from __future__ import annotations

import difflib
import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.MULTILINE | re.DOTALL)
DURATION = re.compile(r"\b\d[\d,]*(?:\.\d+)? s\b")
"""A duration in seconds, ``0.37 s`` or ``1,204 s``: masked before output is compared."""
EXIT = re.compile(r"#.*\bexit (\d)\b")
"""A command's expected exit code, in its line's comment: ``topomark distinguish a.json b.json  # exit 1``."""
INSTALL = ("python3 -m pip install ",)
"""How an install command starts; a block of nothing else is an install block, not run."""
ELLIPSIS = "..."
CHECKOUT_LINKS = ("reference",)
"""The checkout's folders the pages read from their working folder (the example clients)."""
TIMEOUT = 600


@dataclass
class Block:
    """One ``sh`` block: its commands (continuations joined) and the ``text`` block shown as their output."""

    line: int
    commands: list[str]
    output: str | None = None
    install: bool = False
    problems: list[str] = field(default_factory=list)


def command_lines(body: str) -> list[str]:
    """The commands of a ``sh`` block: one a line, ``\\`` continuations joined, comment-only lines dropped."""
    lines = body.replace("\\\n", " ").splitlines()
    return [line for line in lines if line.strip() and not line.lstrip().startswith("#")]


def page_blocks(text: str) -> list[Block]:
    """The ``sh`` blocks of a page with their output blocks; a ``text`` block after no ``sh`` block raises."""
    found: list[Block] = []
    previous = None
    for m in FENCE.finditer(text):
        language, body, line = m.group(1), m.group(2), text.count("\n", 0, m.start()) + 1
        if language == "sh":
            commands = command_lines(body)
            found.append(Block(line, commands, install=all(c.startswith(INSTALL) for c in commands)))
        elif language == "text":
            if previous != "sh":
                raise ValueError(f"line {line}: a text block that follows no sh block: which command prints it?")
            found[-1].output = body
        previous = language
    return found


def expected_exit(command: str) -> int:
    """The exit code a command's comment states, 0 when it states none."""
    m = EXIT.search(command)
    return int(m.group(1)) if m else 0


def mask(text: str) -> list[str]:
    """Output lines as compared: durations masked, trailing spaces dropped."""
    return [DURATION.sub("<n> s", line).rstrip() for line in text.splitlines()]


def matches(shown: list[str], printed: list[str]) -> bool:
    """Whether ``printed`` is ``shown`` line by line, a ``...`` line of ``shown`` standing for any lines."""
    if not shown:
        return not printed
    head, rest = shown[0], shown[1:]
    if head == ELLIPSIS:
        return any(matches(rest, printed[i:]) for i in range(len(printed) + 1))
    return bool(printed) and printed[0] == head and matches(rest, printed[1:])


def environment(bin_dir: Path) -> dict[str, str]:
    """The commands' environment: ``topomark`` and ``python3`` are this checkout's, unbuffered, no debug."""
    bin_dir.mkdir(exist_ok=True)
    wrapper = bin_dir / "topomark"
    wrapper.write_text(f'#!/bin/sh\nexec {shlex.quote(sys.executable)} -m topomark "$@"\n')
    wrapper.chmod(0o755)
    (bin_dir / "python3").symlink_to(sys.executable)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("TOPOMARK_", "PYTHON"))}
    env.update(PATH=f"{bin_dir}{os.pathsep}{env.get('PATH', '')}", PYTHONPATH=str(ROOT), PYTHONUNBUFFERED="1",
               COLUMNS="100")
    return env


def run_page(text: str, folder: Path) -> tuple[list[Block], str]:
    """Run the blocks of a page in ``folder``; every block's problems are recorded on it, and the transcript."""
    blocks = page_blocks(text)
    work = folder / "work"
    work.mkdir()
    for name in CHECKOUT_LINKS:
        (work / name).symlink_to(ROOT / name)
    env, transcript = environment(folder / "bin"), []
    for block in blocks:
        if block.install:
            transcript.append(f"[line {block.line}: an install block, not run]")
            continue
        printed = []
        for command in block.commands:
            done = subprocess.run(["sh", "-c", command], cwd=work, env=env, stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT)
            printed.append(done.stdout)
            transcript.append(f"$ {command}\n{done.stdout}[exit {done.returncode}]")
            if done.returncode != expected_exit(command):
                block.problems.append(f"{command!r} exited {done.returncode}, the page says "
                                      f"{expected_exit(command)}:\n{done.stdout}")
        if block.output is not None:
            shown, got = mask(block.output), mask("".join(printed))
            if not matches(shown, got):
                diff = "\n".join(difflib.unified_diff(shown, got, "page", "printed", lineterm=""))
                block.problems.append(f"the output differs from the page:\n{diff}")
    return blocks, "\n".join(transcript)


def check_page(page: Path, tmp_path: Path) -> None:
    blocks, _ = run_page(page.read_text(encoding="utf-8"), tmp_path)
    assert [b for b in blocks if not b.install], f"{page.name} has no command block"
    problems = [f"{page.name}, block at line {b.line}: {p}" for b in blocks for p in b.problems]
    assert not problems, "\n\n".join(problems)


@pytest.mark.slow
def test_every_readme_block_runs_as_written(tmp_path):
    check_page(ROOT / "README.md", tmp_path)


@pytest.mark.slow
def test_every_tutorial_block_runs_as_written(tmp_path):
    check_page(ROOT / "docs" / "tutorial.md", tmp_path)


# ---------------------------------------------------------------- each rule of the harness can fail

PAGE = """Make a cycle:

```sh
topomark world cycle:n=5 -o c.json
topomark explore c.json
```

```text
wrote c.json: n=5 m=5 genus=0
explored c.json with §3.3, Algorithm 3.1 (basic; lighthouse directional-vertex; policies edge=nearest, hypothesis=fifo, path=shortest)
...
cost (edge traversals)                        5
...
wall time                                     9.99 s
...
```

```sh
topomark iso c.json c.json  # exit 0: the same world
cat c.json | wc -l   # the files of one block are there in the next
```

```sh
python3 -m pip install .
```
"""


def test_a_page_that_holds_runs_its_blocks_in_order_and_skips_only_the_install_block(tmp_path):
    blocks, transcript = run_page(PAGE, tmp_path)
    assert [b.problems for b in blocks] == [[], [], []]
    assert [b.install for b in blocks] == [False, False, True]
    assert "an install block, not run" in transcript and "$ python3 -m pip" not in transcript


@pytest.mark.parametrize("shown, wrong, problem", [
    ("edge traversals)                        5", "edge traversals)                        6", "output differs"),
    ("wrote c.json: n=5 m=5 genus=0\n", "", "output differs"),                     # a printed line left out
    ("# exit 0: the same world", "# exit 1: the same world", "exited 0, the page says 1"),
])
def test_each_difference_from_the_page_is_found(tmp_path, shown, wrong, problem):
    blocks, _ = run_page(PAGE.replace(shown, wrong), tmp_path)
    assert any(problem in p for b in blocks for p in b.problems), [b.problems for b in blocks]


def test_output_that_follows_no_command_is_refused():
    with pytest.raises(ValueError, match="follows no sh block"):
        page_blocks("```sh\ntopomark claims\n```\n\n```text\na\n```\n\n```text\nb\n```\n")


def test_a_block_mixing_install_and_commands_is_run():
    (block,) = page_blocks("```sh\npython3 -m pip install .\ntopomark explore\n```\n")
    assert not block.install


def test_only_durations_are_masked_and_an_ellipsis_stands_for_any_lines():
    assert mask("wall time  0.01 s  \n1,204 s of CPU; cost 6868") == ["wall time  <n> s", "<n> s of CPU; cost 6868"]
    assert matches(["a", "...", "d"], ["a", "b", "c", "d"]) and matches(["...", "a"], ["a"])
    assert not matches(["a", "...", "d"], ["a", "b"]) and not matches(["a"], ["a", "b"])
    assert expected_exit("topomark census --quiet   # exit 1: 1 ambiguous class") == 1
    assert expected_exit("topomark world cycle -o c.json  # wrote c.json") == 0


# ---------------------------------------------------------------- install hints work from a checkout

PIP = re.compile(r"pip install ((?:-e )?)([^\s`);]+)")


def install_hints(text: str) -> list[str]:
    """What each ``pip install`` of ``text`` installs that a checkout cannot: topomark is on no package index,
    so only the checkout (``.``, ``'.[EXTRA]'``) with the extras ``pyproject.toml`` declares will do."""
    import tomllib

    extras = set(tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
                 ["optional-dependencies"])
    wrong = []
    for m in PIP.finditer(text):
        target = m.group(2).strip("'\"")
        extra = re.fullmatch(r"\.(?:\[([\w,-]+)\])?", target)
        if not extra or not set((extra.group(1) or "").split(",")) - {""} <= extras:
            wrong.append(m.group(0))
    return wrong


def test_every_install_hint_of_the_readme_and_docs_works_from_a_checkout():
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
    wrong = [f"{p.relative_to(ROOT)}: {hint}" for p in pages for hint in install_hints(p.read_text(encoding="utf-8"))]
    assert not wrong, "install from the checkout, python3 -m pip install '.[EXTRA]':\n" + "\n".join(wrong)


def test_an_install_from_a_package_index_or_of_an_unknown_extra_is_found():
    assert install_hints("pip install 'topomark[plot]'; pip install '.[plots]'") == \
        ["pip install 'topomark[plot]'", "pip install '.[plots]'"]
    assert install_hints("python3 -m pip install -e '.[test]' and pip install \".[docs]\" or pip install .") == []

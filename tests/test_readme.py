"""The README and the docs speak truthfully to users: their examples run, their commands parse, and no prose
file points at anything a reader of the repository cannot see.

* The README's Python block runs unchanged; every ``topomark ...`` command of a shell block of the README and
  of the hand-written pages of ``docs/`` is accepted by the command's own parser.
* The README stays short (at most :data:`README_MAX_LINES` lines): the rest lives in ``docs/``.
* No prose — README, CHANGELOG, ``docs/**/*.md``, the module docstrings of ``spec/``, ``reference/``,
  ``proofs/`` and ``topomark/`` — mentions an issue number, "this session", "this machine", a guide outside the
  repository, or a path outside it.
"""

from __future__ import annotations

import ast
import re
import shlex
from pathlib import Path

import pytest

from topomark.reference.cli.main import build_parser

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
README_MAX_LINES = 260
SEPARATORS, REDIRECTIONS = {"&&", "||", "|", ";"}, {">", ">>", "<", "2>", "2>&1"}
GENERATED_PAGES = {"cli.md", "api.md", "checks.md", "claims.md", "marker-classes.md"}
FORBIDDEN = {  # what a reader of the repository cannot follow, and why
    "an issue number": re.compile(r"\bissues?\s*#?\d+|(?<![\w&#/])#\d+\b", re.IGNORECASE),
    "this session": re.compile(r"\bthis session\b", re.IGNORECASE),
    "this machine": re.compile(r"\bthis machine\b", re.IGNORECASE),
    "a guide outside the repository": re.compile(r"\bthe guide\b|thesis-guide", re.IGNORECASE),
    "a path outside the repository": re.compile(r"/work/|\.\./shared"),
}


def blocks(text: str, languages: tuple[str, ...]) -> list[str]:
    """The fenced code blocks of Markdown ``text`` whose language is one of ``languages``."""
    return [m.group(2) for m in re.finditer(r"^```(\w*)\n(.*?)^```", text, re.MULTILINE | re.DOTALL)
            if m.group(1) in languages]


def commands(text: str) -> list[list[str]]:
    """Every ``topomark ...`` command line of the shell blocks of ``text``, split as a shell would."""
    found = []
    for block in blocks(text, ("sh", "bash", "shell", "console")):
        for line in block.replace("\\\n", " ").splitlines():
            words = shlex.split(line, comments=True)
            while words:
                cut = next((i for i, w in enumerate(words) if w in SEPARATORS), len(words))
                if words[0] == "topomark":
                    command = words[1:cut]
                    redirect = next((i for i, w in enumerate(command) if w in REDIRECTIONS), len(command))
                    found.append(command[:redirect])  # a redirection and its file belong to the shell
                words = words[cut + 1:]
    return found


def prose_files() -> list[Path]:
    files = [README, ROOT / "CHANGELOG.md"] + sorted((ROOT / "docs").rglob("*.md"))
    return [f for f in files if f.exists()]


def module_docstrings() -> dict[str, str]:
    found = {}
    for folder in ("spec", "reference", "proofs", "topomark"):
        for path in sorted((ROOT / folder).rglob("*.py")):
            doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")))
            if doc:
                found[str(path.relative_to(ROOT))] = doc
    return found


def test_the_readme_is_short():
    assert len(README.read_text(encoding="utf-8").splitlines()) <= README_MAX_LINES


def test_the_readme_python_block_runs_unchanged(tmp_path, monkeypatch):
    (code,) = blocks(README.read_text(encoding="utf-8"), ("python",))
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {"__name__": "readme"})


def test_the_quick_start_is_the_two_commands():
    text = README.read_text(encoding="utf-8")
    assert 'python3 -m pip install . && topomark explore\npython3 -m pip install -e ".[test]" && python3 -m pytest\n' in text


@pytest.mark.parametrize("page", [README] + sorted(p for p in (ROOT / "docs").glob("*.md")
                                                   if p.name not in GENERATED_PAGES), ids=lambda p: p.name)
def test_every_topomark_command_shown_parses(page):
    shown = commands(page.read_text(encoding="utf-8"))
    for argv in shown:
        build_parser(only=argv[0] if argv else None).parse_args(argv)
    assert shown or page.name not in ("README.md", "tutorial.md", "implementers.md")


def test_a_command_that_does_not_parse_is_caught():
    (argv, redirected) = commands("```sh\ntopomark explore --no-such-option  # a comment\n"
                                  "topomark world cycle > c.json && echo done\n```\n")
    assert redirected == ["world", "cycle"]
    with pytest.raises(Exception, match="no-such-option"):
        build_parser(only="explore").parse_args(argv)


def test_no_prose_points_outside_the_repository():
    texts = {str(p.relative_to(ROOT)): p.read_text(encoding="utf-8") for p in prose_files()}
    texts.update(module_docstrings())
    hits = [f"{where}: {what}: {m.group(0)!r}" for where, text in texts.items()
            for what, pattern in FORBIDDEN.items() for m in pattern.finditer(text)]
    assert not hits, "\n".join(hits)


@pytest.mark.parametrize("text, what", [("see issue 12", "an issue number"), ("fixed in #12.", "an issue number"),
                                        ("measured in this session", "this session"),
                                        ("on this machine", "this machine"),
                                        ("as the thesis-guide says", "a guide outside the repository"),
                                        ("read /work/shared/thesis.txt", "a path outside the repository")])
def test_each_forbidden_phrase_is_found(text, what):
    assert FORBIDDEN[what].search(text)


def test_headings_and_html_entities_are_not_issue_numbers():
    assert not FORBIDDEN["an issue number"].search("## Heading\n&#123; `C#1`/#2")

"""The claims ledger (``topomark claims``): its page is up to date and every name it cites exists.

The existence check reads the test files with ``ast`` (nothing is imported), looks checks up in
``CHECKS``, experiments in the bench's ``EXPERIMENTS``, and parses every command with topomark's own
parser, its algorithm, lighthouse, marker class and experiment names looked up too.  It reports every
missing name at once.
"""

from __future__ import annotations

import ast
import json
import re
import shlex
from pathlib import Path

import pytest

from topomark.reference.algorithms.algorithm_spec import CHECKS
from topomark.reference.algorithms.registry import REGISTRY
from topomark.reference.bench.plan import EXPERIMENTS
from topomark.reference.claims import ledger, report
from topomark.reference.cli.main import build_parser, main
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.spec.errors import TopomarkFault
from topomark.spec.markerclass import MARKER_CLASSES

ROOT = Path(__file__).resolve().parents[1]
CLAIMS = ledger.load()


def functions_of(path: Path) -> set[str]:
    """The test functions a file defines, module level or in a class, read with ast."""
    tree = ast.parse(path.read_text())
    return {node.name for node in ast.walk(tree) if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))}


def _missing_test(test_id: str) -> str | None:
    file, _, name = test_id.partition("::")
    path = ROOT / file
    if not path.is_file():
        return f"test file {file} does not exist"
    return None if name in functions_of(path) else f"test {test_id} does not exist"


def _missing_in_command(command: str, parser) -> list[str]:
    words = shlex.split(command)
    if not words or words[0] != "topomark":
        return [f"command {command!r} is not a topomark command"]
    try:
        args = parser.parse_args(words[1:])
    except Exception as exc:  # noqa: BLE001 - any refusal is a missing command or option
        return [f"command {command!r}: {exc}"]
    named = [("algorithm", getattr(args, "algorithm", None), REGISTRY),
             ("lighthouse", getattr(args, "lighthouse", None), LIGHTHOUSES),
             ("marker class", getattr(args, "marker", None), MARKER_CLASSES),
             ("bench experiment", getattr(args, "experiment", None), EXPERIMENTS)]
    return [f"command {command!r}: {kind} {value!r} does not exist" for kind, value, known in named
            if isinstance(value, str) and value not in known]


def missing_names(claims: list[ledger.Claim]) -> list[str]:
    """Every check, test, bench experiment and command a claim names that does not exist."""
    parser, problems = build_parser(), []
    for c in claims:
        problems += [f"{c.id}: check {k!r} is not in CHECKS" for k in c.checks if k not in CHECKS]
        problems += [f"{c.id}: bench experiment {e!r} does not exist" for e in c.experiments if e not in EXPERIMENTS]
        problems += [f"{c.id}: {p}" for p in map(_missing_test, c.tests) if p]
        problems += [f"{c.id}: {p}" for p in (_missing_in_command(c.command, parser) if c.command else [])]
    return problems


def test_every_check_test_experiment_and_command_the_ledger_names_exists():
    problems = missing_names(CLAIMS)
    assert not problems, f"{len(problems)} names in reference/claims/claims.toml do not exist:\n" + "\n".join(problems)


def test_the_existence_check_finds_each_kind_of_missing_name():
    fake = ledger.Claim("fake", "§3.4", ("§3.4",), "c", "checked", checks=("I-1", "no-such-check"),
                        tests=("tests/test_claims.py::test_no_such_test", "tests/test_nowhere.py::test_x"),
                        experiments=("table-4.1", "table-9.9"),
                        command="topomark explore cycle:n=5 --algorithm no-such-algorithm")
    problems = missing_names([fake, ledger.Claim("cmd", "§3.4", ("§3.4",), "c", "proved", command="topomark nonsense")])
    assert len(problems) == 6, problems
    for words in ("no-such-check", "test_no_such_test", "test_nowhere.py", "table-9.9", "no-such-algorithm",
                  "'topomark nonsense'"):
        assert any(words in p for p in problems), words


def test_docs_claims_md_is_what_the_command_generates(capsys):
    assert main(["claims", "--markdown"]) == 0
    generated = capsys.readouterr().out
    assert (ROOT / "docs" / "claims.md").read_text() == generated, \
        "docs/claims.md is out of date: run topomark claims --markdown > docs/claims.md"


def test_the_ledger_covers_every_chapter_and_every_backing_is_justified():
    summary = ledger.summary(CLAIMS)
    assert set(summary) == {2, 3, 4, 5, 6}
    assert sum(r["total"] for r in summary.values()) == len(CLAIMS) >= 60
    for c in CLAIMS:
        assert c.where and all(ledger.REFERENCE.fullmatch(w) for w in c.where), c.id
        assert c.backing != "measured" or c.verdict in ledger.VERDICTS, c.id
        assert c.reproduce() or c.backing in ("assumed", "unbacked"), c.id


def test_a_malformed_row_is_a_fault_of_topomark(tmp_path):
    bad = tmp_path / "claims.toml"
    bad.write_text('[[claim]]\nid = "x"\nsection = "§3"\nwhere = ["§3"]\nclaim = "c"\nbacking = "measured"\n'
                   'experiments = ["table-4.1"]\ncommand = "topomark bench table-4.1"\nsource = "README"\n')
    with pytest.raises(TopomarkFault, match="needs its evidence"):
        ledger.load(bad)
    bad.write_text(bad.read_text() + 'verdict = "held"\n[[claim]]\nid = "x"\nsection = "§3"\nwhere = ["§3"]\n'
                   'claim = "c"\nbacking = "assumed"\nevidence = "cited"\n')
    with pytest.raises(TopomarkFault, match="used twice"):
        ledger.load(bad)


@pytest.mark.parametrize("where, problem", [('["L' '1506"]', "not a thesis reference"), ('[]', "where is empty"),
                                            ('["§6.2.1, L' '1506"]', "not a thesis reference")])
def test_where_must_cite_the_thesis_by_its_structure(tmp_path, where, problem):
    bad = tmp_path / "claims.toml"
    bad.write_text(f'[[claim]]\nid = "x"\nsection = "§6.2.1"\nwhere = {where}\nclaim = "c"\nbacking = "assumed"\n'
                   'evidence = "cited"\n')
    with pytest.raises(TopomarkFault, match=problem):
        ledger.load(bad)
    bad.write_text(bad.read_text().replace(f"where = {where}", 'where = ["§6.2.1 Case 1a", "Figure 6.4"]'))
    assert ledger.load(bad)[0].thesis == "§6.2.1 Case 1a, Figure 6.4"


@pytest.mark.parametrize("section, where, thesis", [("§6.2.1", ("Table 6.1",), "§6.2.1, Table 6.1"),
                                                    ("§3.6.4", ("§3.6.4", "§3.6.4 footnote 13"), "§3.6.4 footnote 13"),
                                                    ("§3.6", ("§3.6.4",), "§3.6.4"), ("§4", ("Chapter 4",), "Chapter 4")])
def test_the_thesis_column_names_the_section_once(section, where, thesis):
    assert ledger.Claim("x", section, where, "c", "assumed", evidence="cited").thesis == thesis


def test_the_command_prints_the_summary_and_json_exit_0(capsys):
    assert main(["claims"]) == 0
    out = capsys.readouterr().out
    for ch, row in ledger.summary(CLAIMS).items():
        assert report.summary_line(ch, row) in out
    assert main(["claims", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["total"] == len(data["claims"]) == len(CLAIMS)
    assert {c["backing"] for c in data["claims"]} <= set(ledger.BACKINGS)
    measured = [c for c in data["claims"] if c["backing"] == "measured"]
    assert measured and all(c["verdict"] in ledger.VERDICTS and c["reproduce"].startswith("topomark bench")
                            for c in measured)


def test_json_and_markdown_together_are_bad_input():
    assert main(["claims", "--json", "--markdown"]) == 2

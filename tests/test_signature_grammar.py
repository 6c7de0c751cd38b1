"""The signature grammar of ``spec/protocol.md``: the EBNF block there is compiled to a matcher here, and every
signature topomark emits (every registered algorithm on two worlds, random marked worlds, random signatures) is
a sentence of it and round-trips through ``Signature.parse``; what the grammar refuses, topomark refuses."""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.reference.algorithms.registry import REGISTRY
from topomark.reference.run.explore import check_run, explore
from topomark.reference.worlds import generators as g
from topomark.reference.worlds.strategies import worlds
from topomark.spec.errors import InvalidInput
from topomark.spec.signature import Signature, signature_at
from topomark.spec.thread import ThreadMark
from topomark.spec.world import Start

PROTOCOL_MD = Path(__file__).resolve().parents[1] / "spec" / "protocol.md"
_TOKEN = re.compile(r'\s*(::=|"[^"]*"|\[[^\]]*\]|[A-Za-z][A-Za-z-]*|[()|?*+])')


def ebnf_rules() -> dict[str, str]:
    """The rules of the ```ebnf block of spec/protocol.md: name -> body (one rule per line)."""
    block = PROTOCOL_MD.read_text().split("```ebnf\n", 1)[1].split("```", 1)[0]
    rules = {}
    for line in block.strip().splitlines():
        name, body = (part.strip() for part in line.split("::=", 1))
        rules[name] = body
    return rules


def _compile(body: str, rules: dict[str, str], depth: int = 0) -> str:
    """A W3C-style EBNF body as a regular expression (the grammar is not recursive)."""
    assert depth < 20, "the signature grammar must not be recursive"
    out, pos = [], 0
    while pos < len(body):
        m = _TOKEN.match(body, pos)
        assert m, f"cannot read the grammar at {body[pos:]!r}"
        token, pos = m.group(1), m.end()
        if token.startswith('"'):
            out.append(re.escape(token[1:-1]))
        elif token.startswith("[") or token in "()|?*+":
            out.append(token if token != "(" else "(?:")
        else:
            out.append("(?:" + _compile(rules[token], rules, depth + 1) + ")")
        pos += len(body[pos:]) - len(body[pos:].lstrip())
    return "".join(out)


@lru_cache(maxsize=1)
def grammar() -> re.Pattern:
    rules = ebnf_rules()
    return re.compile(_compile(rules["signature"], rules))


def assert_sentence(text: str) -> None:
    assert grammar().fullmatch(text), f"{text!r} is not a signature of the grammar in spec/protocol.md"
    assert str(Signature.parse(text)) == text


def _strings(x, found: set[str]) -> None:
    if isinstance(x, str) and x.startswith("[") and x[1:2].isdigit():
        found.add(x)
    elif isinstance(x, dict):
        for v in x.values():
            _strings(v, found)
    elif isinstance(x, (list, tuple)):
        for v in x:
            _strings(v, found)


def test_the_grammar_is_the_one_block_in_the_spec_and_names_every_rule_it_uses():
    rules = ebnf_rules()
    used = {t for body in rules.values() for t in _TOKEN.findall(body) if t[0].isalpha()}
    assert used <= set(rules) and "signature" in rules


@pytest.mark.parametrize("world", [g.complete(4).with_start(Start("0", "1")),
                                   g.lattice_hole(3, 3, 0.0, seed=1).with_start(Start("0,0", "0,1"))],
                         ids=["K4", "lattice"])
def test_every_signature_every_algorithm_senses_is_a_sentence_of_the_grammar(world):
    found: set[str] = set()
    for name in REGISTRY:
        if name in ("model-tree", "model-tree-listing"):  # its search is slow, and it senses the plain signatures only
            continue
        try:
            check_run(world, REGISTRY[name])
        except InvalidInput:  # an algorithm for a class of worlds (docs/adding-an-algorithm.md) refuses the rest
            continue
        _strings(explore(world, name, check=False).trace, found)
    assert any(",T" in s or ",S" in s for s in found) and any("-H" in s for s in found) and any("V2" in s for s in found)
    for text in found:
        assert_sentence(text)


@settings(max_examples=60, deadline=None)
@given(worlds(max_vertices=6, markers="any"))
def test_every_signature_of_a_marked_world_is_a_sentence_of_the_grammar(world):
    for v in world.vertices:
        for entry in range(world.degree(v)):
            assert_sentence(str(signature_at(world, v, entry)))


@st.composite
def signatures(draw) -> Signature:
    d = draw(st.integers(1, 12))
    exits = st.integers(0, d - 1)
    count = draw(st.integers(0, 3))
    direction = draw(st.one_of(st.none(), exits)) if count else None
    places = draw(st.lists(exits, unique=True, max_size=d))
    edges = tuple(sorted((p, draw(st.integers(1, 3)), draw(st.sampled_from([None, "H", "T"]))) for p in places))
    thread = None
    if draw(st.booleans()):
        tied = draw(st.booleans())
        thread = ThreadMark(tied, draw(st.one_of(st.none(), exits)) if tied else None,
                            tuple(sorted((p, draw(st.integers(1, 3))) for p in draw(st.lists(exits, unique=True)))),
                            draw(st.booleans()), draw(st.integers(0, 3)))
        if thread == ThreadMark(False, None, (), False, 0):
            thread = None
    return Signature(d, count, direction, edges, thread)


@settings(max_examples=300, deadline=None)
@given(signatures())
def test_every_signature_is_written_as_a_sentence_of_the_grammar(sig):
    assert_sentence(str(sig))
    assert Signature.parse(str(sig)) == sig


@pytest.mark.parametrize("text", ["[3,V1,A]", "[3,V0,A]", "[3,A,E1-0]", "[03,A,A]", "[0,A,A]", "[3,A]",
                                  "[3,A,T-0]", "[3,A,A,K1]", "[3,V-01,A]", "[3,A,A,F,T]", "[3,A,A,]",
                                  "[3,A,A,S1-0]", "[3,A,E-0,A]", "[3,B,A]", "[3,A,E-0-X]", "3,A,A", "[3,A,A,K,F]"])
def test_what_the_grammar_refuses_topomark_refuses(text):
    assert not grammar().fullmatch(text)
    with pytest.raises(InvalidInput):
        Signature.parse(text)


@pytest.mark.parametrize("text", ["[2,V-2,A]", "[3,A,E-1,E-0]", "[3,A,E-1,E2-1]", "[2,A,A,T-5]", "[2,A,A,S-1,S-0]",
                                  "[3,A,A,S-3]", "[1" + "0" * 19 + ",A,A]"])
def test_the_rules_beyond_the_grammar_are_what_topomark_refuses(text):
    """Exits below the degree, items in order of exit, numbers of at most 18 digits: the text says so."""
    assert grammar().fullmatch(text)
    with pytest.raises(InvalidInput):
        Signature.parse(text)

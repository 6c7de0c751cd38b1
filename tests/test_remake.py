"""The report's command list remakes a chain of searches in order: each search after the one whose world it
starts from, and each naming the kept world it found."""

from topomark.reference.worstcase.remake import chain_order, commands


def _run(algorithm, restart, n=50):
    return {"algorithm": algorithm, "restart": restart, "objective": "ratio", "evaluations": 10, "max_degree": 4,
            "per_n": [{"n": n}]}


def test_a_search_restarting_from_another_algorithms_world_comes_straight_after_it():
    first = _run("case-2", "strip")
    second = _run("case-1b", "worst-case:case=case-2-n50-d4-search")
    other = _run("case-1b", "strip")
    runs = chain_order([second, other, first], [["worst-case:case=case-1b-x"], [None],
                                                ["worst-case:case=case-2-n50-d4-search"]])
    assert [id(r) for r in runs] == [id(first), id(second), id(other)]


def test_a_search_that_only_found_its_start_is_not_that_worlds_finder():
    maker = _run("basic", "strip")
    idle = _run("basic", "worst-case:case=x")  # no gain: its best is the world it started from
    after = _run("basic", "worst-case:case=x")
    runs = chain_order([after, maker, idle], [["worst-case:case=y"], ["worst-case:case=x"],
                                              ["worst-case:case=x"]])
    assert [id(r) for r in runs] == [id(maker), id(after), id(idle)]


def test_two_searches_starting_from_each_others_worlds_are_each_listed_once():
    a, b = _run("basic", "worst-case:case=b"), _run("basic", "worst-case:case=a")
    runs = chain_order([a, b], [["worst-case:case=a"], ["worst-case:case=b"]])
    assert sorted(map(id, runs)) == sorted([id(a), id(b)])


def test_each_search_names_the_kept_worlds_it_found_and_no_family_text():
    first, second = _run("enh1", "rewired-strip"), _run("enh2", "worst-case:case=enh1-n50")
    lines = commands([], [second, first], [[None], ["worst-case:case=enh1-n50"]])
    assert lines == [
        "`topomark worst-case --search --algorithm enh1 --restart-family rewired-strip --objective ratio "
        "--vertices 50 --evaluations 10 --max-degree 4` → `worst-case:case=enh1-n50`",
        "`topomark worst-case --search --algorithm enh2 --restart-world worst-case:case=enh1-n50 --objective ratio "
        "--vertices 50 --evaluations 10 --max-degree 4`"]
    assert commands([], [first], [["rewired-strip:n=50"]])[0].endswith("--max-degree 4`")

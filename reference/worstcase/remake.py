"""The command lines that remake a worst-case report, a chain of searches in the order it was run (thesis §7.2).

A report summarises the output directories of exhaustive runs and searches; its
last section lists the ``topomark worst-case`` command each directory repeats.
A search may go on from the world another search found (``--restart-world``
naming a kept world), so the order matters: :func:`chain_order` puts every
search after the one whose found world it starts from, and :func:`commands`
names beside each search the kept world it found (``→ `worst-case:case=…```),
so a reader can rebuild a chain link by link.

Examples
--------
>>> a = {"restart": "worst-case:case=x"}
>>> b = {"restart": "strip"}
>>> [r["restart"] for r in chain_order([a, b], [["worst-case:case=y"], ["worst-case:case=x"]])]
['strip', 'worst-case:case=x']
"""

from __future__ import annotations

from typing import Any

from topomark.reference.worstcase.structural import RESTART_FAMILIES

__all__ = ["chain_order", "commands"]


def chain_order(runs: list[dict[str, Any]], found: list[list[str | None]]) -> list[dict[str, Any]]:
    """``runs`` (with ``found[i]``, the generator texts of the worlds run i found, one per size) in the order given,
    except that a run restarting from a world another run found comes straight after that run (and its own
    predecessors).  A run that found only the world it started from (no gain) is not that world's finder; a cycle,
    which no real chain makes, is broken where it closes."""
    finder = {text: i for i, texts in enumerate(found) for text in texts
              if text and text != runs[i].get("restart")}
    order: list[int] = []
    placed: set[int] = set()

    def place(i: int, visiting: set[int]) -> None:
        if i in placed or i in visiting:
            return
        before = finder.get(runs[i].get("restart") or "")
        if before is not None:
            place(before, visiting | {i})
        placed.add(i)
        order.append(i)

    for i in range(len(runs)):
        place(i, set())
    return [runs[i] for i in order]


def _search_command(d: dict[str, Any]) -> str:
    """The command line of one search run (its seed shown unless the default)."""
    family = f" --world-family {d['family']}" if d.get("family") else ""
    if d.get("restart"):
        family += f" --restart-{'family' if d['restart'] in RESTART_FAMILIES else 'world'} {d['restart']}"
    family += f" --objective {d['objective']}" if d.get("objective", "cost") != "cost" else ""
    family += f" --seed {d['setup']['seed']}" if d.get("setup", {}).get("seed") else ""
    sizes = " ".join(str(r["n"]) for r in d["per_n"])
    return (f"topomark worst-case --search --algorithm {d['algorithm']}{family} --vertices {sizes} "
            f"--evaluations {d['evaluations']} --max-degree {d['max_degree']}")


def commands(exhaustive: list[dict[str, Any]], searched: list[dict[str, Any]],
             found: list[list[str | None]]) -> list[str]:
    """The report's list: each exhaustive run's command, then each search's in chain order, with ``→`` and the
    kept worlds it found (markdown, each command in backticks)."""
    out = []
    for d in sorted(exhaustive, key=lambda d: (d["algorithm"], d["max_degree"], d["max_vertices"])):
        out.append(f"`topomark worst-case --algorithm {d['algorithm']} --max-vertices {d['max_vertices']} "
                   f"--max-degree {d['max_degree']}`")
    keyed = sorted(zip(searched, found), key=lambda p: (p[0]["algorithm"], p[0].get("family") or ""))
    runs = chain_order([p[0] for p in keyed], [p[1] for p in keyed])
    texts = {id(run): kept for run, kept in keyed}
    for d in runs:
        kept = [t for t in texts[id(d)] if t and t.startswith("worst-case:")]
        out.append(f"`{_search_command(d)}`" + (f" → {', '.join(f'`{t}`' for t in kept)}" if kept else ""))
    return out

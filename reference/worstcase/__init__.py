"""The worst cost of an algorithm: exhaustive over every small world, adversarial past them (thesis §7.2).

The thesis closes (§7.2) with an open question: its O(m²n) bound
for Algorithm 3.1 "is quite loose", and it asks whether the worst cases exist,
on which classes of graphs, and for tighter bounds in terms of diameter and
maximum degree.  This package answers it by measurement:

* :mod:`.exhaustive` — every embedded world up to isomorphism and every start
  dart up to the world's automorphisms (``topomark worst-case``), resumable;
* :mod:`.brute` — a second opinion for small sizes: every labelled rotation
  system, no isomorphism reduction;
* :mod:`.search` — seeded local search for bad worlds past exhaustive sizes
  (``topomark worst-case --search``): a lower bound on the worst case;
* :mod:`.report` — ``worst-case.md`` and its plots.
"""

"""The conformance suite ``topomark/conformance@2`` (and ``@1``): worlds, reference runs, lint and a runner.

* :mod:`.cases` — what a suite holds: Algorithm 3.1's cases (§3.3–3.5) and one
  suite per deterministic registered algorithm (§2.3.1, Chapters 3, 4 and 6);
* :mod:`.manifest` — the versioned manifest and its shape (``@1`` suites stay
  readable);
* :mod:`.export` — writing a suite with topomark's own checked runs;
* :mod:`.lint` — checking a suite, every trace replayed;
* :mod:`.judgement` — whose a case's bound is, and the two judgements: FAIL above a bound of the thesis's
  listing, a difference above topomark's variant;
* :mod:`.runner` — running an external implementation against it through
  ``topomark/protocol@1`` or ``@2`` and comparing it with the reference of the
  same algorithm.
"""

from topomark.reference.oracle.conformance.cases import (FAMILIES, POLICIES, algorithm_cases, default_cases,
                                                         family_of, suite_algorithms)
from topomark.reference.oracle.conformance.export import LAYOUT, export
from topomark.reference.oracle.conformance.lint import lint
from topomark.reference.oracle.conformance.manifest import (SUITE_FORMAT, SUITE_FORMAT_1, SUITE_VERSION,
                                                            SUITE_VERSION_1, check_manifest, load_manifest)
from topomark.reference.oracle.conformance.runner import (AlgorithmRow, Row, render_algorithm_table, render_table,
                                                          run, run_algorithms, timed_run)

__all__ = ["SUITE_FORMAT", "SUITE_VERSION", "SUITE_FORMAT_1", "SUITE_VERSION_1", "POLICIES", "FAMILIES", "LAYOUT",
           "default_cases", "algorithm_cases", "family_of", "suite_algorithms", "export", "lint", "run",
           "run_algorithms", "Row", "AlgorithmRow", "render_table", "render_algorithm_table", "timed_run",
           "load_manifest", "check_manifest"]

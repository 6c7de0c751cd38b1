"""The reference implementation, arranged by job; imports point only downwards in this list.

* :mod:`.cli` — the ``topomark`` command line: argument parsing and one module per command;
* :mod:`.worstcase` — the worst cost of an algorithm: exhaustive over small worlds, adversarial past them;
* :mod:`.oracle` — judging other implementations: the protocol, ``run-external``, ``drive``, conformance;
* :mod:`.bench` — the thesis's experiments: sweeps, plans, the run store, reports and timing scripts;
* :mod:`.replay` — re-checking a trace's every claim against its world;
* :mod:`.run` — a checked exploration: the simulator (the truth), the checker, the map check, ``explore()``;
* :mod:`.trace` — the trace format: records, header, algorithm families, reader and sinks;
* :mod:`.algorithms` — the registry: every algorithm with its thesis reference, kit, bounds and checks;
* :mod:`.explorers` — the algorithms themselves, behind the wall: they see only the robot interface;
* :mod:`.worlds` — world generators and the hypothesis strategies;
* :mod:`.files` — output files the user names.

Everything rests on :mod:`topomark.spec` (the executable definition) and, for the
commands that search worlds, :mod:`topomark.proofs`.
"""

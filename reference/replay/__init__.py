"""Replay: every claim of a trace re-checked against its world (``spec/trace.md``).

:mod:`.replay` reads and dispatches, :mod:`.robot_layer` re-runs the robot layer, :mod:`.algorithm31_layer`
rebuilds S and U from Algorithm 3.1's iterations, :mod:`.hypotheses` judges each iteration's hypothesis
records, :mod:`.divergence` names the first false claim.
"""

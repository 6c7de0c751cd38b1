"""The places a checked run's new edges reach, replayed on the world by the spec's motion rule (for the tests of
the first walk)."""

from topomark.spec.robot import step


def new_edge_ends(world, trace) -> list[str]:
    """The place each ``new`` move of ``trace`` reached, in order, from the world's start."""
    state, reached = world.start_state(), []
    for record in trace:
        if record.get("event") == "move":
            state = step(world, state, record["motion"])
            if record["purpose"] == "new":
                reached.append(state[0])
    return reached

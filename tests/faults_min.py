"""A minimal faulty explorer shared by CLI tests (the full seeded-fault set lives in faults.py)."""

from topomark.reference.explorers.algorithm31 import LighthouseExplorer


class KeepsLoopDartInU(LighthouseExplorer):
    """Forgets to remove e' from U on a loop closure."""

    def loop_augment(self, it, far, by_marker=False):
        super().loop_augment(it, far, by_marker)
        self.S.unexplored.append(far)

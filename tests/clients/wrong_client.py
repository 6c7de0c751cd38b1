#!/usr/bin/env python3
"""Deliberately wrong protocol clients, built on reference/oracle/examples/client.py: ``wrong_client.py FAULT``.

Explorer faults (the program speaks the protocol correctly but maps wrongly):
  trust-first   accepts the first hypothesis without validating it
  keep-e-prime  forgets to remove e' from U on a loop closure (its snapshots show it)
  mirror-map    sends its map with every rotation reversed (a mirror image)
Protocol faults:
  garbage, hang, crash, bad-exit, greedy (never stops moving), flood (never reads), no-map, bad-map,
  undirected-drop, two-drops
"""
import importlib.util
import json
import sys
import time
from pathlib import Path

spec = importlib.util.spec_from_file_location(
    "client", Path(__file__).resolve().parents[2] / "reference" / "oracle" / "examples" / "client.py")
client = importlib.util.module_from_spec(spec)
spec.loader.exec_module(client)
FAULT = sys.argv[1]


class TrustFirst(client.Explorer):
    def validate(self, vk, sig):
        hyps = [h for h in self.U if h[0] != vk and self.expect(*h) == sig]
        if not hyps:
            return None, 0
        self.pos = (0, 0)  # believes it is at v0; never walked there
        return hyps[0], 0


class KeepEPrime(client.Explorer):
    def iterate(self):
        before = set(self.U)
        super().iterate()
        gone = before - set(self.U)
        self.U += sorted(d for d in gone if self.exits[d[0]][d[1]] is not None and len(gone) > 1)[:1]


class MirrorMap(client.Explorer):
    def run(self):
        while self.U:
            self.iterate()
        names = ["s%d" % v for v in range(len(self.exits))]
        client.send({"type": "map", "world": {
            "format": "topomark/world@1",
            "rotation": {names[v]: [names[w] for w, _ in row][::-1] for v, row in enumerate(self.exits)},
            "markers": [{"kind": "vertex", "at": "s0", "points_to": names[self.exits[0][0][0]]}]}})
        client.receive()


def main():
    if FAULT in ("trust-first", "keep-e-prime", "mirror-map"):
        {"trust-first": TrustFirst, "keep-e-prime": KeepEPrime, "mirror-map": MirrorMap}[FAULT]().run()
        return
    hello = client.receive()
    if FAULT == "garbage":
        print("Hello, topomark! Starting exploration now.", flush=True)
    elif FAULT == "hang":
        time.sleep(3600)
    elif FAULT == "crash":
        raise RuntimeError("segmentation fault (simulated)")
    elif FAULT == "bad-exit":
        client.send({"type": "move", "motion": 99})
    elif FAULT == "greedy":
        while True:
            client.send({"type": "move", "motion": 0})
            client.receive()
    elif FAULT == "flood":  # sends moves without ever reading the answers
        while True:
            client.send({"type": "move", "motion": 0})
    elif FAULT == "no-map":
        client.send({"type": "drop", "direction": 0})
        client.receive()
        sys.exit(0)
    elif FAULT == "bad-map":
        client.send({"type": "map", "world": {"format": "topomark/world@1", "rotation": {"a": ["b"], "b": []}}})
    elif FAULT == "undirected-drop":
        client.send({"type": "drop", "direction": None})
    elif FAULT == "two-drops":
        client.send({"type": "drop", "direction": 0})
        client.receive()
        client.send({"type": "drop", "direction": 0})
    else:
        sys.exit("unknown fault " + FAULT)
    for line in sys.stdin:  # wait for the verdict
        if json.loads(line)["type"] in ("bye", "error"):
            break


if __name__ == "__main__":
    main()

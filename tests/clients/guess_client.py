#!/usr/bin/env python3
"""Protocol clients that send a right map they could not know: ``guess_client.py MODE [K]``.

  blind   sends the map of a two-vertex chain before making a single move
  round   walks K times through the exit after the entry (motion 1), never dropping its marker, and sends a
          cycle of K vertices: right on a K-cycle, but a 2K-cycle would have looked the same
  marked  the same walk after dropping its marker at the start, which it sees again: a map it knows
Each reads topomark/protocol@1 on stdin and writes it on stdout, one JSON message a line.
"""
import json
import sys

MODE = sys.argv[1]
K = int(sys.argv[2]) if len(sys.argv) > 2 else 0


def send(msg):
    print(json.dumps(msg), flush=True)


def receive():
    return json.loads(sys.stdin.readline())


def cycle(k):
    return {str(v): [str((v - 1) % k), str((v + 1) % k)] for v in range(k)}


receive()  # hello
if MODE == "blind":
    send({"type": "map", "world": {"format": "topomark/world@1", "rotation": {"0": ["1"], "1": ["0"]}}})
else:
    markers = []
    if MODE == "marked":
        send({"type": "drop", "direction": 0})
        receive()
        markers = [{"kind": "vertex", "at": "0", "points_to": str(K - 1)}]
    for _ in range(K):
        send({"type": "move", "motion": 1})
        receive()
    send({"type": "map", "world": {"format": "topomark/world@1", "rotation": cycle(K), "markers": markers}})
receive()  # bye

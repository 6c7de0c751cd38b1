#!/usr/bin/env python3
"""An explorer for the ICFP Contest 2025's HTTP interface, written against that interface only.

It imports nothing of topomark (the standard library only) and speaks to any server of the contest's interface:
``topomark contest serve``, or any other that answers ``/register``, ``/select``, ``/explore`` and ``/guess`` as
the contest's task statement describes them.

    python3 explorer.py --server http://127.0.0.1:8000 --problem primus

It selects the problem, learns the map as a Moore machine (rooms are states, doors are inputs, labels are
outputs) with an observation table in the manner of Angluin's L*: access strings S (one per room found, the
first the empty plan), suffixes W (random walks), and for every plan s + w, the labels after s.  Two access
strings whose labels differ after some suffix lead to different rooms.  The table is closed when every s + door
looks like some access string; when it is closed and has as many access strings as the problem has rooms,
every room has been found, and every s + door's room is the access string it looks like, since the rows of S
are pairwise different and cover every room.  Otherwise another random walk is added as a suffix.  Each round's
plans go in one /explore call.

The map guessed: a room per access string, its label, and for the doors, any pairing of door-ends that agrees
with the learned targets (a door of room q to room r is joined to a door of r that leads to q; doors leading
back into their own room are joined to themselves).  The single problems' maps are minimal, so without marks
no plan tells this map from the hidden one.  It prints one JSON object (problem, rooms, queryCount, correct, and
the witness and reason a server such as topomark's adds to a wrong guess's answer) and exits 0 when the guess
was correct, 1 when not, 2 when the server refused a request, 3 when it gave up.
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import urllib.error
import urllib.request

SIZES = {"probatio": 3, "primus": 6, "secundus": 12, "tertius": 18, "quartus": 24, "quintus": 30}
DOORS = 6
MAX_ROUNDS = 200


class Refused(Exception):
    """The server answered a request with an error."""


class Server:
    """POSTs JSON to one server of the contest's interface."""

    def __init__(self, url: str, timeout: float = 60.0):
        self.url, self.timeout = url.rstrip("/"), timeout
        self.calls = 0

    def post(self, path: str, body: dict) -> dict:
        request = urllib.request.Request(self.url + path, data=json.dumps(body).encode(), method="POST",
                                         headers={"Content-Type": "application/json"})
        self.calls += 1
        try:
            with urllib.request.urlopen(request, timeout=self.timeout) as answer:
                return json.load(answer)
        except urllib.error.HTTPError as e:
            raise Refused(f"{path}: HTTP {e.code}: {e.read().decode(errors='replace')[:500]}") from None


def learn(explore, rooms: int, rng: random.Random) -> tuple[list[str], dict[str, int], dict[tuple[str, int], str]]:
    """The access strings, their labels and the door targets of a map of ``rooms`` rooms; ``explore(plans)`` gives
    the records of a list of plans."""
    access: list[str] = [""]
    walks: list[str] = []
    seen: dict[str, list[int]] = {}

    def row(s: str) -> tuple:
        return tuple(tuple(seen[s + w][len(s):]) for w in walks)

    for _ in range(MAX_ROUNDS):
        walks.append("".join(rng.choice("012345") for _ in range(5 * rooms)))
        while True:
            candidates = access + [s + str(d) for s in access for d in range(DOORS)]
            plans = sorted({s + w for s in candidates for w in walks} - set(seen))
            if plans:
                seen.update(zip(plans, explore(plans)))
            rows = {row(s): s for s in access}
            new = {}
            for s in candidates:
                if row(s) not in rows and row(s) not in new:
                    new[row(s)] = s
            if not new:
                break
            access += list(new.values())
        if len(access) == rooms:
            rows = {row(s): s for s in access}
            labels = {s: seen[s + walks[0]][len(s)] for s in access}
            return access, labels, {(s, d): rows[row(s + str(d))] for s in access for d in range(DOORS)}
        if len(access) > rooms:
            raise RuntimeError(f"told {len(access)} rooms apart, more than the problem's {rooms}")
    raise RuntimeError(f"could not tell {rooms} rooms apart in {MAX_ROUNDS} rounds")


def guess_map(access: list[str], labels: dict[str, int], target: dict[tuple[str, int], str]) -> dict:
    """The contest map of the learned machine (see the module's docstring)."""
    index = {s: k for k, s in enumerate(access)}
    connections = []
    for q in access:
        for r in access[index[q]:]:
            there = [d for d in range(DOORS) if target[(q, d)] == r]
            back = [d for d in range(DOORS) if target[(r, d)] == q]
            if q == r:
                back = there
            if len(there) != len(back):
                raise RuntimeError("the learned doors cannot be paired (the map is not what was learned)")
            connections += [{"from": {"room": index[q], "door": a}, "to": {"room": index[r], "door": b}}
                            for a, b in zip(there, back)]
    return {"rooms": [labels[s] for s in access], "startingRoom": 0, "connections": connections}


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description="Explore one problem of an ICFP Contest 2025 server and guess its map.")
    p.add_argument("--server", required=True, help="the server's URL, e.g. http://127.0.0.1:8000")
    p.add_argument("--problem", required=True, help="the problem's name")
    p.add_argument("--rooms", type=int, help="its number of rooms (default: the contest's for its name)")
    p.add_argument("--id", help="the id to play under (default: one from /register)")
    p.add_argument("--seed", type=int, default=0, help="the seed of the random walks")
    args = p.parse_args(argv)
    rooms = args.rooms or SIZES.get(args.problem)
    if not rooms:
        p.error(f"give --rooms for a problem other than {', '.join(SIZES)}")
    server = Server(args.server)
    try:
        ident = args.id or server.post("/register", {"name": "topomark example", "pl": "Python",
                                                     "email": "explorer@localhost"})["id"]
        server.post("/select", {"id": ident, "problemName": args.problem})
        count = [0]

        def explore(plans: list[str]) -> list[list[int]]:
            answer = server.post("/explore", {"id": ident, "plans": plans})
            count[0] = answer["queryCount"]
            return answer["results"]

        access, labels, target = learn(explore, rooms, random.Random(args.seed))
        verdict = server.post("/guess", {"id": ident, "map": guess_map(access, labels, target)})
    except Refused as e:
        print(json.dumps({"problem": args.problem, "error": str(e)}))
        return 2
    except (RuntimeError, OSError) as e:
        print(json.dumps({"problem": args.problem, "error": f"gave up: {e}"}))
        return 3
    out = {"problem": args.problem, "rooms": rooms, "queryCount": count[0],
           "explore_calls": server.calls - 3 + (1 if args.id else 0), "correct": verdict["correct"]}
    out.update({k: v for k, v in verdict.items() if k in ("witness", "reason")})  # what a server may add
    print(json.dumps(out))
    return 0 if verdict["correct"] is True else 1


if __name__ == "__main__":
    sys.exit(main())

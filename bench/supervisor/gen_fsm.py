#!/usr/bin/env python3
"""Large UMDES .fsm inputs for timing the `swarmcheck fsm` verbs from the command line.

  gen_fsm.py chain N OUT.fsm          s0 -a-> s1 -a-> ... s(N-1), the last one marked
  gen_fsm.py tree N OUT.fsm           a binary tree of N states (l / r children), leaves marked
  gen_fsm.py counter N EVENT OUT.fsm  a cycle of N states counting EVENT, state 0 marked: two
                                      counters on different events have an N x N product
  gen_fsm.py grid-sup N OUT.fsm [--last EVENT]
                                      the product of two such counters (x, y) as one automaton,
                                      N^2 states; --last renames the event of the final edge
                                      so that two supervisors differ only at the far end
  gen_fsm.py transfer-line SLOTS DIR  Wonham's transfer line: plants M1.fsm M2.fsm TU.fsm, specs
                                      B1.fsm B2.fsm (buffers of SLOTS slots, TU's rejects go back
                                      to B1); 350 slots give about 10^6 closed-loop states

Names are plain ASCII; every file is written in the writer's canonical form (tab separated).
"""
import os
import sys


def write_fsm(path, states, events):
    """states: [(name, marked, [(event, target)])] with the initial first; events: name -> 'c'|'uc'."""
    with open(path, "w") as out:
        out.write(f"{len(states)}\n\n")
        for name, marked, edges in states:
            out.write(f"{name}\t{1 if marked else 0}\t{len(edges)}\n")
            for e, t in sorted(edges):
                out.write(f"{e}\t{t}\t{events[e]}\to\n")
            out.write("\n")


def chain(n, path):
    states = [(f"s{i}", i == n - 1, [("a", f"s{i + 1}")] if i + 1 < n else []) for i in range(n)]
    write_fsm(path, states, {"a": "c"})


def tree(n, path):
    states = []
    for i in range(n):
        edges = [(e, f"t{c}") for e, c in (("l", 2 * i + 1), ("r", 2 * i + 2)) if c < n]
        states.append((f"t{i}", not edges, edges))
    write_fsm(path, states, {"l": "c", "r": "uc"})


def counter(n, event, path):
    states = [(f"q{i}", i == 0, [(event, f"q{(i + 1) % n}")]) for i in range(n)]
    write_fsm(path, states, {event: "c"})


def grid_sup(n, path, last=None):
    def name(x, y):
        return f"q{x}.q{y}"

    states = []
    for x in range(n):
        for y in range(n):
            edges = [("x", name((x + 1) % n, y)), ("y", name(x, (y + 1) % n))]
            if last is not None and x == n - 1 and y == n - 1:
                edges = [(last, name(0, y)), ("y", name(x, 0))]
            states.append((name(x, y), x == 0 and y == 0, edges))
    write_fsm(path, states, {"x": "c", "y": "uc", **({last: "c"} if last else {})})


def transfer_line(slots, folder):
    """Wonham & Ramadge's transfer line: M1 -> B1 -> M2 -> B2 -> TU, TU rejects back to B1."""
    os.makedirs(folder, exist_ok=True)
    c = {"start1": "c", "finish1": "uc", "start2": "c", "finish2": "uc",
         "start3": "c", "pass": "uc", "reject": "uc"}
    write_fsm(f"{folder}/M1.fsm", [("idle", True, [("start1", "work")]),
                                   ("work", False, [("finish1", "idle")])], c)
    write_fsm(f"{folder}/M2.fsm", [("idle", True, [("start2", "work")]),
                                   ("work", False, [("finish2", "idle")])], c)
    write_fsm(f"{folder}/TU.fsm", [("idle", True, [("start3", "test")]),
                                   ("test", False, [("pass", "idle"), ("reject", "idle")])], c)

    def buffer(path, fill, drain):
        states = []
        for k in range(slots + 1):
            edges = [(e, f"b{k + 1}") for e in fill if k < slots]
            edges += [(drain, f"b{k - 1}")] if k > 0 else []
            states.append((f"b{k}", k == 0, edges))
        write_fsm(path, states, c)

    buffer(f"{folder}/B1.fsm", ["finish1", "reject"], "start2")
    buffer(f"{folder}/B2.fsm", ["finish2"], "start3")


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    kind = argv[1]
    if kind == "chain":
        chain(int(argv[2]), argv[3])
    elif kind == "tree":
        tree(int(argv[2]), argv[3])
    elif kind == "counter":
        counter(int(argv[2]), argv[3], argv[4])
    elif kind == "grid-sup":
        last = argv[5] if len(argv) > 5 and argv[4] == "--last" else None
        grid_sup(int(argv[2]), argv[3], last)
    elif kind == "transfer-line":
        transfer_line(int(argv[2]), argv[3])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)

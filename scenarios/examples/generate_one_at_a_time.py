#!/usr/bin/env python3
"""Writes one-at-a-time.fsm: the supervisor of scenarios/examples/three-robots.json.

Robots A, B, C (event prefixes a, b, c); tasks 1..3. rXs starts task X (controllable), rXf
finishes it (uncontrollable: the robot enters the 1 m square around the task). Each task is
done once, by any robot, and at most one robot works at a time: a task may start only when no
task is in progress. State names list the tasks' status in order: '.' free, 'x' done, or the
letter (A, B, C) of the robot working on it. Marked: every task done.
The .fsm is committed; run `python3 scenarios/examples/generate_one_at_a_time.py` to rebuild it.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
ROBOTS = "abc"
TASKS = 3


def name(status):
    return "s" + "".join(status)


def main():
    start = (".",) * TASKS
    states, order, queue = {}, [], [start]
    seen = {start}
    while queue:
        s = queue.pop(0)
        order.append(s)
        trans = []
        busy = any(v not in ".x" for v in s)
        for t in range(TASKS):
            for r in ROBOTS:
                nxt = None
                if s[t] == r.upper():
                    nxt, e, c = s[:t] + ("x",) + s[t + 1:], f"{r}{t + 1}f", "uc"
                elif not busy and s[t] == ".":
                    nxt, e, c = s[:t] + (r.upper(),) + s[t + 1:], f"{r}{t + 1}s", "c"
                if nxt is None:
                    continue
                trans.append((e, name(nxt), c))
                if nxt not in seen:
                    seen.add(nxt)
                    queue.append(nxt)
        states[s] = (all(v == "x" for v in s), sorted(trans))
    lines = [str(len(order)), ""]
    for s in order:
        marked, trans = states[s]
        lines.append(f"{name(s)}\t{1 if marked else 0}\t{len(trans)}")
        lines += [f"{e}\t{t}\t{c}\to" for e, t, c in trans]
        lines.append("")
    with open(os.path.join(HERE, "one-at-a-time.fsm"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()

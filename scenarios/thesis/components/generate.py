#!/usr/bin/env python3
"""Writes the component automata of the UDM thesis's chapter 2 as UMDES .fsm files.

The thesis's figures 2-2 .. 2-6 are pictures that did not survive in the text; what the text
says is kept, and every choice made where it is silent is marked CHOICE (docs/supervisor.md lists
them). Run from anywhere: `python3 scenarios/thesis/components/generate.py`; the .fsm files are
committed, so nothing runs this at build or test time.

Robots A (events a..) and B (b..); regions 5..8 are the quadrants (5 = x<0,y<0, 6 = x<0,y>0,
7 = x>0,y>0, 8 = x>0,y<0); tasks 1..4 lie in regions 5, 7, 6, 6 (thesis Table 4-1).
Events: rXs start task X (controllable), rXf finish task X (uncontrollable, the robot reached
the task), rNe robot enters region N (uncontrollable).
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
ROBOTS = {"a": 5, "b": 8}                 # robot prefix -> start region (Figure 2-1)
TASK_REGION = {1: 5, 2: 7, 3: 6, 4: 6}   # Table 4-1: tsk1 (-2,-5) .. tsk4 (-13,8)
ADJACENT = {5: (6, 8), 6: (5, 7), 7: (6, 8), 8: (5, 7)}   # Figure 2-2: no diagonal moves
# CHOICE: a robot crossing diagonally goes round by its own side of the map: A (starting west)
# through the west regions 5/6, B (starting east) through 7/8. This is what control2.fsm does
# (A reaches task 2 from region 5 by 6, B by 8).
VIA = {"a": {(5, 7): 6, (7, 5): 6, (6, 8): 5, (8, 6): 5},
       "b": {(5, 7): 8, (7, 5): 8, (6, 8): 7, (8, 6): 7}}


def write(name, states, initial, alphabet=()):
    """states: {name: (marked, [(event, target, 'c'|'uc')])}; initial first, rest sorted.
    alphabet: (event, 'c'|'uc') the automaton has even where no transition uses them (listed
    in the EVENTS section): an event of the alphabet is one the automaton can forbid."""
    order = [initial] + sorted(s for s in states if s != initial)
    lines = [str(len(order)), ""]
    for s in order:
        marked, trans = states[s]
        lines.append(f"{s}\t{1 if marked else 0}\t{len(trans)}")
        for e, t, c in sorted(trans):
            lines.append(f"{e}\t{t}\t{c}\to")
        lines.append("")
    used = {e for s in order for e, _, _ in states[s][1]}
    extra = sorted((e, c) for e, c in alphabet if e not in used)
    if extra:
        lines.append("EVENTS")
        lines += [f"{e}\t{c}\to" for e, c in extra]
        lines.append("")
    with open(os.path.join(HERE, name), "w") as f:
        f.write("\n".join(lines))


def reachable(initial, step):
    """Breadth-first closure of step(state) -> [(event, target, c)] from initial."""
    states, todo = {}, [initial]
    while todo:
        s = todo.pop()
        if s in states:
            continue
        states[s] = step(s)
        todo.extend(t for _, t, _ in states[s][1])
    return states


def region_fsm(r):
    """Figure 2-2: the robot's region. 'out' until its start region is first detected."""
    def step(s):
        if s == "out":
            return (False, [(f"{r}{ROBOTS[r]}e", f"R{ROBOTS[r]}", "uc")])
        here = int(s[1:])
        return (True, [(f"{r}{n}e", f"R{n}", "uc") for n in ADJACENT[here]])
    write(f"region_{r}.fsm", reachable("out", step), "out")


def route(r, src, dst):
    """The regions entered going from region src to region dst (CHOICE: shortest, see VIA)."""
    if src == dst:
        return []
    if dst in ADJACENT[src]:
        return [dst]
    return [VIA[r][(src, dst)], dst]


def task_fsm(r):
    """Figure 2-3: one task at a time, started (c) then finished (uc) once the robot is in the
    task's region. CHOICE: an idle robot does not move, and a robot on its way enters exactly
    the regions of its route (the region-entry events confine the task to its region);
    without that, uncontrollable wandering into the other robot's region could not be
    prevented and the supervisor would be empty."""
    home = ROBOTS[r]

    def region_of(loc):
        return home if loc == "home" else TASK_REGION[int(loc[1:])]

    def step(s):
        if s == "start":
            return (False, [(f"{r}{home}e", "idle_home", "uc")])
        if s.startswith("idle_"):
            loc = s[5:]
            return (True, [(f"{r}{x}s", f"go{x}_{loc}_0", "c") for x in TASK_REGION])
        x, loc, k = s[2:].split("_")
        x, k = int(x), int(k)
        path = route(r, region_of(loc), TASK_REGION[x])
        if k < len(path):
            return (False, [(f"{r}{path[k]}e", f"go{x}_{loc}_{k + 1}", "uc")])
        return (False, [(f"{r}{x}f", f"idle_t{x}", "uc")])
    # Every region entry of this robot is in the alphabet, so entries off the route are forbidden.
    write(f"tasks_{r}.fsm", reachable("start", step), "start",
          [(f"{r}{n}e", "uc") for n in range(5, 9)])


def avoidance_fsm():
    """Figure 2-5: the robots are never in the same region. State 'A.B' = their regions
    (0 before the first detection); an entry into the other robot's region is disabled."""
    def step(s):
        ra, rb = map(int, s.split("_"))
        out = [(f"a{n}e", f"{n}_{rb}", "uc") for n in range(5, 9) if n != rb]
        out += [(f"b{n}e", f"{ra}_{n}", "uc") for n in range(5, 9) if n != ra]
        return (True, out)
    write("avoidance.fsm", reachable("0_0", step), "0_0")


def located_fsm():
    """CHOICE (thesis 3.3.1: the controller first reads both robots' starting regions, then
    commands them): no task starts before both robots have been detected in their start
    regions. Only the two first detections and the task starts are in its alphabet."""
    first = {r: f"{r}{ROBOTS[r]}e" for r in ROBOTS}
    starts = [f"{r}{x}s" for r in ROBOTS for x in TASK_REGION]
    states = {
        "none": (False, [(first["a"], "a", "uc"), (first["b"], "b", "uc")]),
        "a": (False, [(first["b"], "both", "uc")]),
        "b": (False, [(first["a"], "both", "uc")]),
        "both": (True, [(e, "both", "c") for e in starts] +
                 [(first[r], "both", "uc") for r in ROBOTS]),
    }
    write("located.fsm", states, "none")


def completion_fsm(other_robot=True):
    """Figure 2-6: tasks 1 then 2 by one robot, 3 then 4 by the other robot, each once.
    State per pair: '-' or robot + stage (1 first started, 2 first finished, 3 second started,
    4 done). CHOICE: 'the other robot' is enforced (the thesis text says so; control2.fsm lets
    robot A do all four tasks). Marked when both pairs are done."""
    pairs = [(1, 2), (3, 4)]

    def step(s):
        stages = s.split("_")
        out = []
        for i, (first, second) in enumerate(pairs):
            other = stages[1 - i]
            st = stages[i]
            nxt = list(stages)
            if st == "-":
                for r in ROBOTS:
                    if other == "-" or other[0] != r or not other_robot:
                        nxt[i] = f"{r}1"
                        out.append((f"{r}{first}s", "_".join(nxt), "c"))
                continue
            r, k = st[0], int(st[1])
            if k == 4:
                continue
            event = {1: f"{r}{first}f", 2: f"{r}{second}s", 3: f"{r}{second}f"}[k]
            nxt[i] = f"{r}{k + 1}"
            out.append((event, "_".join(nxt), "c" if k == 2 else "uc"))
        return (all(x.endswith("4") for x in stages), out)
    name = "completion.fsm" if other_robot else "completion_any_robot.fsm"
    write(name, reachable("-_-", step), "-_-")


if __name__ == "__main__":
    for r in ROBOTS:
        region_fsm(r)
        task_fsm(r)
    avoidance_fsm()
    located_fsm()
    completion_fsm()
    # The reading control2.fsm follows: a robot may also do both pairs (A does all four).
    completion_fsm(other_robot=False)

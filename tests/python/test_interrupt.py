"""Ctrl-C (SIGINT to the interpreter) stops a long run() or step(n) with KeyboardInterrupt."""
import os
import signal
import subprocess
import sys
import time

import pytest

# A run that would take minutes: map 1500 (2.25 million cells), two robots, never stalling.
SCRIPT = r"""
import sys, swarmcheck
big = {"map_size": 1500, "robots": [[0.5, 0.5], [1.5, 0.5]], "mode": "abstract", "max_steps": 2000000000}
sim = swarmcheck.Simulation(big, paths=False)
print("ready", flush=True)
try:
    if sys.argv[1] == "run":
        swarmcheck.run(big, stall_window=0)
    else:
        sim.step(10**9)
    print("not interrupted", flush=True)
except KeyboardInterrupt:
    before = sim.steps
    sim.step(3)   # the simulation is whole: it steps on
    print("interrupted", sim.steps - before, flush=True)
"""


@pytest.mark.parametrize("call", ["run", "step"])
def test_sigint_raises_keyboard_interrupt_in_a_long_call(call):
    p = subprocess.Popen([sys.executable, "-c", SCRIPT, call], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, env=os.environ.copy())
    try:
        assert p.stdout.readline().strip() == "ready"
        time.sleep(1.0)   # inside the call
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
    finally:
        p.kill()
    assert p.returncode == 0, err
    assert out.strip() == "interrupted 3"


# A synthesis whose plant is the product of four cycles of 60 states with events of their own:
# 13 million states to build, minutes; Ctrl-C stops it at its next budget check.
SYNTH_SCRIPT = r"""
import swarmcheck
def cycle(n, e):
    text = [str(n), ""]
    for k in range(n):
        text += [f"q{k} {int(k == 0)} 1", f"{e} q{(k + 1) % n} c o", ""]
    return swarmcheck.Automaton.parse("\n".join(text), e)
parts = [cycle(60, f"e{i}") for i in range(4)]
print("ready", flush=True)
try:
    swarmcheck.synthesize(parts, parts[0])
    print("not interrupted", flush=True)
except KeyboardInterrupt:
    print("interrupted", len(swarmcheck.product(parts[:2])), flush=True)   # the library works on
"""


def test_sigint_raises_keyboard_interrupt_in_a_long_synthesis():
    p = subprocess.Popen([sys.executable, "-c", SYNTH_SCRIPT], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, env=os.environ.copy())
    try:
        assert p.stdout.readline().strip() == "ready"
        time.sleep(1.0)
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
    finally:
        p.kill()
    assert p.returncode == 0, err
    assert out.strip() == "interrupted 3600"

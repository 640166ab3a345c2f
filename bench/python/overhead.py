#!/usr/bin/env python3
"""What Python adds to the library (issue 37's targets: run() within 5 % of the C++ library, a
Python loop of step(1) at most 2 us a step over the library's step). Both sides run in this one
process on the same scenario, alternately, and the medians are compared:

  library: _swarmcheck._library_run_seconds / _library_step_seconds, the C++ loop alone
  Python:  swarmcheck.run(...) timed around the call; `for _ in range(n): sim.step()`

    PYTHONPATH=build/python /usr/bin/python3 bench/python/overhead.py [--repeats 7]
"""
import argparse
import statistics
import time

import swarmcheck
from swarmcheck import _swarmcheck

# run(): a map of 256 x 256 with 64 robots, abstract mode, to completion (about 9 500 steps,
# 70 ms), one thread. The scenario is validated once (a Scenario) and handed to both sides.
RUN_SCENARIO = {"map_size": 256, "robots": [[2.5 + 32 * (k % 8), 2.5 + 32 * (k // 8)] for k in range(64)],
                "mode": "abstract", "max_steps": 50000}
# step(1): four robots at the corners of a 300 x 300 map (no run completes within the steps),
# cosim and abstract, one thread.
STEPS = 20000
STEP_SCENARIO = {"map_size": 300, "robots": [[0.5, 0.5], [299.5, 0.5], [299.5, 299.5], [0.5, 299.5]],
                 "max_steps": STEPS}


def median_run(repeats):
    lib, py = [], []
    scenario = swarmcheck.Scenario(RUN_SCENARIO)
    for _ in range(repeats):
        seconds, steps = _swarmcheck._library_run_seconds(scenario, stall_window=0, threads=1)
        lib.append(seconds)
        t0 = time.perf_counter()
        summary = swarmcheck.run(scenario, stall_window=0, threads=1)
        py.append(time.perf_counter() - t0)
        assert summary["steps"] == steps
    return statistics.median(lib), statistics.median(py), steps


def median_step(repeats, mode, paths):
    lib, py = [], []
    for _ in range(repeats):
        seconds, steps = _swarmcheck._library_step_seconds(STEP_SCENARIO, n=STEPS, threads=1, mode=mode)
        lib.append(seconds / steps)
        sim = swarmcheck.Simulation(STEP_SCENARIO, threads=1, paths=paths, mode=mode)
        step = sim.step
        t0 = time.perf_counter()
        for _ in range(STEPS):
            step()
        py.append((time.perf_counter() - t0) / STEPS)
        assert sim.steps == steps == STEPS
    return statistics.median(lib), statistics.median(py)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    lib, py, steps = median_run(args.repeats)
    print(f"run(), map 256, 64 robots, abstract, {steps} steps, 1 thread: library {lib * 1e3:.1f} ms, "
          f"Python {py * 1e3:.1f} ms, ratio {py / lib:.3f} (target <= 1.05)")
    for mode in ("abstract", "cosim"):
        for paths in (False, True):
            lib, py = median_step(args.repeats, mode, paths)
            print(f"step(1) loop, map 300, 4 robots, {mode}, paths={paths}, {STEPS} steps, 1 thread: library "
                  f"{lib * 1e6:.3f} us/step, Python {py * 1e6:.3f} us/step, over {(py - lib) * 1e6:.3f} us "
                  f"(target <= 2)")


if __name__ == "__main__":
    main()

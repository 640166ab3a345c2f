#!/usr/bin/env python3
"""Sweep the pheromone evaporation rate `ertu` from Python (the eight values of the thesis's DSE,
scenarios/thesis/dse/ertu.dse.json, on its base scenario), plot eP against simulated time with
matplotlib when it is installed (Debian python3-matplotlib), and check the supervisor of the
thesis mission: synthesised from its components, compared with the thesis's control2.fsm.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_ertu.py [--plot ertu.png]
"""
import argparse
import json
import os
import sys

import numpy as np

import swarmcheck

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
THESIS = os.path.join(ROOT, "scenarios", "thesis")


def sweep(values):
    """{ertu: (sTime array, eP array, the run's summary)} over the base scenario."""
    with open(os.path.join(THESIS, "dse", "base.json"), encoding="utf-8") as f:
        base = json.load(f)
    curves = {}
    for ertu in values:
        base["params"]["ertu"] = ertu
        sim = swarmcheck.Simulation(base)
        times, eps = [sim.sTime], [sim.eP]
        while not sim.done:
            sim.step()
            times.append(sim.sTime)
            eps.append(sim.eP)
        curves[ertu] = (np.array(times), np.array(eps), swarmcheck.run(base))
    return curves


def check_thesis_supervisor():
    components = os.path.join(THESIS, "components")
    plants = [os.path.join(components, f"{n}.fsm") for n in ("region_a", "region_b", "tasks_a", "tasks_b")]
    specs = [os.path.join(components, f"{n}.fsm") for n in ("avoidance", "completion")]
    automata = swarmcheck.read_fsm_files(plants + specs + [os.path.join(THESIS, "control2.fsm")])
    plant, spec, control2 = automata[:4], automata[4:6], automata[6]
    sup = swarmcheck.synthesize(plant, spec)
    print(f"synthesised supervisor: {len(sup)} states, nonblocking: {sup.check()['nonblocking']}")
    report = swarmcheck.control_report(plant, control2)
    print(f"thesis control2.fsm: {len(control2)} states, controllable: {report['controllable']}"
          + ("" if report["controllable"] else
             f" (after {' '.join(report['witness'])}, {report['disabled_event']} is disabled)"))
    same = swarmcheck.compare(sup, control2)
    print(f"L(synthesised) in L(control2): {same['a_in_b']['closed']}, "
          f"L(control2) in L(synthesised): {same['b_in_a']['closed']}")
    return sup


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", default="ertu.png", help="the picture to write (with matplotlib)")
    args = parser.parse_args()
    with open(os.path.join(THESIS, "dse", "ertu.dse.json"), encoding="utf-8") as f:
        values = next(iter(json.load(f)["parameters"].values()))
    curves = sweep(values)
    print(f"{'ertu':>6} {'eP %':>7} {'sTime s':>8} {'outcome':>10}")
    for ertu, (_, _, summary) in curves.items():
        print(f"{ertu:>6} {summary['eP']:>7.2f} {summary['sTime']:>8.1f} {summary['outcome']:>10}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (apt-get install python3-matplotlib): no plot", file=sys.stderr)
    else:
        fig, ax = plt.subplots(figsize=(7, 4))
        for ertu, (t, ep, _) in curves.items():
            ax.plot(t, ep, label=f"ertu {ertu}")
        ax.set_xlabel("simulated time (s)")
        ax.set_ylabel("eP (%)")
        ax.legend(fontsize="small")
        fig.savefig(args.plot, dpi=100, bbox_inches="tight")
        print(f"wrote {args.plot}")
    check_thesis_supervisor()


if __name__ == "__main__":
    main()

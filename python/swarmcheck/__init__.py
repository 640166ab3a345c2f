"""swarmcheck: the multi-robot exploration library and its supervisor automata, for Python.

The compiled part (_swarmcheck, pybind11) is the C++ library itself, in this process:

    import swarmcheck
    summary = swarmcheck.run(rule="deterministic", mode="abstract", steps=2000)   # = run --json
    sim = swarmcheck.Simulation("scenarios/examples/walls.json", mode="abstract")
    while not sim.done:
        sim.step(100)
    field = sim.field               # read-only NumPy view of the pheromone field
    sup = swarmcheck.synthesize([swarmcheck.Automaton.read("P.fsm")], [swarmcheck.Automaton.read("S.fsm")])

Bad input raises swarmcheck.InputError (a ValueError) with the command line's message; Ctrl-C
stops a long run (KeyboardInterrupt). See README.md, section "Python".
"""
from __future__ import annotations

import base64
import json
import os
from typing import Any, Dict, List

import numpy as np

from ._swarmcheck import (  # noqa: F401  (the public names of the package)
    BODIES,
    CONTROLLERS,
    MODES,
    OBLIGATIONS,
    PRESETS,
    RULES,
    Automaton,
    InputError,
    Scenario,
    Simulation,
    compare,
    control_report,
    dse,
    is_controllable,
    language_inclusion,
    mission_plan,
    mission_run,
    observability,
    product,
    prove,
    read_fsm_files,
    run,
    supcon,
    supcon_normal,
    synthesize,
)

__all__ = [
    "BODIES", "CONTROLLERS", "MODES", "OBLIGATIONS", "PRESETS", "RULES",
    "Automaton", "InputError", "Scenario", "Simulation", "Trace",
    "compare", "control_report", "dse", "is_controllable", "language_inclusion", "mission_plan", "mission_run",
    "observability",
    "pheromone_digest", "product", "prove", "read_fsm_files", "read_trace", "run", "supcon",
    "supcon_normal", "synthesize",
]


class Trace:
    """A JSON Lines trace of `swarmcheck run --trace FILE` read into NumPy arrays.

    header: the header record (dict); records: the step records (dicts); step, eP, sTime,
    visited, planning_steps: one entry a step record (NumPy arrays); fields: {step: (pheromone
    float32 array (N, N), visited bool array (N, N), digest)} from the field records of
    `--trace-field K`.
    """

    def __init__(self, header: Dict[str, Any], records: List[Dict[str, Any]],
                 fields: Dict[int, tuple]) -> None:
        self.header = header
        self.records = records
        self.fields = fields
        self.step = np.array([r["step"] for r in records], dtype=np.int64)
        self.planning_steps = np.array([r["planning_steps"] for r in records], dtype=np.int64)
        self.visited = np.array([r["visited"] for r in records], dtype=np.int64)
        self.eP = np.array([r["eP"] for r in records], dtype=np.float64)
        self.sTime = np.array([r["sTime"] for r in records], dtype=np.float64)

    def __len__(self) -> int:
        return len(self.records)

    def __repr__(self) -> str:
        return f"<swarmcheck.Trace: {len(self.records)} step records, {len(self.fields)} field records>"

    def _repr_html_(self) -> str:
        """A notebook's table: the run's set-up from the header, then eP and sTime every tenth of the run."""
        import html
        rows = "".join(f"<tr><th>{html.escape(str(k))}</th><td>{html.escape(str(v))}</td></tr>"
                       for k, v in self.header.items() if not isinstance(v, (dict, list)))
        picks = sorted({int(round(k * (len(self.records) - 1) / 10)) for k in range(11)}) if self.records else []
        steps = "".join(f"<tr><td>{self.step[i]}</td><td>{self.eP[i]:.2f}</td><td>{self.sTime[i]:.1f}</td>"
                        f"<td>{self.visited[i]}</td></tr>" for i in picks)
        return (f"<table>{rows}</table><table><tr><th>step</th><th>eP %</th><th>sTime s</th>"
                f"<th>visited</th></tr>{steps}</table>")


def _decode_field(rec: Dict[str, Any], where: str) -> tuple:
    if rec.get("encoding") != "float32-le-base64":
        raise InputError(f"{where}: encoding: expected \"float32-le-base64\"")
    n = int(rec["map_size"])
    pheromone = np.frombuffer(base64.b64decode(rec["pheromone"]), dtype="<f4")
    bits = np.frombuffer(base64.b64decode(rec["visited"]), dtype=np.uint8)
    if pheromone.size != n * n or bits.size != (n * n + 7) // 8:
        raise InputError(f"{where}: expected {n * n} cells in \"pheromone\" and \"visited\"")
    visited = np.unpackbits(bits, bitorder="little")[: n * n].astype(bool)
    return pheromone.reshape(n, n), visited.reshape(n, n), int(rec["digest"])


def read_trace(path: "os.PathLike[str] | str") -> Trace:
    """Read a trace (`swarmcheck run --trace FILE [--trace-field K]`) into a Trace."""
    path = os.fspath(path)
    header: Dict[str, Any] = {}
    records: List[Dict[str, Any]] = []
    fields: Dict[int, tuple] = {}
    with open(path, encoding="utf-8") as f:
        for line_number, line in enumerate(f, 1):
            where = f"{path}:{line_number}"
            try:
                rec = json.loads(line)
            except json.JSONDecodeError as e:
                raise InputError(f"{where}: expected one JSON object a line ({e.msg})") from None
            if line_number == 1:
                header = rec
            elif rec.get("type") == "field":
                fields[int(rec["step"])] = _decode_field(rec, where)
            else:
                records.append(rec)
    return Trace(header, records, fields)


def pheromone_digest(field: np.ndarray) -> int:
    """FNV-1a (64-bit) over the bits of every cell's value in raster order: the trace's
    pheromone_digest, for comparing a field with a trace exactly."""
    h = 0xCBF29CE484222325
    for byte in np.ascontiguousarray(field, dtype="<f8").tobytes():
        h ^= byte
        h = (h * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h

"""Type stubs of swarmcheck's compiled extension (python/src/*.cpp); the docstrings are the
extension's own (help(swarmcheck.Simulation))."""
import os
from typing import Any, Dict, List, Optional, Sequence, Set, Tuple, Union

import numpy as np
import numpy.typing as npt

PathLike = Union[str, "os.PathLike[str]"]
ScenarioSource = Union[None, "Scenario", Dict[str, Any], PathLike]

RULES: Tuple[str, ...]
"""The rule sets (`run --rule`)."""
CONTROLLERS: Tuple[str, ...]
"""The robots' controllers (`--controller`)."""
BODIES: Tuple[str, ...]
"""The robots' bodies (`--body`)."""
PRESETS: Tuple[str, ...]
"""The named systems (`--preset`)."""
MODES: Tuple[str, ...]
"""abstract and cosim (`--mode`)."""
OBLIGATIONS: Tuple[str, ...]
"""The names of the Z3 proof obligations (`prove --only`)."""

class InputError(ValueError):
    """Bad input: the command line's message (file:line:column or a JSON path, then what was expected)."""

class Scenario:
    """An exploration scenario, validated by swarmcheck's reader (the CLI's messages)."""
    def __init__(self, source: ScenarioSource = None, *, mode: Optional[str] = ..., rule: Optional[str] = ...,
                 preset: Optional[str] = ..., controller: Optional[str] = ..., body: Optional[str] = ...,
                 seed: Optional[int] = ..., steps: Optional[int] = ...) -> None: ...
    @staticmethod
    def from_file(path: PathLike) -> "Scenario":
        """A scenario file (JSON), read and validated as `swarmcheck run FILE` does."""
    @staticmethod
    def from_dict(d: Dict[str, Any]) -> "Scenario":
        """A scenario from a dict with the keys of a scenario file."""
    def replace(self, **keywords: Any) -> "Scenario":
        """A copy with the keywords (mode, rule, preset, controller, body, seed, steps) applied."""
    def to_dict(self) -> Dict[str, Any]:
        """The scenario as a dict (every key, defaults included)."""
    @property
    def name(self) -> str:
        """Where it came from: 'default scenario', the file's path, or 'dict'."""
    @property
    def map_size(self) -> int:
        """Cells per side."""
    @property
    def robots(self) -> int:
        """Number of robots."""
    @property
    def rule(self) -> str:
        """The rule set."""
    @property
    def mode(self) -> str:
        """abstract or cosim."""
    @property
    def seed(self) -> int:
        """The run's one seed."""
    @property
    def max_steps(self) -> int:
        """Master steps at most."""

class Simulation:
    """One exploration run of the library, stepped from Python."""
    def __init__(self, scenario: ScenarioSource = None, *, threads: int = 0, paths: bool = True,
                 memory_limit: Optional[int] = None, **keywords: Any) -> None: ...
    def step(self, n: int = 1) -> None:
        """Do n master steps (fewer if the run is done first); Ctrl-C raises KeyboardInterrupt."""
    def run(self, stall_window: int = 100000) -> Dict[str, Any]:
        """Step to the end as `swarmcheck run` does; the dict `swarmcheck run --json` prints."""
    @property
    def done(self) -> bool:
        """Completed (eP 100 %) or max_steps done."""
    @property
    def steps(self) -> int:
        """Master steps done."""
    @property
    def planning_steps(self) -> int:
        """Steps in which the Environment chose new cells."""
    @property
    def visited(self) -> int:
        """Visited free cells."""
    @property
    def free_cells(self) -> int:
        """Free cells of the map."""
    @property
    def eP(self) -> float:
        """Exploration percentage."""
    @property
    def sTime(self) -> float:
        """Simulated time, s."""
    @property
    def completion_step(self) -> Optional[int]:
        """The step eP reached 100 %, or None."""
    @property
    def scenario(self) -> Scenario:
        """The Scenario it runs."""
    def state(self) -> Dict[str, Any]:
        """The observable state, as one record of the JSON Lines trace (robots' cells, waypoints, poses, controllers)."""
    @property
    def cells(self) -> npt.NDArray[np.int32]:
        """The cell each robot was last moved to, (robots, 2) [i, j] (a copy)."""
    @property
    def waypoints(self) -> npt.NDArray[np.float64]:
        """The waypoint each robot issued, (robots, 2) metres (a copy)."""
    @property
    def poses(self) -> npt.NDArray[np.float64]:
        """Each robot's pose, (robots, 3) x_m, y_m, theta_rad (a copy)."""
    @property
    def field(self) -> npt.NDArray[np.float64]:
        """The pheromone field, (map_size, map_size): a read-only view of the simulation's buffer (no copy)."""
    @property
    def visited_cells(self) -> npt.NDArray[np.bool_]:
        """Which cells are visited, (map_size, map_size) (a copy)."""
    def svg(self) -> str:
        """The picture of `swarmcheck run --svg` at the current step."""
    def _repr_svg_(self) -> str: ...

def run(scenario: ScenarioSource = None, *, stall_window: int = 100000, threads: int = 0,
        memory_limit: Optional[int] = None, mode: Optional[str] = ..., rule: Optional[str] = ..., preset: Optional[str] = ...,
        controller: Optional[str] = ..., body: Optional[str] = ..., seed: Optional[int] = ...,
        steps: Optional[int] = ...) -> Dict[str, Any]:
    """One exploration run: the dict `swarmcheck run --json` prints, computed in this process."""

def _library_run_seconds(scenario: ScenarioSource = None, *, stall_window: int = 100000, threads: int = 0,
                         **keywords: Any) -> Tuple[float, int]:
    """(seconds, steps) of one run through the C++ library alone (overhead figures)."""

def _library_step_seconds(scenario: ScenarioSource = None, *, n: int = 1000, threads: int = 0,
                          **keywords: Any) -> Tuple[float, int]:
    """(seconds, steps) of n library steps in a C++ loop (overhead figures)."""

class Automaton:
    """A deterministic automaton of the UMDES .fsm format (a plain value); states[0] is initial."""
    def __init__(self) -> None: ...
    @staticmethod
    def read(path: PathLike) -> "Automaton":
        """Read a .fsm file."""
    @staticmethod
    def parse(text: str, source: str = "<text>") -> "Automaton":
        """Read .fsm text; `source` names it in messages."""
    def write(self, path: PathLike) -> None:
        """Write as .fsm, whole or not at all."""
    def to_fsm(self) -> str:
        """The .fsm text."""
    def to_dot(self) -> str:
        """Graphviz DOT."""
    def to_dict(self) -> Dict[str, Any]:
        """The JSON of `swarmcheck fsm export --to json`."""
    def svg(self) -> str:
        """The picture of `swarmcheck fsm export --to svg`."""
    def _repr_svg_(self) -> Optional[str]: ...
    @property
    def states(self) -> List[str]:
        """State names; states[0] is initial."""
    @property
    def initial(self) -> Optional[str]:
        """The initial state, or None for the empty automaton."""
    @property
    def marked(self) -> Set[str]:
        """The marked states."""
    @property
    def events(self) -> Dict[str, Dict[str, bool]]:
        """{event: {'controllable': bool, 'observable': bool}}."""
    @property
    def transitions(self) -> List[Tuple[str, str, str]]:
        """[(state, event, next state)]."""
    def check(self) -> Dict[str, Any]:
        """What `swarmcheck fsm check --json` prints (without 'file')."""
    def trim(self) -> "Automaton":
        """The accessible and coaccessible part."""
    def accessible_part(self) -> "Automaton":
        """The accessible part."""
    def observer(self) -> "Automaton":
        """The observer (`fsm project`)."""
    def __len__(self) -> int: ...

AutomatonOrList = Union[Automaton, Sequence[Automaton]]

def read_fsm_files(paths: Sequence[str]) -> List[Automaton]:
    """Read the .fsm files of one command together (attributes shared across files)."""
def product(automata: Sequence[Automaton], names: Sequence[str] = ...) -> Automaton:
    """The synchronous product (accessible part), as `swarmcheck fsm product`."""
def supcon(plant: AutomatonOrList, spec: AutomatonOrList) -> Automaton:
    """The supremal controllable nonblocking supervisor."""
def supcon_normal(plant: AutomatonOrList, spec: AutomatonOrList) -> Automaton:
    """The supremal controllable, normal and nonblocking supervisor."""
def synthesize(plant: AutomatonOrList, spec: AutomatonOrList) -> Automaton:
    """`swarmcheck fsm synth`: supcon, or supcon_normal when an event is uo."""
def is_controllable(plant: AutomatonOrList, spec: AutomatonOrList) -> bool:
    """Is spec controllable with respect to plant?"""
def control_report(plant: AutomatonOrList, sup: AutomatonOrList) -> Dict[str, Any]:
    """`swarmcheck fsm controllable --json` (without the files), witnesses as lists of events."""
def observability(plant: AutomatonOrList, spec: AutomatonOrList) -> Dict[str, Any]:
    """`swarmcheck fsm observable --json` (without the files)."""
def language_inclusion(a: Automaton, b: Automaton) -> Dict[str, Any]:
    """L(a) in L(b) and Lm(a) in Lm(b), with shortlex-least witnesses."""
def compare(a: Automaton, b: Automaton) -> Dict[str, Any]:
    """`swarmcheck fsm compare --json` (without the files)."""

def mission_plan(mission: PathLike, from_state: Optional[str] = None) -> Dict[str, Any]:
    """`swarmcheck mission plan MISSION --json` (the exact planner)."""
def mission_run(mission: PathLike, *, body: str = "unicycle", dt: float = 0.05, max_time: float = 3600.0,
                speed: float = 0.5, seed: int = 1, trace: Optional[PathLike] = None,
                records: bool = False) -> Dict[str, Any]:
    """`swarmcheck mission run MISSION --json`; records=True adds "event_records" (one dict an event)."""

def dse(config: PathLike, scenario: ScenarioSource = None, *, threads: int = 0, journal: Optional[PathLike] = None,
        preset: Optional[str] = ..., controller: Optional[str] = ..., body: Optional[str] = ...) -> Dict[str, Any]:
    """`swarmcheck dse CONFIG --json`: the results object, its "points" one record a design point."""

def prove(only: Optional[str] = None, timeout: float = 120.0) -> Dict[str, Any]:
    """`swarmcheck prove --json`: every Z3 obligation, or the one named `only`, each in a forked prover."""

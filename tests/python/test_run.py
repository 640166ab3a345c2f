"""swarmcheck.run() returns the dict `swarmcheck run --json` prints, computed in process."""
import json
import os

import pytest

import swarmcheck

# Enough steps for every rule set to plan, move and deposit many times (the default scenario is
# the thesis's map 10 with four robots), few enough for seconds.
STEPS = {"abstract": 300, "cosim": 1500}


@pytest.mark.parametrize("mode", swarmcheck.MODES)
@pytest.mark.parametrize("rule", swarmcheck.RULES)
def test_run_equals_cli_json_for_every_rule_set_and_mode(cli_json, rule, mode):
    expected = cli_json("run", "--rule", rule, "--mode", mode, "--steps", STEPS[mode], "--threads", 2)
    got = swarmcheck.run(rule=rule, mode=mode, steps=STEPS[mode], threads=2)
    assert got == expected
    assert list(got) == list(expected)   # the keys in the CLI's order too


def test_run_to_completion_equals_cli_json(cli_json):
    expected = cli_json("run", "--mode", "abstract", "--seed", 7)
    got = swarmcheck.run(mode="abstract", seed=7)
    assert got["completed"] and got["outcome"] == "completed"
    assert got == expected


def test_run_with_preset_controller_and_body_equals_cli_json(cli_json):
    expected = cli_json("run", "--preset", "thesis", "--body", "kinematic", "--steps", 400)
    got = swarmcheck.run(preset="thesis", body="kinematic", steps=400)
    assert (got["rule"], got["controller"], got["body"]) == ("thesis", "thesis", "kinematic")
    assert got == expected


def walled_in_scenario():
    """Map 8, one robot, a wall of obstacles across row 3: the cells beyond it are unreachable."""
    return {"map_size": 8, "robots": [[0.5, 0.5]], "obstacles": [[3, j] for j in range(8)],
            "mode": "abstract", "max_steps": 5000}


def test_stalled_run_equals_cli_json_from_a_file_and_from_a_dict(cli_json, tmp_path):
    path = tmp_path / "walled.json"
    path.write_text(json.dumps(walled_in_scenario()))
    expected = cli_json("run", path)
    assert expected["outcome"] == "stalled" and expected["unreachable_cells"] == 32
    assert swarmcheck.run(path) == expected
    assert swarmcheck.run(str(path)) == expected
    assert swarmcheck.run(walled_in_scenario()) == expected


def test_stall_window_equals_cli_json(cli_json):
    expected = cli_json("run", "--mode", "abstract", "--rule", "deterministic", "--stall-window", 3, "--steps", 5000)
    got = swarmcheck.run(mode="abstract", rule="deterministic", stall_window=3, steps=5000)
    assert got == expected


def test_simulation_run_equals_module_run():
    sim = swarmcheck.Simulation(mode="abstract", steps=200)
    assert sim.run() == swarmcheck.run(mode="abstract", steps=200)
    assert sim.done and sim.steps == 200


def test_the_same_scenario_object_runs_the_same(cli_json, source_dir):
    s = swarmcheck.Scenario(os.path.join(source_dir, "scenarios", "default.json"), mode="abstract", steps=250)
    assert swarmcheck.run(s) == cli_json("run", os.path.join(source_dir, "scenarios", "default.json"),
                                         "--mode", "abstract", "--steps", 250)


@pytest.mark.parametrize("preset", [None, "thesis"])
def test_scenario_to_dict_round_trips_and_runs_the_same(preset):
    s = swarmcheck.Scenario(mode="cosim", preset=preset, seed=5)
    d = s.to_dict()
    again = swarmcheck.Scenario(d)
    assert again.to_dict() == d
    assert swarmcheck.run(again, steps=120) == swarmcheck.run(s, steps=120)
    assert s.replace(rule="stochastic").rule == "stochastic" and s.rule == (preset and "thesis" or "deterministic")

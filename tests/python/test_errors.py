"""Bad input raises swarmcheck.InputError (a ValueError) with the CLI's message; never a crash."""
import json

import pytest

import swarmcheck


def cli_message(cli, *args):
    code, out, err = cli(*args)
    assert code == 2 and out == ""
    assert err.startswith("swarmcheck: error: ")
    return err[len("swarmcheck: error: "):].rstrip("\n")


BAD_SCENARIOS = [
    {"map_size": 0, "robots": [[0.5, 0.5]]},                           # map_size out of range
    {"map_size": 10, "robots": [[0.5, 0.5]], "rule": "nope"},          # an enum
    {"map_size": 10, "robots": [[0.5, 0.5], [0.5, 0.5]]},              # two robots in one cell
    {"map_size": 10, "robots": [[0.5, 0.5]], "obstacles": [[0, 0]]},   # a robot on an obstacle
    {"map_size": 10, "robots": [[0.5, 0.5]], "params": {"a1": "x"}},   # a parameter's type
    {"map_size": 10},                                                  # robots missing
    {"map_size": 10, "robots": [[0.5, 0.5]], "colour": "blue"},        # an unknown key
]


@pytest.mark.parametrize("bad", BAD_SCENARIOS)
def test_a_bad_scenario_file_raises_the_cli_message(cli, tmp_path, bad):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad))
    expected = cli_message(cli, "run", path)
    with pytest.raises(swarmcheck.InputError) as e:
        swarmcheck.Scenario.from_file(path)
    assert str(e.value) == expected
    assert isinstance(e.value, ValueError)
    with pytest.raises(ValueError) as e2:
        swarmcheck.run(str(path))
    assert str(e2.value) == expected


@pytest.mark.parametrize("bad", BAD_SCENARIOS)
def test_a_bad_scenario_dict_raises_the_cli_message_with_its_json_path(cli, tmp_path, bad):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(bad))
    expected = cli_message(cli, "run", path)
    with pytest.raises(ValueError) as e:
        swarmcheck.Scenario(bad)
    # The file's name prefixes the CLI's message; the JSON path and the sentence are the same.
    assert expected == f"{path}: {e.value}"


def test_bad_keywords_name_the_keyword():
    with pytest.raises(ValueError, match=r"^rule: expected one of thesis\|"):
        swarmcheck.run(rule="nope")
    with pytest.raises(ValueError, match=r"^mode: expected one of abstract\|cosim"):
        swarmcheck.Simulation(mode="fast")
    with pytest.raises(ValueError, match=r"^preset: expected one of thesis"):
        swarmcheck.run(preset="other")
    with pytest.raises(ValueError, match=r"^seed: expected an integer"):
        swarmcheck.run(seed=-1)
    with pytest.raises(ValueError, match=r"^stall_window: "):
        swarmcheck.run(stall_window=-1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'engine'"):
        swarmcheck.run(engine="model")


def test_an_override_that_makes_a_scenario_invalid_is_named(cli, tmp_path):
    # A step of 1 s is valid in abstract mode; cosim refuses it (its controllers are checked to 0.5 s).
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"map_size": 10, "robots": [[0.5, 0.5]], "mode": "abstract",
                                "params": {"step_size": 1.0}}))
    expected = cli_message(cli, "run", path, "--mode", "cosim")
    assert "with the command-line overrides" in expected
    with pytest.raises(ValueError) as e:
        swarmcheck.run(str(path), mode="cosim")
    assert str(e.value) == expected.replace("with the command-line overrides", "with the keyword overrides")


def test_a_missing_file_and_a_non_json_value_are_errors(tmp_path):
    with pytest.raises(ValueError, match="nothing.json"):
        swarmcheck.Scenario(str(tmp_path / "nothing.json"))
    with pytest.raises(ValueError, match=r"^robots\[0\]: expected a JSON value"):
        swarmcheck.Scenario({"map_size": 10, "robots": [object()]})
    with pytest.raises(TypeError):
        swarmcheck.Scenario(42)


def test_bad_fsm_text_raises_the_cli_message(cli, tmp_path):
    path = tmp_path / "bad.fsm"
    path.write_text("2\n\ns0 1 1\na s1 c o\n")
    expected = cli_message(cli, "fsm", "check", path)
    with pytest.raises(swarmcheck.InputError) as e:
        swarmcheck.Automaton.read(path)
    assert str(e.value) == expected


def test_a_map_past_the_memory_limit_is_refused_with_the_cli_message(cli, tmp_path):
    path = tmp_path / "big.json"
    path.write_text(json.dumps({"map_size": 60000, "robots": [[0.5, 0.5]]}))
    expected = cli_message(cli, "run", path, "--memory-limit", "1G")
    assert "--memory-limit" in expected
    with pytest.raises(swarmcheck.InputError) as e:
        swarmcheck.run(str(path), memory_limit=1 << 30)
    assert str(e.value) == expected.replace("--memory-limit", "memory_limit")
    with pytest.raises(ValueError, match="memory_limit"):
        swarmcheck.Simulation(str(path))   # the default limit: 3/4 of this machine's memory
    with pytest.raises(ValueError, match="^memory_limit: expected a number of bytes"):
        swarmcheck.run(memory_limit=-1)

"""Missions from Python: mission_plan and mission_run return the dicts of `swarmcheck mission
plan|run --json`, the events also as records, the trace as the CLI writes it."""
import json
import os

import pytest

import swarmcheck


@pytest.fixture(scope="module")
def thesis_mission(source_dir):
    return os.path.join(source_dir, "scenarios", "thesis", "thesis-mission.json")


def test_plan_equals_cli_json(cli_json, thesis_mission):
    assert swarmcheck.mission_plan(thesis_mission) == cli_json("mission", "plan", thesis_mission)
    later = cli_json("mission", "plan", thesis_mission, "--from", "s14")
    assert swarmcheck.mission_plan(thesis_mission, from_state="s14") == later


@pytest.mark.parametrize("body", ["kinematic", "unicycle"])
def test_run_equals_cli_json_and_its_trace(cli, cli_json, thesis_mission, tmp_path, body):
    expected = cli_json("mission", "run", thesis_mission, "--body", body, "--dt", 0.1, "--trace", tmp_path / "cli.jsonl")
    got = swarmcheck.mission_run(thesis_mission, body=body, dt=0.1, trace=tmp_path / "py.jsonl", records=True)
    records = got.pop("event_records")
    assert got == expected and got["completed"]
    assert [r["event"] for r in records] == got["events"]
    assert (tmp_path / "py.jsonl").read_text() == (tmp_path / "cli.jsonl").read_text()
    traced = [json.loads(line) for line in (tmp_path / "cli.jsonl").read_text().splitlines()]
    traced_events = [t for t in traced if t.get("type") == "event"]
    assert [(t["t"], t["event"], t["robot"], t["kind"] == "c", t["state"]) for t in traced_events] == \
           [(r["time_s"], r["event"], r["robot"], r["controllable"], r["state_after"]) for r in records]


def test_bad_mission_input_raises_the_cli_message(cli, thesis_mission, tmp_path):
    code, _, err = cli("mission", "plan", thesis_mission, "--from", "nowhere")
    assert code == 2
    with pytest.raises(ValueError) as e:
        swarmcheck.mission_plan(thesis_mission, from_state="nowhere")
    assert err.replace("swarmcheck: error: --from", "from_state").rstrip() == str(e.value)
    bad = tmp_path / "bad.json"
    bad.write_text("{\"fsm\": 3}")
    code, _, err = cli("mission", "run", bad)
    assert code == 2
    with pytest.raises(swarmcheck.InputError) as e:
        swarmcheck.mission_run(bad)
    assert err == f"swarmcheck: error: {e.value}\n"
    with pytest.raises(ValueError, match="^dt: "):
        swarmcheck.mission_run(thesis_mission, dt=0)

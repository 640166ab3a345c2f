"""swarmcheck.Simulation: its state and its pheromone field equal what `swarmcheck run --trace`
records of the same run, step for step; the field is a read-only view, not a copy."""
import numpy as np
import pytest

import swarmcheck

STEPS = 120
FIELD_EVERY = 40


@pytest.fixture(scope="module", params=[("thesis", "cosim"), ("deterministic", "abstract"), ("stochastic", "cosim")])
def traced(request, cli, tmp_path_factory):
    rule, mode = request.param
    path = tmp_path_factory.mktemp("trace") / "run.jsonl"
    code, _, err = cli("run", "--rule", rule, "--mode", mode, "--steps", STEPS, "--trace", path,
                       "--trace-field", FIELD_EVERY, "--threads", 2)
    assert code in (0, 1), err
    return rule, mode, swarmcheck.read_trace(path)


def test_state_equals_the_trace_record_at_every_step(traced):
    rule, mode, trace = traced
    sim = swarmcheck.Simulation(rule=rule, mode=mode, steps=STEPS, threads=2)
    assert sim.state() == trace.records[0]
    for record in trace.records[1:]:
        sim.step()
        assert sim.state() == record
    assert sim.done and sim.steps == STEPS


def test_field_equals_the_traces_field_records(traced):
    rule, mode, trace = traced
    sim = swarmcheck.Simulation(rule=rule, mode=mode, steps=STEPS)
    assert sorted(trace.fields) == list(range(0, STEPS + 1, FIELD_EVERY))
    for step in sorted(trace.fields):
        sim.step(step - sim.steps)
        pheromone, visited, digest = trace.fields[step]
        field = sim.field
        assert field.shape == (10, 10) and field.dtype == np.float64
        assert np.array_equal(field.astype(np.float32), pheromone)   # the trace stores float32
        assert swarmcheck.pheromone_digest(field) == digest              # and the exact bits' digest
        assert swarmcheck.pheromone_digest(field) == trace.records[step]["pheromone_digest"]
        assert np.array_equal(sim.visited_cells, visited)
    assert np.any(sim.field > 0)


def test_robot_arrays_equal_the_state():
    sim = swarmcheck.Simulation(mode="cosim", steps=300)
    sim.step(137)
    robots = sim.state()["robots"]
    assert sim.cells.tolist() == [r["cell"] for r in robots]
    assert sim.waypoints.tolist() == [r["waypoint"] for r in robots]
    assert sim.poses.tolist() == [[r["body"]["x_m"], r["body"]["y_m"], r["body"]["theta_rad"]] for r in robots]
    assert {r["controller"]["maneuver"] for r in robots} <= {1, 2}


def test_field_is_a_read_only_view_of_the_simulation_not_a_copy():
    sim = swarmcheck.Simulation(mode="abstract", steps=100)
    sim.step(50)
    a, b = sim.field, sim.field
    assert a.base is sim and not a.flags.owndata
    assert np.shares_memory(a, b)
    assert not a.flags.writeable
    with pytest.raises(ValueError):
        a[0, 0] = 1.0
    # One buffer, brought up to date after a step: an earlier view sees the new field.
    before = a.copy()
    sim.step(50)
    now = sim.field
    assert np.shares_memory(a, now) and np.array_equal(a, now)
    assert not np.array_equal(before, now)
    del sim   # the view keeps the simulation alive
    assert np.isfinite(a).all()


def test_step_n_equals_n_steps_of_one():
    one, many = swarmcheck.Simulation(mode="cosim", steps=400), swarmcheck.Simulation(mode="cosim", steps=400)
    for _ in range(250):
        one.step()
    many.step(250)
    assert one.state() == many.state()
    many.step(10**6)   # stops at max_steps
    assert many.steps == 400 and many.done


def test_end_state_picture_is_the_run_svg(cli, tmp_path):
    path = tmp_path / "end.svg"
    code, _, err = cli("run", "--mode", "abstract", "--steps", 200, "--svg", path)
    assert code in (0, 1), err
    sim = swarmcheck.Simulation(mode="abstract", steps=200)
    sim.run()
    svg = sim._repr_svg_()
    assert svg.startswith("<svg") or svg.startswith("<?xml")
    # The same picture but for the title (the CLI names the scenario "default scenario" too).
    assert svg == path.read_text()


def test_trace_arrays_and_table_follow_the_records(traced):
    _, _, trace = traced
    assert trace.step.tolist() == list(range(STEPS + 1))
    assert trace.eP.tolist() == [r["eP"] for r in trace.records]
    table = trace._repr_html_()
    assert f"<td>{STEPS}</td><td>{trace.eP[-1]:.2f}</td>" in table
    assert table.count("<tr><td>") == 11

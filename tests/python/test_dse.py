"""swarmcheck.dse returns the results object of `swarmcheck dse --json`, its points as records."""
import json
import os

import swarmcheck


def test_dse_equals_cli_json_on_the_thesis_ertu_sweep(cli_json, source_dir, tmp_path):
    d = os.path.join(source_dir, "scenarios", "thesis", "dse")
    config, base = os.path.join(d, "ertu.dse.json"), os.path.join(d, "base.json")
    expected = cli_json("dse", config, "--scenario", base, "-o", tmp_path / "out", "--threads", 2, status=(0,))
    got = swarmcheck.dse(config, base, threads=2)
    assert got == expected
    assert [p["parameters"]["{Environment}.EnvironmentInstance.ertu_perc"] for p in got["points"]] == \
        [0.07, 0.06, 0.05, 0.04, 0.03, 0.02, 0.01, 0.009]
    # Each point's objectives are its run's: the same as swarmcheck.run on that point.
    point = got["points"][2]
    point_scenario = json.load(open(base))
    point_scenario["params"]["ertu"] = 0.05
    summary = swarmcheck.run(point_scenario)
    assert point["objectives"]["explorationPercentage"]["runs"] == [summary["eP"]]


def test_dse_resumes_from_its_journal(source_dir, tmp_path):
    d = os.path.join(source_dir, "scenarios", "thesis", "dse")
    config, base = os.path.join(d, "ertu.dse.json"), os.path.join(d, "base.json")
    journal = tmp_path / "journal.jsonl"
    first = swarmcheck.dse(config, base, journal=journal, threads=1)
    assert len(journal.read_text().splitlines()) == 8
    assert swarmcheck.dse(config, base, journal=journal, threads=1) == first
    assert len(journal.read_text().splitlines()) == 8   # nothing run again

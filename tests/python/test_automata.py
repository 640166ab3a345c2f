"""Automata from Python equal the CLI's: `fsm product|synth|project` output files, and the
--json of `fsm check|controllable|observable|compare` (witnesses as lists of events)."""
import os

import pytest

import swarmcheck

FAULT_PLANT = "4\np0 1 2\nf p1 uc uo\na p2 c o\np1 1 1\na p3 c o\np2 1 0\np3 1 0\n"
FAULT_SPEC = "3\ns0 1 2\nf s1\na s2\ns1 1 0\ns2 1 0\n"


@pytest.fixture(scope="module")
def thesis(source_dir):
    d = os.path.join(source_dir, "scenarios", "thesis")
    c = os.path.join(d, "components")
    return {
        "plants": [os.path.join(c, f"{k}.fsm") for k in ("region_a", "region_b", "tasks_a", "tasks_b")],
        "specs": [os.path.join(c, f"{k}.fsm") for k in ("avoidance", "completion")],
        "control2": os.path.join(d, "control2.fsm"),
    }


def without(d, *keys):
    return {k: v for k, v in d.items() if k not in keys}


def test_read_write_round_trip_is_the_canonical_export(cli, thesis, tmp_path):
    a = swarmcheck.Automaton.read(thesis["control2"])
    code, out, err = cli("fsm", "export", thesis["control2"], "--to", "fsm")
    assert code == 0, err
    assert a.to_fsm() == out
    a.write(tmp_path / "c2.fsm")
    assert (tmp_path / "c2.fsm").read_text() == out
    assert swarmcheck.Automaton.read(tmp_path / "c2.fsm") == a
    assert swarmcheck.Automaton.parse(out) == a
    assert a.initial == a.states[0] and len(a) == len(a.states) == 72
    assert all(q in a.states and e in a.events and r in a.states for q, e, r in a.transitions)


def test_check_equals_cli_json(cli_json, thesis, tmp_path):
    for path in [thesis["control2"], *thesis["plants"]]:
        assert swarmcheck.Automaton.read(path).check() == without(cli_json("fsm", "check", path), "file")
    blocking = tmp_path / "blocking.fsm"
    blocking.write_text("3\ns0 0 2\na s1 c o\nb s2 c o\ns1 1 0\ns2 0 0\n")
    got = swarmcheck.Automaton.read(blocking).check()
    assert got == without(cli_json("fsm", "check", blocking), "file")
    assert got["blocking_states"] == ["s2"] and not got["nonblocking"]


def test_product_equals_the_cli_output_file(cli, thesis, tmp_path):
    files = thesis["plants"][:1] + thesis["plants"][2:3]
    out = tmp_path / "p.fsm"
    code, _, err = cli("fsm", "product", *files, "-o", out)
    assert code == 0, err
    got = swarmcheck.product(swarmcheck.read_fsm_files(files))
    assert got == swarmcheck.Automaton.read(out)
    assert got.to_fsm() == out.read_text()


def test_synthesis_of_the_thesis_supervisor_equals_the_cli_output_file(cli, thesis, tmp_path):
    out = tmp_path / "sup.fsm"
    code, _, err = cli("fsm", "synth", "--plant", *thesis["plants"], "--spec", *thesis["specs"], "-o", out)
    assert code == 0, err
    automata = swarmcheck.read_fsm_files(thesis["plants"] + thesis["specs"])
    sup = swarmcheck.synthesize(automata[:4], automata[4:])
    assert len(sup) > 0
    assert sup == swarmcheck.Automaton.read(out)
    assert sup.to_fsm() == out.read_text()


def test_normal_synthesis_with_uo_events_equals_the_cli_output_file(cli, cli_json, tmp_path):
    plant, spec, out = tmp_path / "fp.fsm", tmp_path / "fs.fsm", tmp_path / "sup.fsm"
    plant.write_text(FAULT_PLANT)
    spec.write_text(FAULT_SPEC)
    facts = cli_json("fsm", "synth", "--plant", plant, "--spec", spec, "-o", out)
    assert facts["normal"] and facts["unobservable_events"] == ["f"]
    p, s = swarmcheck.read_fsm_files([str(plant), str(spec)])
    sup = swarmcheck.synthesize(p, s)
    assert sup == swarmcheck.supcon_normal(p, s) == swarmcheck.Automaton.read(out)
    assert sup.to_fsm() == out.read_text()
    assert swarmcheck.is_controllable(p, s) == facts["spec_controllable"]


def test_observer_equals_fsm_project(cli, tmp_path):
    plant, out = tmp_path / "fp.fsm", tmp_path / "obs.fsm"
    plant.write_text(FAULT_PLANT)
    code, _, err = cli("fsm", "project", plant, "-o", out)
    assert code == 0, err
    assert swarmcheck.Automaton.read(plant).observer() == swarmcheck.Automaton.read(out)


def test_control_report_equals_cli_json_with_its_witness(cli_json, thesis):
    expected = cli_json("fsm", "controllable", "--plant", *thesis["plants"], "--sup", thesis["control2"])
    automata = swarmcheck.read_fsm_files(thesis["plants"] + [thesis["control2"]])
    got = swarmcheck.control_report(automata[:4], automata[4])
    assert got == without(expected, "plant", "supervisor")
    assert not got["controllable"] and got["witness"] == ["b8e", "b3s"] and got["disabled_event"] == "b7e"


def test_observability_equals_cli_json_with_two_words_alike(cli_json, tmp_path):
    plant, spec = tmp_path / "fp.fsm", tmp_path / "fs.fsm"
    plant.write_text(FAULT_PLANT)
    spec.write_text(FAULT_SPEC)
    expected = cli_json("fsm", "observable", "--plant", plant, "--spec", spec)
    got = swarmcheck.observability(*swarmcheck.read_fsm_files([str(plant), str(spec)]))
    assert got == without(expected, "plant", "spec")
    assert (got["word"], got["twin"], got["event"]) == ([], ["f"], "a")


def test_compare_equals_cli_json_with_witnesses(cli, cli_json, thesis, tmp_path):
    out = tmp_path / "sup.fsm"
    code, _, err = cli("fsm", "synth", "--plant", *thesis["plants"], "--spec", *thesis["specs"], "-o", out)
    assert code == 0, err
    expected = cli_json("fsm", "compare", out, thesis["control2"])
    got = swarmcheck.compare(swarmcheck.Automaton.read(out), swarmcheck.Automaton.read(thesis["control2"]))
    for side in ("a", "b"):
        expected[side].pop("file")
    assert got == expected
    assert swarmcheck.language_inclusion(swarmcheck.Automaton.read(out),
                                         swarmcheck.Automaton.read(thesis["control2"])) == expected["a_in_b"]


def test_automaton_picture_is_the_cli_export(cli, thesis):
    code, out, err = cli("fsm", "export", thesis["plants"][0], "--to", "svg")
    assert code == 0, err
    a = swarmcheck.Automaton.read(thesis["plants"][0])
    assert a._repr_svg_() == out == a.svg()
    assert "<svg" in out

"""swarmcheck.prove returns the dict of `swarmcheck prove --json` (times aside)."""
import re

import pytest

import swarmcheck


def without_times(report):
    for o in report["obligations"]:
        o.pop("seconds")
        o.pop("slowest_query")   # which query was slowest depends on the times
    report.pop("total_seconds")
    return report


@pytest.mark.parametrize("name", ["servo-saturation", "atan2-without-fix"])
def test_prove_one_obligation_equals_cli_json(cli_json, name):
    expected = cli_json("prove", "--only", name, status=(0,))
    got = swarmcheck.prove(only=name)
    assert got["obligations"][0]["seconds"] > 0
    assert without_times(got) == without_times(expected)
    assert got["all_met"] and got["obligations"][0]["name"] == name


def test_an_unknown_obligation_is_the_cli_message(cli):
    code, _, err = cli("prove", "--only", "nothing")
    assert code == 2
    with pytest.raises(ValueError) as e:
        swarmcheck.prove(only="nothing")
    # The CLI cuts a long message ("... (N more bytes)"); Python keeps it whole.
    shown = re.sub(r" \.\.\. \(\d+ more bytes\)\n$", "", err)
    assert shown.startswith("swarmcheck: error: --only nothing: no such obligation; the obligations are: ")
    assert f"swarmcheck: error: --{e.value}".startswith(shown)
    assert str(e.value).endswith(", ".join(swarmcheck.OBLIGATIONS))
    assert set(swarmcheck.OBLIGATIONS) >= {"servo-saturation", "atan2-fix", "handshake-safety"}

"""Shared fixtures: the swarmcheck binary the Python results are compared with, and the sources."""
import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def source_dir():
    return os.environ.get("SWARMCHECK_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture(scope="session")
def cli():
    """Runs `swarmcheck ARGS`: returns (exit status, stdout, stderr)."""
    binary = os.environ["SWARMCHECK_BIN"]

    def call(*args):
        p = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=120)
        return p.returncode, p.stdout, p.stderr

    return call


@pytest.fixture(scope="session")
def cli_json(cli):
    def call(*args, status=(0, 1)):
        code, out, err = cli(*args, "--json")
        assert code in status, err
        return json.loads(out)

    return call

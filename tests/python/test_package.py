"""The package as users get it: docstrings and type stubs on every public name, the installed
copy imports from a prefix, and the examples/python script gives the CLI's numbers."""
import ast
import inspect
import json
import os
import re
import subprocess
import sys

import pytest

import swarmcheck
from swarmcheck import _swarmcheck


def public_members(obj):
    return [n for n in dir(obj) if not n.startswith("_")]


def test_every_public_name_and_member_has_a_docstring():
    for name in swarmcheck.__all__:
        obj = getattr(swarmcheck, name)
        if isinstance(obj, tuple):
            continue   # the constants are documented in the stubs
        assert (obj.__doc__ or "").strip(), name
        if inspect.isclass(obj):
            for member in public_members(obj):
                if member not in obj.__dict__:
                    continue   # inherited (ValueError's args, ...)
                assert (getattr(obj, member).__doc__ or "").strip(), f"{name}.{member}"


def stub_names(path):
    tree = ast.parse(open(path, encoding="utf-8").read())
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        elif isinstance(node, ast.AnnAssign):
            names[node.target.id] = set()
    return names


def test_the_stubs_declare_every_name_of_the_extension_and_nothing_else():
    stubs = stub_names(os.path.join(os.path.dirname(_swarmcheck.__file__), "_swarmcheck.pyi"))
    extension = {n for n in dir(_swarmcheck) if not n.startswith("__")}
    assert extension == set(stubs) - {"PathLike", "ScenarioSource", "AutomatonOrList"}
    for name, members in stubs.items():
        obj = getattr(_swarmcheck, name, None)
        if inspect.isclass(obj) and name != "InputError":
            assert set(public_members(obj)) - {"mro"} <= members, name


def test_the_installed_package_imports_from_its_prefix(tmp_path):
    build = os.path.dirname(os.path.dirname(os.path.dirname(_swarmcheck.__file__)))
    subprocess.run(["cmake", "--install", build, "--prefix", tmp_path, "--component", "python"],
                   check=True, capture_output=True)
    site = tmp_path / "lib" / "python3" / "dist-packages"
    installed = sorted(str(p.relative_to(site)) for p in site.rglob("*") if p.is_file())
    assert [f for f in installed if not f.startswith("swarmcheck/_swarmcheck.cpython")] == \
        ["swarmcheck/__init__.py", "swarmcheck/_swarmcheck.pyi", "swarmcheck/py.typed"]
    assert len(installed) == 4
    env = dict(os.environ, PYTHONPATH=str(site))
    out = subprocess.run([sys.executable, "-c", "import swarmcheck; print(swarmcheck.__file__); "
                          "print(swarmcheck.run(mode='abstract')['outcome'])"],
                         cwd=tmp_path, env=env, capture_output=True, text=True, check=True).stdout.split()
    assert out == [str(site / "swarmcheck" / "__init__.py"), "completed"]


def test_sweep_ertu_example_prints_the_cli_runs_and_the_synthesised_supervisor(cli, cli_json, source_dir, tmp_path):
    script = os.path.join(source_dir, "examples", "python", "sweep_ertu.py")
    p = subprocess.run([sys.executable, script, "--plot", tmp_path / "ertu.png"], capture_output=True, text=True,
                       check=True, timeout=120)
    rows = re.findall(r"^\s*([0-9.]+)\s+([0-9.]+)\s+([0-9.]+)\s+(\w+)$", p.stdout, re.M)
    assert len(rows) == 8
    base = json.load(open(os.path.join(source_dir, "scenarios", "thesis", "dse", "base.json")))
    for ertu, eP, sTime, outcome in rows[:3]:
        base["params"]["ertu"] = float(ertu)
        path = tmp_path / "point.json"
        path.write_text(json.dumps(base))
        expected = cli_json("run", path)
        assert (float(eP), float(sTime), outcome) == (round(expected["eP"], 2), round(expected["sTime"], 1),
                                                      expected["outcome"])
    thesis = os.path.join(source_dir, "scenarios", "thesis", "components")
    facts = cli_json("fsm", "synth", "--plant", *[os.path.join(thesis, f + ".fsm") for f in
                                                  ("region_a", "region_b", "tasks_a", "tasks_b")],
                     "--spec", os.path.join(thesis, "avoidance.fsm"), os.path.join(thesis, "completion.fsm"),
                     "-o", tmp_path / "sup.fsm")
    assert f"synthesised supervisor: {facts['states']} states, nonblocking: True" in p.stdout
    assert "controllable: False (after b8e b3s, b7e is disabled)" in p.stdout

"""The one front door (simlab/request.h): the table of bad requests tests/data/bad_requests.json,
which tests/test_front_door.cpp feeds to the CLI and the GUI, fed to Python: each refused with
ValueError and the CLI's text (what the CLI prints after "error: "), before any work or write."""

import json
import os
import pathlib
import subprocess

import pytest

import elasticlab as el

TABLE = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "bad_requests.json"
ROWS = [r for r in json.loads(TABLE.read_text()) if "python" in r]
CLI = os.environ.get("ELASTIC_LAB_CLI")


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    """The inputs the table names: a saved experiment and a FIFO."""
    d = tmp_path_factory.mktemp("door")
    el.Simulation("spring1d").save_scene(d / "exp.json")
    os.mkfifo(d / "fifo")
    return d


def test_the_table_has_rows_for_python():
    assert len(ROWS) >= 12


@pytest.mark.parametrize("row", ROWS, ids=[r["name"] for r in ROWS])
def test_python_refuses_with_the_clis_text(row, inputs):
    before = {p.name: p.read_bytes() for p in inputs.iterdir() if p.is_file()}
    expression = row["python"].replace("{dir}", str(inputs))
    with pytest.raises(ValueError) as e:
        eval(expression, {"el": el})
    assert str(e.value) == row["message"].replace("{dir}", str(inputs))
    # Nothing written, the experiment untouched.
    assert {p.name: p.read_bytes() for p in inputs.iterdir() if p.is_file()} == before


@pytest.mark.parametrize("row", [r for r in ROWS if "cli" in r], ids=[r["name"] for r in ROWS if "cli" in r])
def test_the_cli_agrees(row, inputs):
    """The same row through the CLI here too (the C++ test does all rows): the text is one."""
    if not CLI:
        pytest.skip("ELASTIC_LAB_CLI is not set (CTest sets it)")
    args = [a.replace("{dir}", str(inputs)) for a in row["cli"]]
    r = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr == "error: " + row["message"].replace("{dir}", str(inputs)) + "\n"


def test_an_uninitialised_simulation_refuses_instead_of_crashing():
    s = el.Simulation.__new__(el.Simulation)
    for name in ("time", "scene", "positions", "diagnostics", "diagnostics_columns", "integrator", "step_count"):
        with pytest.raises(RuntimeError, match="not initialised"):
            getattr(s, name)
    for call in (lambda: s.step(), lambda: s.run(1.0), lambda: s.reset(), lambda: s.save_scene("x.json")):
        with pytest.raises(RuntimeError, match="not initialised"):
            call()
    assert repr(s) == "<elasticlab.Simulation, not initialised>"

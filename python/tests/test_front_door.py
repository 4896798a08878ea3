"""The one front door (simlab/request.h): the table of bad requests tests/data/bad_requests.json,
which tests/test_front_door.cpp feeds to the CLI and the GUI, fed to Python: each refused with
ValueError and the CLI's text (what the CLI prints after "error: "), before any work or write."""

import ast
import json
import math
import os
import pathlib
import signal
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


# A deterministic mutation test of the Python door (issue 31): every constant of every row's
# expression replaced in turn by each hostile value. Each call must end in a refusal
# (ValueError, TypeError, RuntimeError, SimulationFailed) or a result, within a hang guard; never
# a crash (which would take the interpreter and this test with it), another exception, or a
# message that echoes a raw or whole value.
HOSTILE = [True, -1, 0, float("nan"), float("inf"), -float("inf"), 1e308, 10 ** 30, "", "x" * 5000,
           "\x1b]0;t\x07\x1b[2J", [], {}, ["rk4", "rk4"], [""]]


def _mutations():
    for row in ROWS:
        tree = ast.parse(row["python"], mode="eval")
        count = sum(isinstance(n, ast.Constant) for n in ast.walk(tree))
        for i in range(count):
            for value in HOSTILE:
                yield row, i, value


MUTATIONS = list(_mutations())


def _mutated(expression, index, value):
    tree = ast.parse(expression, mode="eval")
    constants = [n for n in ast.walk(tree) if isinstance(n, ast.Constant)]
    replacement = ast.parse(repr(value), mode="eval").body if not isinstance(value, float) or math.isfinite(value) \
        else ast.parse(f"float({str(value)!r})", mode="eval").body
    target = constants[index]
    for parent in ast.walk(tree):
        for field, old in ast.iter_fields(parent):
            if old is target:
                setattr(parent, field, replacement)
            elif isinstance(old, list):
                for k, item in enumerate(old):
                    if item is target:
                        old[k] = replacement
    return compile(ast.fix_missing_locations(tree), "<mutation>", "eval")


def test_the_python_door_holds_under_mutation(inputs, tmp_path, monkeypatch):
    assert len(MUTATIONS) > 300
    monkeypatch.chdir(tmp_path)  # a mutated output name lands here
    outcomes = {"refused": 0, "ran": 0}
    current = []

    def hung(signum, frame):
        raise TimeoutError(f"a mutated request ran past the hang guard: {current}")

    previous = signal.signal(signal.SIGALRM, hung)
    try:
        for row, index, value in MUTATIONS:
            code = _mutated(row["python"].replace("{dir}", str(inputs)), index, value)
            current[:] = [row["name"], index, repr(value)[:40]]
            signal.alarm(60)
            try:
                eval(code, {"el": el})
                outcomes["ran"] += 1
            except (ValueError, TypeError, RuntimeError, el.SimulationFailed) as e:
                text = str(e)
                assert "\x1b" not in text and "\x07" not in text and len(text) < 1500, (row["name"], index, value, text[:200])
                outcomes["refused"] += 1
            finally:
                signal.alarm(0)
    finally:
        signal.signal(signal.SIGALRM, previous)
    assert outcomes["refused"] > outcomes["ran"]

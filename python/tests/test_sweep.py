"""Sweeps (elasticlab.sweep) and the numpy-like surface of the module (issue 29), run by CTest as
part of test_python: the table, its grid order and statuses, the same table from a Dask
LocalCluster with two worker processes, a process pool and the CLI; pickling that goes on bit
for bit; sampling in seconds; signatures and stubs. No assertion depends on speed.
"""

import ast
import inspect
import io
import os
import pickle
import re
import subprocess
import threading
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import numpy as np
import pandas as pd
import pytest

import elasticlab as el

CLI = os.environ.get("ELASTIC_LAB_CLI")

# A small grid of short runs: a bounce within 1.3 s, 8 particles per layer.
GRID = {"pressure": [10, 40], "ks": [400, 1600], "contact": ["force", "projection"]}
FIXED = {"particles": 8}
DURATION = 1.3


def same_table(a, b):
    """Column by column, exactly (NaN equal to NaN), wall time aside."""
    assert list(a.columns) == list(b.columns)
    for c in a.columns:
        if c == "wall_seconds":
            continue
        x, y = a[c], b[c]
        if x.dtype.kind == "f" or y.dtype.kind == "f":
            assert np.array_equal(x.to_numpy(float), y.to_numpy(float), equal_nan=True), c
        else:
            assert list(x) == list(y), c


@pytest.fixture(scope="module")
def serial():
    return el.sweep("ring2d", GRID, duration=DURATION, progress=False, **FIXED)


def test_the_table_has_a_row_per_point_in_grid_order(serial):
    df = serial
    assert len(df) == 8 and list(df["index"]) == list(range(8))
    # First key slowest, as itertools.product.
    assert list(df["pressure"]) == [10.0] * 4 + [40.0] * 4
    assert list(df["ks"]) == [400.0, 400.0, 1600.0, 1600.0] * 2
    assert list(df["contact"]) == ["force", "projection"] * 4
    assert set(df["status"]) == {"ok"} and set(df["reason"]) == {""}
    assert set(df["integrator"]) == {"rk4"} and set(df["version"]) == {el.__version__}
    for m in ("volume_inner_final", "volume_outer_max", "pressure_inner_max", "energy_total_final",
              "energy_drift_max", "bounce_time", "bounce_height", "strain_max", "steps", "force_evals",
              "wall_seconds"):
        assert m in df.columns
    assert df["steps"].dtype == np.int64 and (df["steps"] == 434).all()  # 1.3 s at dt 0.003: 434 steps
    assert (df["t_end"] >= DURATION).all()
    # Every one bounced on the floor: the centre of mass turned upwards after a touch, then rose again.
    assert df["bounce_time"].between(0.5, DURATION).all()
    assert (df["bounce_height"].dropna() > 0).all()
    assert (df["volume_inner_min"] <= df["volume_inner_final"]).all()
    assert (df["volume_inner_final"] <= df["volume_inner_max"]).all()
    # Higher pressure, larger volume; it is the parameter that reached the run.
    assert (df[df.pressure == 40]["volume_inner_final"].to_numpy() > df[df.pressure == 10]["volume_inner_final"].to_numpy()).all()
    assert df.attrs["scene"] == "ring2d" and df.attrs["duration"] == DURATION


def test_a_run_of_the_table_is_the_simulation_of_that_point(serial):
    row = serial.iloc[5]
    sim = el.Simulation("ring2d", pressure=row.pressure, ks=row.ks, contact=row.contact, **FIXED)
    r = sim.run(DURATION)
    assert sim.step_count == row.steps
    assert sim.diagnostics["volume_inner"] == row.volume_inner_final
    assert sim.diagnostics["energy_total"] == row.energy_total_final
    assert r["t"][-1] == row.t_end


def test_a_dask_local_cluster_with_two_worker_processes_gives_the_same_table(serial):
    distributed = pytest.importorskip("distributed")
    import dask
    # Workers started by a fork server: seconds sooner than spawn's fresh interpreters, and
    # unlike a plain fork safe beside the client's event-loop thread.
    with dask.config.set({"distributed.worker.multiprocessing-method": "forkserver"}), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=40) as cluster, distributed.Client(cluster) as client:
        df = el.sweep("ring2d", GRID, duration=DURATION, executor=client, progress=False, **FIXED)
        workers = client.run(os.getpid)
    assert len(set(workers.values())) == 2 and os.getpid() not in workers.values()
    same_table(df, serial)


def test_executors_with_map_give_the_same_table(serial):
    with ProcessPoolExecutor(2) as pool:
        same_table(el.sweep("ring2d", GRID, duration=DURATION, executor=pool, progress=False, **FIXED), serial)
    with ThreadPoolExecutor(2) as pool:  # the GIL is released while a point runs
        same_table(el.sweep("ring2d", GRID, duration=DURATION, executor=pool, progress=False, **FIXED), serial)
        # Points packed three to a task (the last task has two): the same table, in grid order.
        same_table(el.sweep("ring2d", GRID, duration=DURATION, executor=pool, chunk=3, progress=False, **FIXED),
                   serial)
    with pytest.raises(ValueError, match="chunk = 0 is out of range"):
        el.sweep("ring2d", GRID, duration=DURATION, executor=Refusing(), chunk=0, **FIXED)


def test_the_cli_writes_the_same_table(serial, tmp_path):
    if not CLI:
        pytest.skip("ELASTIC_LAB_CLI is not set (CTest sets it)")
    out = tmp_path / "sweep.csv"
    r = subprocess.run([CLI, "sweep", "--scene", "ring2d", "--set", "particles=8", "--grid", "pressure=10,40",
                        "--grid", "ks=400,1600", "--grid", "contact=force,projection", "--duration", str(DURATION),
                        "--csv", str(out), "--quiet"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    same_table(pd.read_csv(out, keep_default_na=False, na_values=["nan"], float_precision="round_trip"), serial)


def test_items_pickle_and_run_anywhere(serial):
    text, columns, count = el._core._sweep_plan("ring2d", list(GRID), [list(v) for v in GRID.values()], None,
                                                DURATION, None, None, None, None, **FIXED)
    from elasticlab._sweep import SweepItem, run_item
    item = pickle.loads(pickle.dumps(SweepItem(text, 3)))
    row = dict(zip(columns, run_item(item)))
    assert row["index"] == 3 and row["volume_inner_final"] == serial.iloc[3]["volume_inner_final"]


def test_failed_and_over_budget_rows_say_why():
    df = el.sweep("ring2d", {"pressure": [0.5, 20], "dt": [0.0001, 0.003]}, duration=1.2, max_steps=1000,
                  metrics=["steps", "t_end"], progress=False)
    by = {(r.pressure, r.dt): r for r in df.itertuples()}
    assert by[(20, 0.003)].status == "ok" and by[(20, 0.003)].reason == ""
    assert by[(0.5, 0.003)].status == "failed" and "collapsed" in by[(0.5, 0.003)].reason  # too little gas
    over = by[(20, 0.0001)]
    assert over.status == "over budget" and "12000 steps" in over.reason and over.steps == 0
    assert list(df.columns) == ["index", "pressure", "dt", "integrator", "status", "reason", "steps", "t_end", "version"]


def test_random_samples_follow_the_seed():
    grid = {"pressure": el.uniform(10, 40), "ks": el.loguniform(300, 3000), "contact": ["force", "projection"]}
    a = el.sweep("ring2d", grid, samples=5, seed=7, duration=0.05, metrics=["steps"], progress=False, **FIXED)
    b = el.sweep("ring2d", grid, samples=5, seed=7, duration=0.05, metrics=["steps"], progress=False, **FIXED)
    c = el.sweep("ring2d", grid, samples=5, seed=8, duration=0.05, metrics=["steps"], progress=False, **FIXED)
    same_table(a, b)
    assert not np.array_equal(a["pressure"], c["pressure"])
    assert a["pressure"].between(10, 40).all() and a["ks"].between(300, 3000).all()
    assert set(a["contact"]) <= {"force", "projection"} and a.attrs["seed"] == 7
    fresh = el.sweep("ring2d", {"pressure": el.uniform(10, 40)}, samples=2, duration=0.01, progress=False)
    assert isinstance(fresh.attrs["seed"], int)  # a fresh seed, kept to draw the same points again


def test_ranges():
    assert list(el.linear(0.5, 2.0, 4)) == [0.5, 1.0, 1.5, 2.0]
    assert list(el.log(1, 1000, 4)) == pytest.approx([1, 10, 100, 1000], rel=1e-15)
    assert el.log(3, 7, 5)[0] == 3 and el.log(3, 7, 5)[-1] == 7
    d = el.decades(100, 1e4, 2)
    assert list(d[::2]) == [100, 1000, 10000] and d[1] == pytest.approx(316.227766, rel=1e-8)
    with pytest.raises(ValueError, match="needs both ends > 0"):
        el.log(0, 10, 3)


class Refusing:
    """An executor that fails the test if anything reaches it."""

    def map(self, *args):
        raise AssertionError("the sweep ran before its request was checked")


def cli_sweep_error(*args):
    if not CLI:
        pytest.skip("ELASTIC_LAB_CLI is not set (CTest sets it)")
    r = subprocess.run([CLI, "sweep", "--duration", "0.1", "--csv", "-", *args], capture_output=True, text=True)
    assert r.returncode == 2, r.stderr
    return r.stderr.strip()


@pytest.mark.parametrize("grid, keywords, cli_args", [
    ({"stiffness": [1, 2]}, {}, ["--grid", "stiffness=1,2"]),
    ({"ks": [800, -5]}, {}, ["--grid", "ks=800,-5"]),
    ({"ks": [800, 800]}, {}, ["--grid", "ks=800,800"]),
    ({"contact": ["glue"]}, {}, ["--grid", "contact=glue"]),
    ({"ks": [800]}, {"metrics": ["bounce"]}, ["--grid", "ks=800", "--metrics", "bounce"]),
    ({"ks": [800]}, {"radius_inner": 3.0}, ["--grid", "ks=800", "--set", "radius_inner=3"]),
])
def test_bad_requests_raise_the_clis_message_before_anything_runs(grid, keywords, cli_args):
    with pytest.raises(ValueError) as e:
        el.sweep("ring2d", grid, duration=0.1, executor=Refusing(), progress=False, **keywords)
    message = str(e.value)
    assert message and "\n" not in message
    assert message in cli_sweep_error("--scene", "ring2d", *cli_args)


def test_bad_sweep_keywords():
    with pytest.raises(ValueError, match="duration = -1 is out of range"):
        el.sweep("ring2d", {"ks": [800]}, duration=-1, executor=Refusing())
    with pytest.raises(ValueError, match="^atol = 2 is out of range"):
        el.sweep("ring2d", {"ks": [800]}, duration=1, atol=2, executor=Refusing())
    with pytest.raises(ValueError, match="distribution"):
        el.sweep("ring2d", {"ks": el.uniform(1, 2)}, duration=1, executor=Refusing())
    with pytest.raises(TypeError):
        el.sweep("ring2d", {"ks": [800]}, 1.0)  # duration is a keyword
    with pytest.raises(TypeError, match="executor"):
        el.sweep("ring2d", {"ks": [800]}, duration=0.01, executor=object(), progress=False)


def test_progress_bar_and_callback(capsys):
    pytest.importorskip("tqdm")
    el.sweep("ring2d", {"ks": [400, 800]}, duration=0.01, metrics=["steps"], **FIXED)
    assert "sweep: 100%" in capsys.readouterr().err  # tqdm's bar on stderr
    seen = []
    el.sweep("ring2d", {"ks": [400, 800]}, duration=0.01, metrics=["steps"], progress=lambda d, n: seen.append((d, n)))
    assert seen == [(1, 2), (2, 2)]


# --- Simulation: pickling -------------------------------------------------------------------------

@pytest.mark.parametrize("integrator", ["euler", "midpoint", "rk4", "symplectic-euler", "verlet", "rk45",
                                        "implicit-euler", "xpbd"])
def test_a_pickled_simulation_goes_on_bit_for_bit(integrator):
    sim = el.Simulation("ring2d", integrator=integrator, dt=0.002, rtol=1e-5, contact="force", **FIXED)
    sim.run(0.9)  # on the floor: contact forces in play
    copy = pickle.loads(pickle.dumps(sim))
    assert type(copy) is el.Simulation and copy.integrator == integrator
    assert copy.time == sim.time and copy.step_count == sim.step_count
    assert copy.parameters == sim.parameters and copy.integrator_options == sim.integrator_options
    sim.run(0.2)
    copy.run(0.2)
    assert copy.step_count == sim.step_count
    assert np.array_equal(copy.positions, sim.positions) and np.array_equal(copy.velocities, sim.velocities)


def test_a_pickled_cvode_simulation_restarts_its_solver_from_the_state():
    """CVODE keeps a history (order, past steps) no scene file holds: a copy restarts the method
    from the exact state, as a resumed scene file does (docs/python.md), and stays close."""
    sim = el.Simulation("ring2d", integrator="cvode-bdf", rtol=1e-8, atol=1e-10, **FIXED)
    sim.run(0.5)
    copy = pickle.loads(pickle.dumps(sim))
    assert np.array_equal(copy.positions, sim.positions) and copy.time == sim.time
    sim.run(0.2)
    copy.run(0.2)
    assert np.abs(copy.positions - sim.positions).max() < 1e-5


def test_a_simulation_goes_to_a_worker_process_and_back():
    sim = el.Simulation("ring2d", integrator="rk45", **FIXED)
    sim.run(0.3)
    with ProcessPoolExecutor(1) as pool:
        back = pool.submit(_advance, sim).result()
    sim.run(0.3)
    assert np.array_equal(back.positions, sim.positions) and back.time == sim.time


def _advance(sim):
    sim.run(0.3)
    return sim


# --- Simulation: numpy-like ------------------------------------------------------------------------

def test_run_samples_every_so_many_seconds():
    sim = el.Simulation("ring2d", dt=0.002, **FIXED)
    r = sim.run(0.1, every=0.02)
    assert r.dtype.names == tuple(sim.diagnostics_columns) and r["step"].dtype == np.int64
    assert list(r["t"]) == pytest.approx([0, 0.02, 0.04, 0.06, 0.08, 0.1], abs=1e-12)
    assert list(r["step"]) == [0, 10, 20, 30, 40, 50]
    assert np.isnan(r["error_estimate"]).all()  # none: NaN, not -1
    adaptive = el.Simulation("ring2d", integrator="rk45", rtol=1e-6, **FIXED)
    a = adaptive.run(0.3, t_eval=[0.0, 0.05, 0.123, 0.3])
    assert list(a["t"]) == [0.0, 0.05, 0.123, pytest.approx(0.3, abs=1e-12)]  # landed on exactly
    assert (a["error_estimate"][1:] >= 0).all()
    df = pd.DataFrame(a)  # a structured array is a table for pandas
    assert list(df.columns) == list(adaptive.diagnostics_columns)
    end = el.Simulation("spring1d").run(0.01)  # no sampling asked: the start and the end
    assert len(end) == 2 and end["t"][0] == 0
    with pytest.raises(ValueError, match="every = 0 is out of range"):
        sim.run(0.1, every=0)
    with pytest.raises(ValueError, match="t_eval"):
        sim.run(0.1, t_eval=[0.5])
    with pytest.raises(ValueError, match="one of"):
        sim.run(0.1, every=0.01, every_steps=2)


def test_options_are_keywords_and_none_means_off():
    sim = el.Simulation("ring2d", integrator="rk45", rtol=1e-8, atol=1e-9, max_step=0.01)
    o = sim.integrator_options
    assert o["rtol"] == 1e-8 and o["atol"] == 1e-9 and o["max_step"] == 0.01
    assert el.Simulation("ring2d", integrator="rk45").integrator_options["max_step"] is None
    sim.set_integrator("implicit-euler", newton=3)
    assert sim.integrator_options["newton"] == 3 and sim.integrator_options["rtol"] == 1e-8
    with pytest.raises(ValueError, match="^rtol = 2 is out of range"):
        el.Simulation("ring2d", rtol=2)


def test_time_is_readable_from_another_thread_and_progress_is_called():
    sim = el.Simulation("ring2d", dt=0.0005, **FIXED)
    seen, calls = [], []
    done = threading.Event()

    def watch():
        while not done.is_set():
            seen.append(sim.time)

    t = threading.Thread(target=watch)
    t.start()
    sim.run(20.0, progress=calls.append)
    done.set()
    t.join()
    assert seen == sorted(seen) and seen[-1] <= sim.time
    assert len(set(seen)) > 1  # it moved while the run went on in the other thread
    assert calls == sorted(calls) and all(0 < c <= sim.time for c in calls)


def test_progress_callback_can_stop_a_run():
    sim = el.Simulation("ring2d", dt=0.0005, **FIXED)

    def stop(t):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sim.run(1e5, progress=stop)
    assert 0 < sim.time < 1e5


# --- signatures, docstrings, stubs ------------------------------------------------------------------

PUBLIC = ["Simulation", "scenes", "integrators", "parameters", "study", "refinement", "stability", "sweep",
          "linear", "log", "decades", "uniform", "loguniform", "integers"]


@pytest.mark.parametrize("name", PUBLIC)
def test_every_public_callable_has_a_real_signature_and_a_docstring(name):
    obj = getattr(el, name)
    inspect.signature(obj)  # raises ValueError for a builtin without one
    assert obj.__doc__ and len(obj.__doc__) > 40


def test_methods_have_signatures_and_units():
    for method in ("run", "step", "reset", "set_integrator", "exact", "save_scene"):
        inspect.signature(getattr(el.Simulation, method))
    assert "[s]" in el.Simulation.run.__doc__ and "[s]" in el.sweep.__doc__
    assert list(inspect.signature(el.sweep).parameters)[:3] == ["scene", "grid", "duration"]


def test_the_stubs_cover_the_compiled_module():
    """_core.pyi names every public function and class of _core with the same parameters."""
    stub = os.path.join(os.path.dirname(el._core.__file__), "_core.pyi")
    tree = ast.parse(open(stub).read())
    stubbed = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            stubbed[node.name] = [a.arg for a in node.args.args + node.args.kwonlyargs]
        elif isinstance(node, ast.ClassDef):
            stubbed[node.name] = {n.name: [a.arg for a in n.args.args + n.args.kwonlyargs]
                                  for n in node.body if isinstance(n, ast.FunctionDef)}
    public = {n for n in dir(el._core) if not n.startswith("__")}
    assert public - {"__version__"} <= set(stubbed) | {"__version__"}, public - set(stubbed)
    for name in public:
        obj = getattr(el._core, name)
        if callable(obj) and not isinstance(obj, type):
            # pybind11's first docstring line: name(arg: type, ...) -> ...
            args = re.findall(r"(?:\(|, )(\w+): ", obj.__doc__.splitlines()[0])
            assert args == stubbed[name], name
    assert os.path.exists(os.path.join(os.path.dirname(stub), "py.typed"))

"""The Python module elasticlab (python/elasticlab.cpp), run by CTest as test_python.

Physics against closed forms, the parameter table's messages against the CLI's, the no-copy
views, Ctrl+C in a run and in a study. No assertion depends on how fast anything runs: every
wait is on a condition, and CTest's timeout is the only guard against a hang.
"""

import csv
import math
import os
import signal
import subprocess
import threading
import time
import _thread

import numpy as np
import pytest

import elasticlab as el

CLI = os.environ.get("ELASTIC_LAB_CLI")


# --- closed form -------------------------------------------------------------------------------

def oscillator(params, t):
    """spring1d with a fixed top end, by hand: m y'' = -k (y + L0) - c y' - m g from rest at
    y = -initial_length; the moving particle's y and y' (under-damped case)."""
    k, c, m, g = params["ks"], params["kd"], params["mass"], params["gravity"]
    y_eq = -(params["length"] + m * g / k)
    z0 = -params["initial_length"] - y_eq
    w0, gamma = math.sqrt(k / m), c / (2 * m)
    wd = math.sqrt(w0 * w0 - gamma * gamma)
    e = math.exp(-gamma * t)
    z = e * (z0 * math.cos(wd * t) + gamma * z0 / wd * math.sin(wd * t))
    dz = -e * z0 * (w0 * w0 / wd) * math.sin(wd * t)
    return y_eq + z, dz


def test_spring1d_follows_the_closed_form():
    sim = el.Simulation("spring1d", integrator="rk4", dt=1e-3, kd=2.0)
    assert sim.parameters["fixed_end"] == 1
    for _ in range(4):
        sim.run(0.25)
        y, v = oscillator(sim.parameters, sim.time)
        # RK4 at h w0 = 0.028: its global error is ~1e-9 m here; 1e-7 leaves room, a wrong
        # time, step or force is off by far more.
        assert abs(sim.positions[1, 1] - y) < 1e-7
        assert abs(sim.velocities[1, 1] - v) < 1e-5
        x_exact, v_exact = sim.exact()  # simcore's own closed form agrees with ours
        assert abs(x_exact[1, 1] - y) < 1e-12 and abs(v_exact[1, 1] - v) < 1e-10
    assert sim.step_count == 1000 and sim.time == pytest.approx(1.0, abs=1e-12)
    assert repr(sim) == "<elasticlab.Simulation 'spring1d', rk4, 2 particles, step 1000, t = 1 s>"
    assert np.all(sim.positions[:, [0, 2]] == 0.0)  # 1D moves along y only
    assert sim.positions[0, 1] == 0.0  # the fixed end


# CVODE's methods choose their own order and step (no fixed-step mode): their error follows the
# tolerance instead (test_cvode_error_follows_the_tolerance).
FIXED_STEP = [i["name"] for i in el.integrators() if not i["name"].startswith("cvode-")]


@pytest.mark.parametrize("integrator", ["cvode-bdf", "cvode-adams"])
def test_cvode_error_follows_the_tolerance(integrator):
    """Tolerance proportionality: 100x tighter tolerances give a much smaller error against the
    closed form (at least 10x; CVODE's local control makes it roughly proportional)."""
    errors = []
    for tol in (1e-5, 1e-7):
        sim = el.Simulation("spring1d", integrator=integrator, kd=0.0, options={"atol": tol, "rtol": tol})
        sim.run(0.4)
        errors.append(float(np.max(np.abs(sim.positions - sim.exact()[0]))))
    assert errors[1] < errors[0] / 10, errors


@pytest.mark.parametrize("integrator", FIXED_STEP)
def test_every_integrator_runs_and_converges(integrator):
    """Each integrator at two steps in its asymptotic range (undamped: velocity Verlet is
    second order only without damping): the error against the closed form shrinks by 2^order."""
    order = {i["name"]: i["order"] for i in el.integrators()}[integrator]
    dts = {1: (4e-4, 2e-4), 2: (4e-3, 2e-3), 4: (1e-2, 5e-3), 5: (2e-2, 1e-2), 8: (2e-2, 1e-2)}[order]
    errors = []
    for dt in dts:
        sim = el.Simulation("spring1d", integrator=integrator, dt=dt, kd=0.0, options={"fixed_step": True})
        error = 0.0  # the largest over 0.4 s (at one time the error may pass through zero)
        for _ in range(10):
            sim.run(0.04)
            error = max(error, float(np.max(np.abs(sim.positions - sim.exact()[0]))))
        errors.append(error)
    assert math.log2(errors[0] / errors[1]) == pytest.approx(order, abs=0.3), errors


def test_adaptive_integrator_options():
    loose = el.Simulation("spring1d", integrator="rk45", options={"atol": 1e-4, "rtol": 1e-4})
    tight = el.Simulation("spring1d", integrator="rk45", options={"atol": 1e-10, "rtol": 1e-10})
    assert tight.integrator_options["atol"] == 1e-10
    for sim in (loose, tight):
        sim.run(0.5)
    err = [float(np.max(np.abs(s.positions - s.exact()[0]))) for s in (loose, tight)]
    assert err[1] < 1e-7 and err[1] < err[0] / 100
    assert tight.step_count > loose.step_count


def test_run_records_the_diagnostics_rows():
    sim = el.Simulation("ring2d", dt=0.002)
    rows = sim.run(0.1, every_steps=10)
    cols = sim.diagnostics_columns
    assert rows.dtype.names == tuple(cols) and rows.shape == (1 + 5,)  # start, every 10 steps, the end
    step, t = rows["step"], rows["t"]
    assert list(step) == [0, 10, 20, 30, 40, 50]
    assert t[-1] == pytest.approx(0.1) and t[-1] == sim.time
    assert np.array_equal(np.array(rows[-1].tolist()), sim.diagnostics_row, equal_nan=True)
    assert sim.diagnostics["error_estimate"] is None and np.isnan(rows["error_estimate"]).all()  # none: not -1
    assert sim.diagnostics["volume_outer"] == rows["volume_outer"][-1]
    assert "volume_inner" in cols and "pressure_outer" in cols  # gas columns in 2D only
    assert "volume_inner" not in el.Simulation("spring1d").diagnostics_columns


# --- no copy -----------------------------------------------------------------------------------

def test_positions_are_a_read_only_view_of_the_state():
    sim = el.Simulation("ring2d")
    p, v = sim.positions, sim.velocities
    assert p.shape == (sim.particle_count, 3) and p.dtype == np.float64
    assert p.base is sim and v.base is sim  # the Simulation owns the memory
    assert np.shares_memory(p, sim.positions)  # the same buffer each time: no copy
    assert not np.shares_memory(p, v)
    assert not p.flags.writeable
    with pytest.raises(ValueError):
        p[0, 0] = 1.0
    before = p.copy()
    sim.step(5)
    assert not np.array_equal(p, before)  # the view follows the simulation
    assert np.array_equal(p, sim.positions)


def test_a_view_keeps_its_simulation_alive():
    p = el.Simulation("sphere3d").positions
    import gc
    gc.collect()
    assert p.base.particle_count == p.shape[0]
    assert np.isfinite(p).all() and np.linalg.norm(p, axis=1).max() > 0.5


def test_two_simulations_step_in_parallel_threads():
    """Stepping releases the GIL and two Simulations share nothing: each thread's result is the
    one it gets alone, bit for bit."""
    def make(scene):
        return el.Simulation(scene, integrator="rk4", dt=0.002, threads=1)
    alone = {scene: make(scene) for scene in ("ring2d", "sphere3d")}
    for sim in alone.values():
        sim.run(0.3)
    together = {scene: make(scene) for scene in alone}
    workers = [threading.Thread(target=sim.run, args=(0.3,)) for sim in together.values()]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    for scene in alone:
        assert together[scene].step_count == alone[scene].step_count == 150
        assert np.array_equal(together[scene].positions, alone[scene].positions)


def test_a_second_thread_cannot_step_a_busy_simulation():
    sim = el.Simulation("ring2d", dt=0.001)
    errors = []

    def meddle():
        while not stepping(sim):
            time.sleep(0.001)
        for call in (lambda: sim.step(), lambda: sim.run(1.0), lambda: sim.positions):
            try:
                call()
            except RuntimeError as e:
                errors.append(str(e))
        _thread.interrupt_main()

    t = threading.Thread(target=meddle, daemon=True)
    t.start()
    with pytest.raises(KeyboardInterrupt):
        sim.run(1e6)
    t.join()
    assert errors == ["this Simulation is being stepped by another thread"] * 3


# --- errors: the table's messages, as the CLI prints them --------------------------------------

def cli_error(*args):
    """The CLI's one-line message for bad input (exit status 2)."""
    if not CLI:
        pytest.skip("ELASTIC_LAB_CLI is not set (CTest sets it)")
    r = subprocess.run([CLI, "run", *args, "--duration", "0.01", "--quiet"], capture_output=True, text=True)
    assert r.returncode == 2, r.stderr
    return r.stderr.strip()


@pytest.mark.parametrize("scene, keywords, cli_args", [
    ("spring1d", {"ks": -1}, ["--set", "ks=-1"]),
    ("spring1d", {"ks": "abc"}, ["--set", "ks=abc"]),
    ("spring1d", {"ks": float("nan")}, ["--set", "ks=nan"]),
    ("spring1d", {"pressure": 20}, ["--set", "pressure=20"]),
    ("ring2d", {"particles": 2.5}, ["--set", "particles=2.5"]),
    ("ring2d", {"contact": "glue"}, ["--set", "contact=glue"]),
    ("ring2d", {"radius_inner": 3.0}, ["--set", "radius_inner=3"]),
    ("nowhere", {}, []),
])
def test_bad_parameters_raise_the_clis_message(scene, keywords, cli_args):
    with pytest.raises(ValueError) as e:
        el.Simulation(scene, **keywords)
    message = str(e.value)
    assert message and "\n" not in message
    assert message in cli_error("--scene", scene, *cli_args)


def test_bad_integrator_and_options():
    with pytest.raises(ValueError) as e:
        el.Simulation("spring1d", integrator="leapfrog")
    assert str(e.value) in cli_error("--scene", "spring1d", "--integrator", "leapfrog")
    with pytest.raises(ValueError, match=r"^atol = 2 is out of range; allowed \(0, 1\]$"):
        el.Simulation("spring1d", options={"atol": 2})
    with pytest.raises(ValueError, match="unknown integrator option 'tol'"):
        el.Simulation("spring1d", options={"tol": 1e-6})
    with pytest.raises(TypeError):
        el.Simulation("spring1d", ks=[800])
    with pytest.raises(TypeError):
        el.Simulation("spring1d", options={"fixed_step": 1})
    with pytest.raises(ValueError, match="duration = -1 is out of range"):
        el.Simulation("spring1d").run(-1)


def test_failure_raises_and_keeps_the_last_good_state():
    sim = el.Simulation("spring1d", integrator="euler", dt=0.09, kd=0)  # h w0 = 2.5: euler grows
    with pytest.raises(el.SimulationFailed) as e:
        sim.run(100.0, every_steps=1)
    f = e.value
    assert isinstance(f, RuntimeError)
    assert f.reason and f.step >= 1 and str(e.value).startswith(f"simulation failed at step {f.step}")
    assert sim.failure == {"reason": f.reason, "step": f.step, "time": f.time}
    assert np.isfinite(sim.positions).all()
    assert len(f.rows) == sim.step_count + 1 and f.rows["step"][-1] == sim.step_count  # a row per good step
    with pytest.raises(el.SimulationFailed):
        sim.step()


def test_scene_file_round_trip(tmp_path):
    sim = el.Simulation("ring2d", integrator="verlet", ks=900, dt=0.002)
    sim.run(0.05)
    path = tmp_path / "exp.json"
    sim.save_scene(path)
    resumed = el.Simulation(path)  # a pathlib.Path works as well as a str
    assert resumed.integrator == "verlet" and resumed.parameters["ks"] == 900
    assert resumed.step_count == sim.step_count and resumed.time == sim.time
    assert np.array_equal(resumed.positions, sim.positions)
    sim.run(0.05)
    resumed.run(0.05)
    assert np.array_equal(resumed.positions, sim.positions)  # resumed exactly
    assert el.Simulation(str(path), ks=950).parameters["ks"] == 950  # keywords override
    bad = tmp_path / "bad.json"
    bad.write_text(path.read_text().replace('"ks": 900', '"ks": "x"'))
    with pytest.raises(ValueError) as e:
        el.Simulation(bad)
    assert str(e.value) in cli_error("--scene", str(bad))


# --- studies -----------------------------------------------------------------------------------

def test_study_fits_the_nominal_orders_and_writes_the_clis_files(tmp_path):
    result = el.study("spring1d", integrators=["midpoint", "rk4"], dts=[0.004, 0.002, 0.001],
                      duration=1.0, fixed_step=True, kd=1.0, box=1000.0,
                      csv=tmp_path / "wp.csv", plot=tmp_path / "wp.svg")
    assert "closed form" in result["reference"]
    assert result["orders"]["rk4"] == pytest.approx(4.0, abs=0.2)
    assert result["orders"]["midpoint"] == pytest.approx(2.0, abs=0.1)
    rows = result["rows"]
    assert [(r["integrator"], r["dt"]) for r in rows] == [
        (m, h) for m in ("midpoint", "rk4") for h in (0.004, 0.002, 0.001)]
    assert all(r["status"] == "ok" and r["steps"] == round(1.0 / r["dt"]) for r in rows)
    with open(tmp_path / "wp.csv") as f:
        table = list(csv.DictReader(f))
    assert len(table) == len(rows)
    for written, row in zip(table, rows):
        assert written["integrator"] == row["integrator"] and int(written["steps"]) == row["steps"]
        assert float(written["error_max"]) == row["error_max"]  # shortest round-trip text
        assert int(written["force_evals"]) == row["force_evals"]
    svg = (tmp_path / "wp.svg").read_text()
    assert svg.lstrip().startswith("<") and "<svg" in svg and "rk4" in svg


def test_study_keeps_every_timing_and_the_error_measures(tmp_path):
    # issue 28: raw timings, quartiles, error_rms, orders per measure, the family, the budget.
    result = el.study("spring1d", integrators=["yoshida4", "rk4"], dts=[0.01, 0.005, 0.0025], duration=2.0,
                      kd=0.0, box=1000.0, repeat=3, timings=tmp_path / "t.csv", csv=tmp_path / "wp.csv")
    for r in result["rows"]:
        assert len(r["walls"]) == 3
        assert r["wall_min"] <= r["wall_q1"] <= r["wall_median"] <= r["wall_q3"] <= max(r["walls"])
        assert r["wall_seconds"] == r["wall_median"]
        assert r["error_rms"] <= r["error_max"]
        assert r["family"] == {"yoshida4": "symplectic", "rk4": "explicit-rk"}[r["integrator"]]
    assert result["orders"]["yoshida4"] == pytest.approx(4.0, abs=0.15)
    assert result["orders_rms"]["yoshida4"] == pytest.approx(4.0, abs=0.15)
    assert set(result["orders_final"]) == {"yoshida4", "rk4"}
    assert {b["family"] for b in result["fastest"]} == {"symplectic", "explicit-rk"}
    with open(tmp_path / "t.csv") as f:
        timings = list(csv.DictReader(f))
    assert len(timings) == 3 * len(result["rows"])
    assert [float(t["wall_seconds"]) for t in timings[:3]] == result["rows"][0]["walls"]
    with open(tmp_path / "wp.csv") as f:
        table = list(csv.DictReader(f))
    assert float(table[0]["wall_q3"]) == result["rows"][0]["wall_q3"]
    # A budget no run can meet: every point not reached, no error.
    over = el.study("spring1d", integrators=["rk4"], dts=[0.01, 0.005], duration=2.0, time_budget=1e-9)
    assert [r["status"] for r in over["rows"]] == ["not reached", "not reached"]
    assert all(math.isnan(r["error_max"]) and r["walls"] == [] for r in over["rows"])


def test_study_in_float_shows_the_round_off_floor():
    dts = [0.00125, 0.000625, 0.0003125, 0.00015625, 7.8125e-05, 3.90625e-05]
    result = el.study("spring1d", integrators=["rk4"], dts=dts, duration=2.0, kd=0.0, box=1000.0,
                      precision=["double", "float"])
    double = [r["error_max"] for r in result["rows"] if r["precision"] == "double"]
    single = [r["error_max"] for r in result["rows"] if r["precision"] == "float"]
    assert all(b < a for a, b in zip(double, double[1:]))  # double keeps falling
    assert single[-1] > 4 * min(single)  # float stops and rises
    assert set(result["orders"]) == {"rk4", "rk4 (float)"}
    with pytest.raises(ValueError, match="no float build"):
        el.study("spring1d", integrators=["rk45"], dts=[0.01], precision=["float"])


def test_a_float_run_steps_the_float_path(tmp_path):
    """precision="float": the float path steps the run (the same bits with 1 and 2 threads, as
    the CLI's run --precision float writes them), close to double but not double, and the
    simulation holds its end state afterwards."""
    def run(precision, threads, state=None):
        sim = el.Simulation("ring2d", gravity=0.0, perturb=0.02, threads=threads)
        rows = sim.run(0.2, every_steps=10, precision=precision)
        return sim, rows
    f1, rows = run("float", 1)
    f2, _ = run("float", 2)
    d, _ = run("double", 1)
    assert f1.time == pytest.approx(d.time) and f1.step_count == d.step_count == 67
    assert np.array_equal(f1.positions, f2.positions)
    assert not np.array_equal(f1.positions, d.positions)
    assert 0 < np.abs(f1.positions - d.positions).max() < 1e-4
    assert rows["step"][-1] == f1.step_count and abs(rows["energy_drift"]).max() < 1e-3
    if CLI:  # the CLI's float run ends in the same state, bit for bit
        subprocess.run([CLI, "run", "--scene", "ring2d", "--set", "gravity=0", "--set", "perturb=0.02",
                        "--duration", "0.2", "--precision", "float", "--quiet", "--state", str(tmp_path / "s.csv")],
                       check=True)
        with open(tmp_path / "s.csv") as f:
            table = list(csv.DictReader(f))
        assert [float(r["x"]) for r in table] == list(f1.positions[:, 0])
    # The study takes precision="float" too (the float path beyond spring1d).
    result = el.study("ring2d", integrators=["rk4"], dts=[0.002], duration=0.1, gravity=0.0, perturb=0.02,
                      precision="float")
    assert [r["precision"] for r in result["rows"]] == ["float"]
    with pytest.raises(ValueError, match="^precision float is built for the explicit integrators"):
        el.Simulation("ring2d", integrator="rk45").run(0.1, precision="float")


def test_conservation_classifies_the_growth(tmp_path):
    out = el.conservation("spring1d", integrators=["verlet", "rk4"], periods=300, dt=0.01, csv=tmp_path / "c.csv")
    rows = {r["integrator"]: r for r in out["rows"]}
    assert rows["verlet"]["class"] == "bounded" and rows["rk4"]["class"] == "drift"
    assert rows["rk4"]["alpha_lo"] <= rows["rk4"]["alpha"] <= rows["rk4"]["alpha_hi"]
    assert len(rows["rk4"]["t"]) == len(rows["rk4"]["energy_error"]) > 10
    assert out["omega_max"] == pytest.approx(math.sqrt(800.0), rel=1e-6)
    with open(tmp_path / "c.csv") as f:
        assert f.readline().startswith("integrator,alpha,alpha_lo,alpha_hi,class,")
    with pytest.raises(ValueError, match="chooses its own steps"):
        el.conservation("spring1d", integrators=["rk45"], dt=0.01)
    assert {i["name"]: i["family"] for i in el.integrators()}["yoshida8"] == "symplectic"


def test_study_refuses_a_bad_spec():
    with pytest.raises(ValueError):
        el.study("spring1d", integrators=["rk4"], dts=[0.3], duration=1.0)  # T not a multiple of dt
    with pytest.raises(ValueError, match="unknown integrator 'rk5'"):
        el.study("spring1d", integrators=["rk5"], dts=[0.01])


def test_stability_scan_brackets_the_prediction(tmp_path):
    out = el.stability("spring1d", integrators=["rk4", "symplectic-euler"], duration=1.0, kd=0.0,
                       csv=tmp_path / "st.csv")
    rows = {r["integrator"]: r for r in out["rows"]}
    w = out["omega_max"]
    assert w == pytest.approx(math.sqrt(800.0), rel=1e-6)  # one mode: sqrt(k / m)
    for name, limit in (("rk4", 2 * math.sqrt(2)), ("symplectic-euler", 2.0)):
        r = rows[name]
        assert r["dt_predicted"] * w == pytest.approx(limit, rel=1e-3)
        assert r["dt_stable"] < r["dt_unstable"]
        # measured near the prediction (docs/numerics.md has the whole comparison)
        assert 0.8 < r["dt_stable"] / r["dt_predicted"] < 1.1
    with open(tmp_path / "st.csv") as f:
        lines = f.read().splitlines()
    assert lines[0].startswith("integrator,dt_stable,dt_unstable,dt_predicted")
    assert [line.split(",")[0] for line in lines[1:]] == ["rk4", "symplectic-euler"]


# --- Ctrl+C ------------------------------------------------------------------------------------

def interrupt_when(condition, how):
    """A thread that waits until condition() holds, then delivers SIGINT the way `how` says."""
    def body():
        while not condition():
            time.sleep(0.001)
        if how == "interrupt_main":
            _thread.interrupt_main()
        else:
            signal.raise_signal(signal.SIGINT)  # a real signal, delivered to this thread
    t = threading.Thread(target=body, daemon=True)
    t.start()
    return t


def stepping(sim):
    """True once another thread is inside sim.run (reading the state then raises RuntimeError;
    time and step_count stay readable). That this can be seen at all shows that the run released
    the GIL."""
    try:
        sim.positions
        return False
    except RuntimeError:
        return True


@pytest.mark.parametrize("how", ["interrupt_main", "raise_signal"])
def test_ctrl_c_interrupts_a_run_at_a_full_step(how):
    sim = el.Simulation("ring2d", dt=0.001)
    t = interrupt_when(lambda: stepping(sim), how)
    with pytest.raises(KeyboardInterrupt):
        sim.run(1e6)  # 1e9 steps: only the interrupt ends it
    t.join()
    n = sim.step_count
    assert n > 0 and sim.failure is None
    # Consistent: the same state as an uninterrupted run of as many steps, bit for bit ...
    same = el.Simulation("ring2d", dt=0.001)
    same.step(n)
    assert np.array_equal(sim.positions, same.positions)
    assert np.array_equal(sim.velocities, same.velocities)
    assert sim.diagnostics == same.diagnostics
    # ... and it goes on from there.
    sim.step(3)
    same.step(3)
    assert np.array_equal(sim.positions, same.positions)


def threads_of_this_process():
    return len(os.listdir("/proc/self/task"))


@pytest.mark.parametrize("what", ["study", "refinement", "stability"])
def test_ctrl_c_cancels_a_study(tmp_path, what):
    import gc
    gc.collect()  # no thread of an earlier test's Simulation ends while we count
    before = threads_of_this_process()
    # Once the process has a thread more than before (beside the interrupter), the call is
    # inside the study: the worker thread exists only there.
    t = interrupt_when(lambda: threads_of_this_process() > before + 1, "interrupt_main")
    target = tmp_path / "out.csv"
    with pytest.raises(KeyboardInterrupt):
        if what == "study":  # a reference of 1.6e9 steps: hours, unless cancelled
            el.study("spring1d", integrators=["rk4"], dts=[1e-5], duration=1000.0, csv=target)
        elif what == "refinement":  # 10^4 s of the ring at two resolutions
            el.refinement("ring2d", levels=[12, 24], duration=1e4, csv=target)
        else:  # bisections over runs of 1e4 s (1e9 steps at hmin: the most a trial may take)
            el.stability("ring2d", integrators=["euler"], duration=1e4, csv=target)
    t.join()
    assert not target.exists()  # nothing written, not even in part
    assert os.listdir(tmp_path) == []


def test_refinement_measures_second_order_in_space(tmp_path):
    # The weightless ring (tests/test_refinement.cpp): its area error against the finest level
    # falls like h^2 as the mesh spacing h halves.
    out = el.refinement("ring2d", levels=[48, 12, 24], duration=0.2, gravity=0.0,
                        csv=tmp_path / "ref.csv", plot=tmp_path / "ref.svg")
    rows = out["rows"]
    assert [r["value"] for r in rows] == [12, 24, 48] and [r["reference"] for r in rows] == [False, False, True]
    assert all(r["status"] == "ok" and r["particles"] == 2 * r["value"] and r["key"] == "particles" for r in rows)
    assert 1.8 < out["orders"]["volume"] < 2.8
    assert math.isnan(out["orders"]["com"])  # the symmetric body's centre stays put: nothing to fit
    assert out["time_error_volume"] < 1e-4 * rows[1]["error_volume"]  # the step's error is not the mesh's
    assert len(out["temporal"]) == 4
    with open(tmp_path / "ref.csv") as f:
        table = list(csv.DictReader(f))
    assert [int(r["value"]) for r in table] == [12, 24, 48]
    assert "<svg" in (tmp_path / "ref.svg").read_text()
    with pytest.raises(ValueError):
        el.refinement("ring2d", levels=[12], duration=0.2)  # one level is not a study


def test_stability_prediction_is_the_clis(tmp_path):
    # One verdict (issue 25): Python's predicted step is the CLI's, on a body above the exact
    # limit (the level-2 sphere: Arnoldi), linearised at the rest shape by both.
    out = el.stability("sphere3d", integrators=["rk4", "euler"], duration=0.1, hmin=0.001, subdivisions=2, dt=0.01)
    python = {r["integrator"]: r["dt_predicted"] for r in out["rows"]}
    target = tmp_path / "cli.csv"
    subprocess.run([os.environ["ELASTIC_LAB_CLI"], "stability", "--scene", "sphere3d", "--set", "subdivisions=2",
                    "--set", "dt=0.01", "--integrators", "rk4,euler", "--duration", "0.1", "--hmin", "0.001",
                    "--quiet", "--csv", str(target)], check=True, capture_output=True)
    with open(target) as f:
        cli = {row["integrator"]: float(row["dt_predicted"]) for row in csv.DictReader(f)}
    assert python.keys() == cli.keys()
    for name, predicted in cli.items():
        assert python[name] == pytest.approx(predicted, rel=1e-12)
    assert 0.005 < python["rk4"] < 0.01 and python["euler"] < 0.8 * python["rk4"]

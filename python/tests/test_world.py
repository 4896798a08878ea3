"""elasticlab.World: scenes of several bodies from Python (issue 26), run by CTest as test_python.

Per-body views follow the world, per-body diagnostics agree with the views, a scene of bodies
built from Python runs as the CLI's, refusals name the body and the key, and a pickled or saved
world goes on bit for bit.
"""

import os
import pickle

import numpy as np
import pytest

import elasticlab as el


def test_world_scenes_and_bodies():
    assert el.world_scenes() == ["collide2d", "collide3d", "stack3d"]
    w = el.World("collide2d", gravity=0, set=["body2.mass=4"])
    assert [b.number for b in w.bodies] == [1, 2]
    assert [b.kind for b in w.bodies] == ["ring2d", "ring2d"]
    assert w.bodies[0].parameters["mass"] == 1.0 and w.bodies[1].parameters["mass"] == 4.0
    assert w.bodies[1].parameters["gravity"] == 0.0  # a world parameter, every body's
    assert w.bodies[0].start_position == (-3.0, 0.0, 0.0)
    assert w.bodies[1].start_velocity == (-2.0, 0.0, 0.0)
    n1, n2 = w.bodies[0].particle_count, w.bodies[1].particle_count
    assert w.positions.shape == (n1 + n2, 3)
    # The body's view is its slice of the world's state, and follows it as it steps.
    p2 = w.bodies[1].positions
    assert not p2.flags.writeable
    before = p2.copy()
    w.step(5)
    assert not np.array_equal(p2, before)
    np.testing.assert_array_equal(p2, w.positions[n1:])
    np.testing.assert_array_equal(w.bodies[0].velocities, w.velocities[:n1])


def test_body_diagnostics_agree_with_the_views():
    w = el.World("collide3d", gravity=0, set=["body2.mass=4"])
    w.step(3)
    for b in w.bodies:
        d = b.diagnostics
        m = b.parameters["mass"]  # every particle has it at the reference resolution
        assert d["mass"] == pytest.approx(m * b.particle_count, rel=1e-12)
        np.testing.assert_allclose(d["com"], b.positions.mean(axis=0), rtol=0, atol=1e-12)
        np.testing.assert_allclose(d["velocity"], b.velocities.mean(axis=0), rtol=0, atol=1e-12)
        assert d["volume_outer"] > d["volume_inner"] > 0
    total = sum(np.array(b.diagnostics["momentum"]) for b in w.bodies)
    np.testing.assert_allclose(total, w.momentum, rtol=0, atol=1e-12)
    assert w.diagnostics["momentum_x"] == pytest.approx(w.momentum[0], abs=1e-12)
    assert w.diagnostics["com_x_2"] == pytest.approx(w.bodies[1].diagnostics["com"][0], abs=1e-15)
    assert w.min_gap == w.diagnostics["min_gap"] > 0


def test_a_weightless_collision_keeps_momentum_and_the_bodies_separate():
    w = el.World("collide2d", gravity=0, integrator="rk4")
    rows = w.run(1.6, every=0.05)
    assert rows["t"][-1] == pytest.approx(1.6, abs=w.dt)
    p0 = np.array([rows["momentum_x"][0], rows["momentum_y"][0]])
    drift = np.abs(np.stack([rows["momentum_x"], rows["momentum_y"]], axis=1) - p0).max()
    assert drift <= 1e-9 * 24 * 2 * 2  # relative to the momentum each body carries
    assert rows["min_gap"].min() > 0  # they touched (within the skin) and never crossed
    assert rows["com_x_1"].max() > rows["com_x_1"][0] and rows["velocity_x_1"][-1] < 0  # bounced back


def test_bodies_from_python_run_as_the_cli_scene():
    """bodies=[...] built by hand as collide2d is: the same trajectory, bit for bit."""
    mine = el.World(bodies=[{"kind": "ring2d", "position": (-3, 0), "velocity": (2, 0)},
                            {"kind": "ring2d", "position": (3, 0, 0), "velocity": (-2, 0, 0), "mass": 4}],
                    box=10, gravity=0)
    built = el.World("collide2d", gravity=0, set=["body2.mass=4"])
    mine.step(20)
    built.step(20)
    np.testing.assert_array_equal(mine.positions, built.positions)
    assert mine.scene == "world"


@pytest.mark.parametrize("kwargs, mentions", [
    (dict(scene="collide3d", set=["body3.mass=2"]), "body3.mass: the scene has 2 bodies"),
    (dict(scene="collide3d", set=["body1.gravity=0"]), "body1.gravity"),
    (dict(scene="collide3d", set=["body2.position_x=-2"]), "bodies 1 and 2 overlap"),
    (dict(bodies=[{"kind": "ring2d", "position": (-3, 0)}, {"kind": "torus", "position": (3, 0)}], box=10),
     "body2.kind: unknown body kind 'torus'"),
    (dict(bodies=[{"kind": "ring2d", "position": (-3, 0)}, {"kind": "ring2d", "position": (3, 0), "mass": -1}],
          box=10), "body2"),
    (dict(bodies=[{"kind": "sphere3d", "position": (k, 0, 0)} for k in range(17)]), "at most 16"),
    (dict(scene="ring2d"), "ring2d is one body"),
])
def test_refusals_name_the_body_and_the_key(kwargs, mentions):
    with pytest.raises(ValueError, match=None) as e:
        el.World(**kwargs)
    assert mentions in str(e.value)


def test_one_body_simulation_points_at_world():
    with pytest.raises(ValueError, match="elasticlab.World"):
        el.Simulation("stack3d")


def test_pickle_and_scene_file_go_on_bit_for_bit(tmp_path):
    w = el.World("collide2d", gravity=0, integrator="rk45", offset=0.4)
    w.run(0.1)
    copy = pickle.loads(pickle.dumps(w))
    path = os.fspath(tmp_path / "world.json")
    w.save_scene(path)
    resumed = el.World(path)
    assert resumed.integrator == "rk45" and resumed.time == w.time and resumed.step_count == w.step_count
    for other in (copy, resumed):
        np.testing.assert_array_equal(other.positions, w.positions)
    w.step(15)
    copy.step(15)
    resumed.step(15)
    np.testing.assert_array_equal(copy.positions, w.positions)
    np.testing.assert_array_equal(resumed.velocities, w.velocities)


def test_an_intersection_raises_simulation_failed():
    w = el.World("collide2d", gravity=0, integrator="euler", dt=0.01,
                 set=["body1.velocity_x=60", "body2.velocity_x=-60"])
    with pytest.raises(el.SimulationFailed) as e:
        w.run(0.5, every_steps=1)
    assert e.value.rows is not None and len(e.value.rows) >= 1
    assert w.failure is not None


def test_a_world_is_studied_as_a_whole():
    """stability, study and refinement take a world as the CLI does (tests/test_world_studies.cpp
    measures them): one spectrum of every body, errors over every body, every body refined."""
    st = el.stability("collide2d", integrators=["rk4"], duration=0.3, gravity=0)
    assert st["bodies"] == 2
    assert st["free_coordinates"] == 2 * el.stability("ring2d", integrators=["rk4"], duration=0.3,
                                                      gravity=0)["free_coordinates"]
    row = st["rows"][0]
    assert 0 < row["dt_stable"] < row["dt_unstable"]
    out = el.study("collide2d", integrators=["rk4"], dts=[0.01, 0.005], duration=0.1, samples=2, gravity=0)
    assert [r["status"] for r in out["rows"]] == ["ok", "ok"]
    assert out["rows"][1]["error_final"] < out["rows"][0]["error_final"]
    ref = el.refinement("collide2d", levels=[8, 16], duration=0.05, interval=0.05, temporal_runs=0, gravity=0)
    assert [r["particles"] for r in ref["rows"]] == [32, 64]
    with pytest.raises(ValueError, match="several bodies"):
        el.conservation("collide2d")

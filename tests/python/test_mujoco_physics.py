"""Live co-simulation with MuJoCo physics (examples/python/talos_mujoco_physics.py, the code
docs/cosimulation.md shows): MuJoCo steps TALOS (Menagerie's MJCF, floating base, contacts, its
position actuators' PD control) standing, squatting unassisted and stepping in place with a soft
support on the pelvis, and proxsim measures from that state every 10 ms. Checked: the physics
moved the robot for real (the squat lowers the pelvis, each foot leaves the floor in turn, nothing
but the feet touches the floor); proxsim found no collision in the physical states; every ray
proxsim cast that met the floor or the box meets the same geom in MuJoCo's own mj_ray at the same
distance (1e-6 m); and proxsim driven again by the recorded states writes the same readings.csv
and poses.csv, byte for byte. Skipped, saying so, without ../shared/robots/pal_talos."""
import os
import sys

import numpy as np
import pytest

from conftest import SOURCE_DIR

sys.path.insert(0, os.path.join(SOURCE_DIR, "examples", "python"))
import talos_mujoco_physics as live  # noqa: E402

needs_talos = pytest.mark.skipif(not os.path.isfile(os.path.join(live.TALOS_DIR, "scene_position.xml")),
                                 reason=f"TALOS is not at {live.TALOS_DIR} (read from beside the project, never copied)")


@pytest.fixture(scope="module")
def record(tmp_path_factory):
    out = tmp_path_factory.mktemp("live")
    return live.run(out=str(out / "run")), out


@needs_talos
def test_the_physics_moves_the_robot(record):
    r, _ = record
    mj = r["mujoco"]
    assert len(mj) == 400
    start = mj[0]["pelvis_z_m"]
    squat = [s for s in mj if live.SETTLE_S <= s["t_s"] < live.SQUAT_END_S]
    stepping = [s for s in mj if s["t_s"] > live.SQUAT_END_S]
    # the squat: PD alone, both feet down throughout, the pelvis at least 4 cm lower at its bottom
    assert not any(s["assisted"] for s in squat)
    assert all(len(s["feet_on_floor"]) == 2 for s in mj if s["t_s"] < live.SQUAT_END_S)
    assert min(s["pelvis_z_m"] for s in squat) < start - 0.04
    # stepping (assisted): each foot off the floor at some sample, never both
    assert all(s["assisted"] for s in stepping)
    for foot in ("leg_left_6_link", "leg_right_6_link"):
        assert any(foot not in s["feet_on_floor"] for s in stepping), foot
    assert all(s["feet_on_floor"] for s in stepping)
    # nothing but the feet on the floor, in MuJoCo
    assert all(not s["other_on_floor"] for s in mj)


@needs_talos
def test_proxsim_measures_the_physical_state_as_mujoco_sees_it(record):
    r, _ = record
    robot = r["summary"]["robot"]
    assert robot["collisions"] == [] and robot["outcome"] == "time_up", robot
    compared = {"floor": 0, "box": 0}
    for truth, mj in zip(r["truth"], r["mujoco"]):
        for i, (d_mujoco_m, geom) in enumerate(mj["rays"]):
            if truth["object"][i] in compared:  # proxsim's ray met the scene, not the robot itself
                assert geom == truth["object"][i], (truth["t_s"], i)
                assert abs(d_mujoco_m - truth["d_true_m"][i]) < 1e-6, (truth["t_s"], i)
                compared[geom] += 1
    assert compared["floor"] > 100 and compared["box"] > 100, compared


@needs_talos
def test_replaying_the_recorded_states_gives_the_same_files(record, tmp_path):
    r, out = record
    summary = live.replay(r["states"], out=str(tmp_path / "replay"))
    assert summary["robot"]["outcome"] == r["summary"]["robot"]["outcome"]
    for name in ("readings.csv", "poses.csv"):
        with open(out / "run" / name, "rb") as a, open(tmp_path / "replay" / name, "rb") as b:
            assert a.read() == b.read(), name

"""Co-simulation (robot.locomotion: external, docs/cosimulation.md): a run driven by the recorded
states of a gait run measures exactly what the gait run measured; bad states are refused, naming
the fault, and refused states change nothing."""
import os

import numpy as np
import pytest

import proxsim
from conftest import run_cli, scenario


def record_gait_run(make, out):
    """Every sample's robot state of a gait run, its files written to out."""
    states = []
    with make(out=out) as sim:
        while not sim.done:
            sim.step()
            states.append(sim.robot_state())
    return states


def drive(make, out, states, orientation):
    """The same scenario driven from outside by `states`; returns the summary."""
    with make(out=out, locomotion="external") as sim:
        assert sim.external
        for s in states:
            sim.step(q=s["q"], X_WP=(s["xyz"], s[orientation]), gait_phase=s["gait_phase"],
                     support_leg=s["support_leg"])
        assert sim.done
        summary = sim.summary()
    return summary


def read(path):
    with open(path, "rb") as f:
        return f.read()


def test_driven_by_the_paper_gait_run_gives_byte_identical_readings(tmp_path):
    # the paper's walk is straight ahead: its quaternions are exactly (1, 0, 0, 0)
    def make(**kw):
        return proxsim.Simulation.builtin("paper", **kw)

    states = record_gait_run(make, str(tmp_path / "gait"))
    summary = drive(make, str(tmp_path / "external"), states, "quat_wxyz")
    for name in ("readings.csv", "poses.csv", "profile.ply"):
        assert read(tmp_path / "gait" / name) == read(tmp_path / "external" / name), name
    # the terrain map built from those readings is the same map
    terrain = sorted(os.listdir(tmp_path / "gait" / "terrain"))
    assert terrain == sorted(os.listdir(tmp_path / "external" / "terrain")) and terrain
    for name in terrain:
        assert read(tmp_path / "gait" / "terrain" / name) == read(tmp_path / "external" / "terrain" / name), name
    # the stop rule still decides (its stop is recorded for the caller to obey) and the outcome is the gait's
    assert summary["robot"]["stop_requested_t_s"] is not None
    assert summary["robot"]["outcome"] == "stopped"
    assert summary["inputs"]["robot"]["locomotion"] == "external"


def test_driven_by_a_turning_gait_run_gives_byte_identical_readings(tmp_path):
    # the walk around the obstacle turns: its rotation matrices, given as they are, place the robot
    # exactly; as quaternions they differ from the gait's matrices in the last bits only
    def make(**kw):
        return proxsim.Simulation(scenario("circumvent_obstacle.yaml"), **kw)

    states = record_gait_run(make, str(tmp_path / "gait"))
    yaw = [2 * np.arctan2(s["quat_wxyz"][3], s["quat_wxyz"][0]) for s in states]
    assert max(np.abs(yaw)) > np.radians(10)  # it does turn
    drive(make, str(tmp_path / "matrix"), states, "R")
    assert read(tmp_path / "gait" / "readings.csv") == read(tmp_path / "matrix" / "readings.csv")
    drive(make, str(tmp_path / "quaternion"), states, "quat_wxyz")
    gait = np.genfromtxt(tmp_path / "gait" / "readings.csv", delimiter=",", names=True, dtype=None, encoding=None)
    quat = np.genfromtxt(tmp_path / "quaternion" / "readings.csv", delimiter=",", names=True, dtype=None,
                         encoding=None)
    assert (gait["status"] == quat["status"]).all()
    np.testing.assert_allclose(quat["d_true_m"], gait["d_true_m"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(quat["origin_x_m"], gait["origin_x_m"], rtol=0, atol=1e-9)


def test_a_collision_is_found_and_ends_the_episode_as_for_the_gait(tmp_path):
    # the paper's walk without its stop rule strikes the obstacle; driven by its states, so does the external run
    def make(**kw):
        return proxsim.Simulation(scenario("paper_no_stop_rule.yaml"), **kw)

    states = record_gait_run(make, str(tmp_path / "gait"))
    with make(locomotion="external") as sim:
        for s in states:
            sim.step(q=s["q"], X_WP=(s["xyz"], s["R"]), gait_phase=s["gait_phase"], support_leg=s["support_leg"])
        assert sim.done  # ended at the collision, with the gait run's last state
        external = sim.summary()["robot"]
    with make() as sim:
        while not sim.done:
            sim.step()
        gait = sim.summary()["robot"]
    assert gait["outcome"] == "collided"
    assert external["outcome"] == "collided" and external["outcome_t_s"] == gait["outcome_t_s"]
    assert external["collisions"] == gait["collisions"]
    assert external["min_clearance_m"] == gait["min_clearance_m"]


def test_joints_by_name_equal_joints_by_array():
    names_sim = proxsim.Simulation.builtin("paper", locomotion="external")
    array_sim = proxsim.Simulation.builtin("paper", locomotion="external")
    q = np.linspace(0.1, 0.3, len(names_sim.joint_names))
    pose = ([0.0, 0.0, 0.95], [1.0, 0.0, 0.0, 0.0])
    by_name = names_sim.step(q=dict(zip(names_sim.joint_names, q)), X_WP=pose)
    by_array = array_sim.step(q=q, X_WP=pose)
    np.testing.assert_array_equal(by_name["readings"]["d_m"], by_array["readings"]["d_m"])
    np.testing.assert_array_equal(names_sim.robot_state()["q"], q)
    assert names_sim.robot_state()["support_leg"] == "double"  # nothing given: as a replayed trajectory


@pytest.fixture
def external():
    sim = proxsim.Simulation.builtin("paper", locomotion="external")
    q = {name: 0.0 for name in sim.joint_names}
    sim.step(q=q, X_WP=([0.0, 0.0, 0.95], [1.0, 0.0, 0.0, 0.0]))
    return sim, q


@pytest.mark.parametrize("change, fault", [
    (lambda q, p: ({k: v for k, v in q.items() if k != "left_knee_pitch"}, p), "joint 'left_knee_pitch' is missing"),
    (lambda q, p: ({**q, "tail": 0.0}, p), "'tail' is not a moving joint"),
    (lambda q, p: ({**q, "left_knee_pitch": -0.5}, p), "'left_knee_pitch' = -0.5 rad is outside its URDF limits"),
    (lambda q, p: (q, (p[0], [1.0, 0.2, 0.0, 0.0])), "expected a unit quaternion"),
    (lambda q, p: (q, (p[0], np.diag([1.0, 1.0, -1.0]))), "the matrix is not a rotation"),
    (lambda q, p: (q, ([0.5, 0.0, 0.95], p[1])), "the root link jumped 0.5 m"),
    (lambda q, p: (q, (p[0], [np.cos(0.3), 0.0, 0.0, np.sin(0.3)])), "the root link turned"),
    (lambda q, p: ({**q, "right_hip_pitch": 0.9}, p), "joint 'right_hip_pitch' jumped 0.9 rad"),
    (lambda q, p: ({**q, "right_hip_pitch": float("nan")}, p), "'right_hip_pitch' is not a finite number"),
])
def test_a_bad_state_is_refused_naming_the_fault(external, change, fault):
    sim, q = external
    pose = ([0.0, 0.0, 0.95], [1.0, 0.0, 0.0, 0.0])
    bad_q, bad_pose = change(q, pose)
    before = sim.robot_state()
    with pytest.raises(proxsim.InputError) as error:
        sim.step(q=bad_q, X_WP=bad_pose)
    assert fault in str(error.value)
    # nothing moved: the sample was not taken, and a good state is still taken next
    assert sim.t_s == 0.0 and sim.robot_state()["t_s"] == before["t_s"]
    sim.step(q=q, X_WP=pose)
    assert sim.t_s == pytest.approx(0.01)


def test_the_first_sample_may_be_anywhere_and_reset_forgets_the_last_state(external):
    sim, q = external
    sim.reset()
    sim.step(q=q, X_WP=([3.0, 1.0, 0.95], [1.0, 0.0, 0.0, 0.0]))  # far from the last episode's state
    np.testing.assert_array_equal(sim.robot_state()["xyz"], [3.0, 1.0, 0.95])


def test_malformed_arguments_are_value_errors(external):
    sim, q = external
    with pytest.raises(ValueError, match="give the robot's state"):
        sim.step()
    with pytest.raises(ValueError, match="orientation"):
        sim.step(q=q, X_WP=([0.0, 0.0, 0.95], [1.0, 0.0, 0.0]))
    with pytest.raises(ValueError, match="support_leg"):
        sim.step(q=q, X_WP=([0.0, 0.0, 0.95], [1.0, 0.0, 0.0, 0.0]), support_leg="both")
    gait = proxsim.Simulation.builtin("paper")
    with pytest.raises(ValueError, match="moves by itself"):
        gait.step(q=q, X_WP=([0.0, 0.0, 0.95], [1.0, 0.0, 0.0, 0.0]))


def test_the_cli_refuses_to_run_an_external_robot_alone(tmp_path):
    source = read(scenario("paper_dining_room.yaml")).decode()
    path = tmp_path / "external.yaml"
    path.write_text(source.replace("robot:\n", "robot:\n  locomotion: external\n", 1))
    assert run_cli("validate", str(path)).returncode == 0
    result = run_cli("run", str(path), "--out", str(tmp_path / "out"), "--no-report")
    assert result.returncode == 2
    assert "robot.locomotion: external" in result.stderr
    assert not os.path.exists(tmp_path / "out" / "readings.csv")
    # the file's key drives the Python simulation the same way
    assert proxsim.Simulation(str(path)).external
    bad = tmp_path / "bad.yaml"
    bad.write_text(source.replace("robot:\n", "robot:\n  locomotion: outside\n", 1))
    result = run_cli("validate", str(bad))
    assert result.returncode == 2 and "expected gait" in result.stderr

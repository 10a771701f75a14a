"""The Python contract of proxsim.Simulation, against the real package and CLI."""
import json
import math
import os

import numpy as np
import pytest

import proxsim
from conftest import SCENARIOS, SOURCE_DIR, read_tree, run_cli, scenario

READING_KEYS = {"d_m", "detected", "fresh", "signal", "output", "t_reported_s", "origin_W", "dir_W"}
ROBOT_KEYS = {"pelvis_W", "yaw_deg", "joints_rad", "gait_phase", "support_leg", "soles_W", "toes_W", "heading_W",
              "stopped", "distance_walked_m"}


def assert_same_files(a_dir, b_dir):
    """The two folders hold the same files, byte for byte (timings.json and the report aside)."""
    a, b = read_tree(a_dir), read_tree(b_dir)
    assert sorted(a) == sorted(b)
    for name in a:
        assert a[name] == b[name], name


def test_step_returns_what_the_robot_knows(paper_sim):
    obs = paper_sim.step()
    assert obs["t_s"] == 0.0
    readings = obs["readings"]
    assert READING_KEYS <= set(readings)
    n = len(paper_sim.sensor_names)
    assert paper_sim.sensor_names == ["ideal", "laser", "ultrasonic", "reflectance"]
    for key in ("d_m", "detected", "signal", "output", "t_reported_s"):
        assert readings[key].shape == (n,), key
    assert readings["origin_W"].shape == (n, 3) and readings["dir_W"].shape == (n, 3)
    assert readings["detected"].dtype == bool
    # the axis is a unit vector; a time-of-flight sensor has no signal, the reflectance one has
    np.testing.assert_allclose(np.linalg.norm(readings["dir_W"], axis=1), 1.0, rtol=1e-12)
    assert math.isnan(readings["signal"][1]) and not math.isnan(readings["signal"][3])
    robot = obs["robot"]
    assert ROBOT_KEYS <= set(robot)
    assert robot["pelvis_W"].shape == (3,) and robot["heading_W"].shape == (3,)
    assert set(robot["soles_W"]) == {"left", "right"} and robot["toes_W"]["left"].shape == (3,)
    assert robot["support_leg"] in ("left", "right", "double")
    assert "left_knee_pitch" in robot["joints_rad"]
    # no truth in what the robot knows
    for forbidden in ("status", "d_true_m", "hit_W", "object", "incidence_deg"):
        assert forbidden not in readings and forbidden not in robot


def test_truth_is_apart_and_agrees_with_the_readings(paper_sim):
    obs = paper_sim.step()
    truth = paper_sim.truth()
    assert truth["status"][0] == "ok" and truth["object"][0] == "floor"
    # the ideal sensor reports the true distance
    assert obs["readings"]["d_m"][0] == pytest.approx(truth["d_true_m"][0], abs=1e-12)
    # its hit point lies at that distance along its axis
    r = obs["readings"]
    np.testing.assert_allclose(truth["hit_W"][0], r["origin_W"][0] + truth["d_true_m"][0] * r["dir_W"][0], atol=1e-9)


def test_steps_to_the_end_then_raises(paper_sim):
    count = 0
    while not paper_sim.done:
        paper_sim.step()
        count += 1
    assert count == paper_sim.sample_count == 500
    assert paper_sim.t_s == pytest.approx(4.99)
    with pytest.raises(RuntimeError, match="every sample"):
        paper_sim.step()


def test_out_writes_the_same_files_as_the_cli(tmp_path):
    cli_out, py_out = tmp_path / "cli", tmp_path / "py"
    done = run_cli("run", scenario("circumvent_obstacle.yaml"), "--seed", "5", "--out", str(cli_out), "--no-report")
    assert done.returncode == 0, done.stderr
    with proxsim.Simulation(scenario("circumvent_obstacle.yaml"), seed=5, out=str(py_out)) as sim:
        while not sim.done:
            sim.step()
    assert_same_files(cli_out, py_out)
    assert os.path.exists(py_out / "timings.json")


def test_a_python_runs_folder_lists_its_timings_and_can_be_redrawn(tmp_path):
    out = tmp_path / "py"
    with proxsim.Simulation.builtin("paper", seed=4, out=str(out)) as sim:
        while not sim.done:
            sim.step()
    with open(out / "manifest.json") as f:
        listed = json.load(f)
    names = [entry["path"] if isinstance(entry, dict) else entry for entry in listed["files"]]
    assert "timings.json" in names
    done = run_cli("plot", str(out))
    assert done.returncode == 0, done.stderr
    assert os.path.exists(out / "report" / "paper_figures.png")


def test_reset_gives_the_files_of_a_fresh_simulation(tmp_path):
    fresh, reused = tmp_path / "fresh", tmp_path / "reused"
    with proxsim.Simulation.builtin("paper", seed=9, out=str(fresh)) as sim:
        while not sim.done:
            sim.step()
    with proxsim.Simulation.builtin("paper", seed=3, out=str(reused)) as sim:
        for _ in range(321):  # part of another episode, with commands
            sim.step()
        sim.robot.set_stride(0.4)
        sim.reset(seed=9)
        assert sim.seed == 9 and not sim.done
        while not sim.done:
            sim.step()
    assert_same_files(fresh, reused)


def test_summary_has_the_robot_outcome_and_events(paper_sim):
    while not paper_sim.done:
        paper_sim.step()
    robot = paper_sim.summary()["robot"]
    assert robot["strategy"] == "stop"
    assert robot["stopped"] and robot["stop_t_s"] == pytest.approx(3.6)
    assert [e["event"] for e in robot["events"]] == ["obstacle_ahead", "stopped"]
    assert robot["reached_goal"] is False


def test_commands_change_the_walk():
    with proxsim.Simulation.builtin("paper", scenario_strategy=False) as sim:
        assert sim.summary()["robot"]["strategy"] is None
        for _ in range(100):
            obs = sim.step()
        sim.robot.stop()
        for _ in range(150):
            obs = sim.step()
        assert obs["robot"]["stopped"]
        x_stopped = obs["robot"]["pelvis_W"][0]
        sim.robot.resume()
        sim.robot.set_path([[x_stopped + 0.5, 1.0], [x_stopped + 1.0, 1.5]])
        for _ in range(200):
            obs = sim.step()
        assert not obs["robot"]["stopped"] or obs["robot"]["pelvis_W"][1] > 0.5
        # it turned toward the new path (y > 0; 0.28 m by now: the first step of
        # the turn is slowed for its trailing knee to leave full reach within
        # its top speed, docs/robots.md)
        assert obs["robot"]["pelvis_W"][1] > 0.2


def test_world_sensors_have_no_robot():
    with proxsim.Simulation(scenario("world_sensors_demo.yaml")) as sim:
        obs = sim.step()
        assert obs["robot"] is None and sim.robot is None
        assert obs["readings"]["d_m"].shape == (len(sim.sensor_names),)


def test_bad_scenario_raises_input_error_with_the_cli_messages(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("proxsim: 1\nduration_s: -1\nsensors:\n  - {name: a, type: lazer, link: world}\n")
    with pytest.raises(proxsim.InputError) as error:
        proxsim.Simulation(str(bad))
    cli = run_cli("validate", str(bad))
    assert cli.returncode == 2
    assert len(error.value.problems) >= 2
    for problem in error.value.problems:
        assert problem in cli.stderr
    assert isinstance(error.value, ValueError)
    with pytest.raises(proxsim.InputError, match="no such file"):
        proxsim.Simulation(str(tmp_path / "missing.yaml"))
    with pytest.raises(proxsim.InputError):
        proxsim.Simulation.builtin("no_such_builtin")


def test_a_start_on_an_object_is_an_input_error_naming_it_unless_on_says_so():
    # a box under the robot's feet (feet stand only on ground): refused as the CLI refuses it (exit 2),
    # naming the box and the links in it
    bad = os.path.join(SOURCE_DIR, "tests", "data", "bad_input", "start_on_crate.yaml")
    with pytest.raises(proxsim.InputError, match="starts inside object 'crate': links .*'left_foot'"):
        proxsim.Simulation(bad)
    assert run_cli("validate", bad).returncode == 2
    # the same box started on on purpose
    with proxsim.Simulation(os.path.join(SOURCE_DIR, "tests", "data", "cli", "start_on_crate_on_purpose.yaml")) as sim:
        sim.step()


def test_a_scenario_with_no_sensors_measures_nothing_and_is_refused(tmp_path):
    empty = tmp_path / "empty.yaml"
    empty.write_text("proxsim: 1\nduration_s: 1\n")
    with pytest.raises(proxsim.InputError, match="no sensors: nothing to measure"):
        proxsim.Simulation(str(empty))
    assert run_cli("validate", str(empty)).returncode == 2


def test_wrong_arguments_raise_type_and_value_errors(paper_sim):
    with pytest.raises(TypeError):
        proxsim.Simulation(42)
    with pytest.raises(TypeError):
        proxsim.Simulation.builtin("paper", seed="seven")
    with pytest.raises(ValueError):
        proxsim.Simulation.builtin("paper", threads=0)
    with pytest.raises(ValueError):
        paper_sim.robot.set_stride(-0.5)
    with pytest.raises(ValueError):
        paper_sim.robot.set_stride(float("nan"))
    with pytest.raises(ValueError):
        paper_sim.robot.set_path([[1.0, 2.0, 3.0]])
    with pytest.raises(ValueError):
        paper_sim.robot.set_path([[1.0, float("inf")]])
    with pytest.raises(TypeError):
        paper_sim.robot.set_stride("long")


def test_closed_simulation_refuses_to_step(tmp_path):
    sim = proxsim.Simulation.builtin("paper", out=str(tmp_path / "o"))
    sim.step()
    sim.close()
    sim.close()  # twice is harmless
    with pytest.raises(RuntimeError, match="closed"):
        sim.step()
    # closed before the end: the files say so
    import json

    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["interrupted"] is True and summary["samples"] == 1


def test_threads_do_not_change_the_readings():
    runs = []
    for threads in (1, 2):
        with proxsim.Simulation.builtin("paper", threads=threads) as sim:
            runs.append(np.array([sim.step()["readings"]["d_m"] for _ in range(200)]))
    np.testing.assert_array_equal(runs[0], runs[1])


def test_a_strategy_that_steers_into_the_table_collides_naming_the_table_and_the_link():
    # the paper's robot, its path turned toward the dining table (top at 0.75 m over (2.0, 1.3))
    with proxsim.Simulation.builtin("paper", scenario_strategy=False) as sim:
        while not sim.done:
            if sim.step()["t_s"] == pytest.approx(0.5):
                sim.robot.set_path([[2.0, 1.3]])
        robot = sim.summary()["robot"]
    assert robot["outcome"] == "collided", robot["outcome_detail"]
    first = robot["collisions"][0]
    assert first["object"].startswith("table"), first
    assert first["link"] in {"pelvis", "left_thigh", "right_thigh", "left_tibia", "right_tibia", "left_foot",
                             "right_foot"}, first
    assert robot["outcome_t_s"] < 5.0  # the episode ended there, before its time ran out


def test_a_multizone_sensor_gives_its_zones_by_name():
    sim = proxsim.Simulation(os.path.join(SCENARIOS, "multizone_shins.yaml"))
    obs = sim.step()
    assert obs["readings"]["zones"].keys() == {"tof_left_shin", "tof_right_shin"}
    zones = obs["readings"]["zones"]["tof_left_shin"]
    assert zones["d_m"].shape == (64, 1) and zones["status"].shape == (64, 1)
    assert zones["status"].dtype == np.uint8 and zones["target_count"].shape == (64,)
    np.testing.assert_allclose(np.linalg.norm(zones["dir_W"], axis=1), 1.0, rtol=1e-12)
    # ST's codes: a zone with a target reads 5 and a distance within the part's range, the others none
    valid = zones["status"][:, 0] == 5
    assert valid.any()
    assert np.all(zones["target_count"][valid] == 1) and np.all(zones["target_count"][~valid] == 0)
    assert np.all((zones["d_m"][valid, 0] > 0.02) & (zones["d_m"][valid, 0] < 4.0))
    # the sensor's own reading is its nearest zone's target
    i = sim.sensor_names.index("tof_left_shin")
    assert obs["readings"]["d_m"][i] == pytest.approx(zones["d_m"][valid, 0].min(), abs=0)
    # the same zones in the one shape every part reports in: one measurement per zone here (one target each)
    listed = obs["readings"]["measurements"]["tof_left_shin"]
    np.testing.assert_array_equal(listed["group"], np.arange(64))
    np.testing.assert_array_equal(listed["rank"], np.zeros(64))
    np.testing.assert_array_equal(listed["detected"], valid)
    np.testing.assert_array_equal(listed["code"], zones["status"][:, 0])
    np.testing.assert_array_equal(listed["d_m"][valid], zones["d_m"][valid, 0])
    np.testing.assert_array_equal(listed["dir_W"], zones["dir_W"])
    # the paper's sensors have no zones, and report nothing beside their readings
    paper = proxsim.Simulation.builtin("paper").step()["readings"]
    assert paper["zones"] == {} and paper["measurements"] == {}


def test_a_beam_with_several_echoes_gives_them_by_name(tmp_path):
    # a sonar facing a 3 cm pole 0.5 m ahead of a wall 1.5 m ahead: the pole's face on the axis ray,
    # the wall on the 5° ring (docs/sensors.md#several-echoes; tests/echoes_test.cc)
    path = tmp_path / "echoes.yaml"
    path.write_text(
        "proxsim: 1\nduration_s: 0.2\nrate_hz: 10\nscene:\n  objects:\n"
        "    - {name: pole, box: {size_m: [0.03, 0.03, 2]}, pose: {xyz_m: [0.5, 0, 1]}}\n"
        "    - {name: wall, box: {size_m: [0.02, 4, 3]}, pose: {xyz_m: [1.51, 0, 1]}}\n"
        "sensors:\n  - {name: sonar, type: ultrasonic, range_m: [0.02, 3], max_incidence_deg: 20,"
        " noise: {sigma: 0}, beam: {aperture_deg: 30, rays: 37}, echoes: all, pose: {xyz_m: [0, 0, 1]}}\n")
    obs = proxsim.Simulation(str(path)).step()
    echoes = obs["readings"]["echoes"]["sonar"]
    assert echoes["count"] == 2
    assert echoes["d_m"].shape == (4,) and echoes["signal"].shape == (4,)
    np.testing.assert_allclose(echoes["d_m"][:2], [0.485, 1.5 / math.cos(math.radians(5))], atol=1e-6)
    assert np.isnan(echoes["d_m"][2:]).all() and np.isnan(echoes["signal"][2:]).all()
    assert echoes["signal"][1] > echoes["signal"][0]  # the wall fills 34 of the 37 rays
    assert obs["readings"]["d_m"][0] == pytest.approx(0.485, abs=1e-6)  # the reading is the first echo
    # the same echoes in the one shape every part reports in: along the beam's axis, nearest first
    listed = obs["readings"]["measurements"]["sonar"]
    np.testing.assert_array_equal(listed["d_m"], echoes["d_m"][:2])
    np.testing.assert_array_equal(listed["rank"], [0, 1])
    np.testing.assert_allclose(listed["dir_W"], [[1, 0, 0], [1, 0, 0]], atol=1e-12)
    # the paper's sensors report one echo each
    assert proxsim.Simulation.builtin("paper").step()["readings"]["echoes"] == {}


def test_config_keys_are_the_declared_sections_as_dicts():
    """proxsim.config_keys gives each section's keys as the docs' tables do."""
    assert proxsim.config_sections() == ["material", "map", "robot", "robot.gait", "strategy.stop", "strategy.circumvent"]
    keys = {k["key"]: k for k in proxsim.config_keys("map")}
    assert keys["resolution_m"]["min"] == 0.005 and keys["resolution_m"]["max"] == 1.0
    assert keys["resolution_m"]["unit"] == "m" and keys["resolution_m"]["default"] == "0.02"
    stop = {k["key"]: k for k in proxsim.config_keys("strategy.stop")}
    assert stop["perception"]["choices"] == ["readings", "map"]
    assert stop["stop_distance_m"]["min"] == 0.0 and stop["stop_distance_m"]["min_open"]
    # every declared key of a section appears in a run's summary echo of it
    sim = proxsim.Simulation.builtin("paper", seed=1)
    echoed = sim.summary()["inputs"]["map"]
    assert set(keys) == set(echoed)
    with pytest.raises(ValueError, match="expected one of material, map"):
        proxsim.config_keys("nope")

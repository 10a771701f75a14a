"""The shipped examples run, and the Python stop rule equals the built-in one."""
import os
import subprocess
import sys

import numpy as np
import pytest

import proxsim
from conftest import SOURCE_DIR, scenario

EXAMPLES = os.path.join(SOURCE_DIR, "examples", "python")
sys.path.insert(0, EXAMPLES)

import stop_rule  # noqa: E402


def test_python_stop_rule_stops_when_the_builtin_rule_does():
    with proxsim.Simulation.builtin("paper") as sim:
        while not sim.done:
            sim.step()
        builtin = sim.summary()["robot"]
    python = stop_rule.run()["robot"]
    assert python["strategy"] is None
    assert python["stop_requested_t_s"] is not None
    assert python["stop_requested_t_s"] == builtin["stop_requested_t_s"]
    assert python["stop_t_s"] == builtin["stop_t_s"]
    assert python["distance_walked_m"] == builtin["distance_walked_m"]


@pytest.mark.parametrize("script", ["stop_rule.py", "circumvent.py", "map_hazard_stop.py"])
def test_example_scripts_run(script, tmp_path):
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), "--out", str(tmp_path / "out")],
                          capture_output=True, text=True, timeout=300, env=os.environ.copy())
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "out" / "summary.json").exists()
    if script == "circumvent.py":
        assert "reached the goal: True" in done.stdout
    if script == "map_hazard_stop.py":  # the map's obstacle stops the robot
        assert "the map holds an obstacle" in done.stdout and "stopped: True" in done.stdout


def test_h1_driven_from_a_mujoco_qpos_log(tmp_path):
    # the example makes its qpos log from proxsim's gait, then drives an external run from it
    # (the H1 is read in place from ../shared/robots, beside the project, as the other H1 tests do)
    if not os.path.isdir(os.path.join(SOURCE_DIR, "..", "shared", "robots", "h1_description")):
        pytest.skip("../shared/robots/h1_description is not here")
    script = os.path.join(EXAMPLES, "h1_mujoco_qpos.py")
    done = subprocess.run([sys.executable, script, "--out", str(tmp_path / "out")], capture_output=True, text=True,
                          timeout=300, env=os.environ.copy())
    assert done.returncode == 0, done.stderr
    assert "the obstacle first detected by" in done.stdout and "stop rule asks the robot to stop" in done.stdout
    assert (tmp_path / "out" / "readings.csv").exists()
    log = tmp_path / "out-log" / "h1_qpos.csv"
    qpos = np.loadtxt(log, delimiter=",", ndmin=2)
    assert qpos.shape[1] == 1 + 7 + 19  # t_s, the free joint, the 19 hinges

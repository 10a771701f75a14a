"""Issue 40's Python cases: the robot's state before any sample, one VecWalkEnv shared by threads,
and arguments that are NaN or empty, each refused with an exception naming it."""
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import proxsim


@pytest.mark.parametrize("locomotion", [None, "external"])
def test_robot_state_before_the_first_step_and_after_reset_raises(locomotion):
    # it once read an empty joint vector: SIGSEGV
    with proxsim.Simulation.builtin("paper", locomotion=locomotion) as sim:
        with pytest.raises(RuntimeError, match="robot_state: no sample taken yet"):
            sim.robot_state()
        if locomotion is None:
            sim.step()
            assert sim.robot_state()["q"].size == len(sim.joint_names)
            sim.reset()
            with pytest.raises(RuntimeError, match="call step\\(\\) first"):
                sim.robot_state()


def test_one_vec_walk_env_stepped_and_reset_from_two_threads():
    # step() and reset() release the GIL; without the core's lock a reset under a step freed what it read
    env = proxsim.VecWalkEnv("builtin:paper", num_envs=2, threads=1)
    env.reset(seed=1)
    failures = []
    stop = threading.Event()
    actions = np.array([[1.0, 0.6], [1.0, 0.6]])

    def stepper():
        try:
            while not stop.is_set():
                env.step(actions)
        except Exception as error:  # noqa: BLE001 - any failure is the test's
            failures.append(error)

    def resetter():
        try:
            for seed in range(30):
                env.reset(seed=seed)
        except Exception as error:  # noqa: BLE001
            failures.append(error)

    threads = [threading.Thread(target=stepper), threading.Thread(target=resetter)]
    for t in threads:
        t.start()
    threads[1].join(timeout=120)
    stop.set()
    threads[0].join(timeout=120)
    assert not any(t.is_alive() for t in threads), "a thread hung"
    assert failures == []


@pytest.mark.parametrize("make, message", [
    (lambda: proxsim.WalkEnv("builtin:paper", collision_penalty=float("nan")), "collision_penalty: expected a finite"),
    (lambda: proxsim.WalkEnv("builtin:paper", fall_penalty=float("inf")), "fall_penalty: expected a finite"),
    (lambda: proxsim.VecWalkEnv("builtin:paper", 1, collision_penalty=float("nan")), "collision_penalty"),
    (lambda: proxsim.Simulation.builtin("paper", out=""), "out: an empty path"),
])
def test_nan_penalties_and_an_empty_out_are_refused(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_a_nan_action_is_refused_naming_it():
    env = proxsim.WalkEnv("builtin:paper")
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"action\[0\] \(walk\) is nan"):
        env.step([float("nan"), 0.5])
    vec = proxsim.VecWalkEnv("builtin:paper", 1)
    vec.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions\[0\]\[1\] \(stride_m\) is nan"):
        vec.step(np.array([[1.0, float("nan")]]))


_FAR_STEP = """
import numpy as np, proxsim
sim = proxsim.Simulation.builtin("paper", locomotion="external")
try:
    sim.step(q=np.zeros(len(sim.joint_names)), X_WP=([{x!r}, 0, 0.9], [1, 0, 0, 0]))
    print("accepted")
except proxsim.InputError as error:
    print(error)
"""


@pytest.mark.parametrize("x_m", [5e7, 1e17])
def test_a_co_simulated_robot_beyond_the_coordinate_limit_is_refused_in_bounded_memory(x_m):
    # at 5e7 m the first step allocated 8.5 GB; at 1e17 m terrain/*.npy was written empty; now a 1.5 GB
    # address space suffices for the refusal
    result = subprocess.run(["prlimit", f"--as={1536 << 20}", sys.executable, "-c", _FAR_STEP.format(x=x_m)],
                            capture_output=True, text=True, timeout=120, env=os.environ)
    assert result.returncode == 0, result.stderr
    assert "X_WP: the position" in result.stdout and "beyond the coordinate limit of ±100000 m" in result.stdout

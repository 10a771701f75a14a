"""proxsim.WalkEnv follows Gymnasium's API: spaces, reset, step, termination."""
import numpy as np
import pytest

import proxsim
from conftest import scenario


def test_spaces_and_reset():
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"))
    n = len(env.simulation.sensor_names)
    assert env.observation_space.shape == (3 * n + 6,)
    assert env.action_space.shape == (2,)
    obs, info = env.reset(seed=4)
    assert obs.shape == env.observation_space.shape and obs.dtype == np.float32
    assert env.observation_space.contains(obs)
    assert info["t_s"] == 0.0
    env.close()


def test_walking_earns_progress_and_standing_earns_none():
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"))
    env.reset(seed=1)
    walked = sum(env.step(np.array([1.0, 0.6], dtype=np.float32))[1] for _ in range(200))
    assert walked > 0.5  # metres toward the goal
    for _ in range(150):
        env.step(np.array([0.0, 0.6], dtype=np.float32))  # stop, then stand
    standing = sum(env.step(np.array([0.0, 0.6], dtype=np.float32))[1] for _ in range(50))
    assert standing == pytest.approx(0.0, abs=1e-9)


def test_walking_into_the_obstacle_terminates():
    # the paper's walk without its stop rule: the robot walks into the obstacle at x = 2.5 m
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"))
    env.reset(seed=1)
    terminated = truncated = False
    reward = 0.0
    while not (terminated or truncated):
        _, reward, terminated, truncated, info = env.step(np.array([1.0, 0.6], dtype=np.float32))
    assert terminated and not truncated
    assert info["collided"] and not info["reached_goal"]
    assert reward < -5  # the collision penalty
    assert env.simulation.truth()["min_clearance_m"] <= 0.0


def test_standing_still_is_truncated_at_the_end():
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"))
    env.reset(seed=1)
    steps, terminated, truncated = 0, False, False
    while not (terminated or truncated):
        _, _, terminated, truncated, _ = env.step(np.array([0.0, 0.6], dtype=np.float32))
        steps += 1
    assert truncated and not terminated
    assert steps == env.simulation.sample_count - 1  # reset took the first sample


def test_bad_action_is_a_value_error():
    env = proxsim.WalkEnv("builtin:paper")
    env.reset()
    with pytest.raises(ValueError):
        env.step([1.0])
    with pytest.raises(ValueError):
        env.step([np.nan, 0.5])


def test_sample_actions_run():
    env = proxsim.WalkEnv("builtin:paper")
    env.reset(seed=2)
    for _ in range(20):
        action = env.action_space.sample()
        assert env.action_space.contains(action)
        env.step(action)

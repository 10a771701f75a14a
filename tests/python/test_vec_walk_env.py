"""proxsim.VecWalkEnv: N WalkEnv episodes stepped together in C++ threads equal N separate
WalkEnvs exactly (observations, rewards, flags, auto-resets and their seeds), with Gymnasium's
vector-environment API."""
import os

import numpy as np
import pytest

import proxsim
from conftest import scenario


@pytest.fixture(scope="module")
def short_walk(tmp_path_factory):
    """The paper's walk cut to 1.5 s, so that episodes end (truncated) and auto-reset within the test."""
    with open(scenario("paper_dining_room.yaml")) as f:
        text = f.read()
    assert "duration_s: 5.0" in text
    path = tmp_path_factory.mktemp("vec") / "short_walk.yaml"
    path.write_text(text.replace("duration_s: 5.0", "duration_s: 1.5"))
    return str(path)


def actions_for(rng, n):
    # mostly walking with a stride drawn anew, sometimes a stop: stop and resume are exercised
    walk = (rng.uniform(size=n) < 0.9).astype(np.float32)
    stride = rng.uniform(0.2, 1.1, size=n).astype(np.float32)  # beyond both clip limits too
    return np.stack([walk, stride], axis=1)


@pytest.mark.parametrize("num_envs, threads", [(1, 1), (8, 2), (64, 2)])
def test_equals_separate_walk_envs(short_walk, num_envs, threads):
    vec = proxsim.VecWalkEnv(short_walk, num_envs, threads)
    singles = [proxsim.WalkEnv(short_walk) for _ in range(num_envs)]
    seed = 11
    obs, infos = vec.reset(seed=seed)
    seeds = [seed + i for i in range(num_envs)]
    expected = np.stack([env.reset(seed=s)[0] for env, s in zip(singles, seeds)])
    np.testing.assert_array_equal(obs, expected)
    np.testing.assert_array_equal(infos["episode_seed"], seeds)
    rng = np.random.default_rng(num_envs)
    autoreset = np.zeros(num_envs, dtype=bool)
    ended = 0
    for _ in range(400):  # 1.5 s episodes at 100 Hz: every environment resets twice or more
        actions = actions_for(rng, num_envs)
        obs, rewards, terminations, truncations, infos = vec.step(actions)
        assert obs.shape == (num_envs, vec.single_observation_space.shape[0]) and obs.dtype == np.float32
        for i, env in enumerate(singles):
            if autoreset[i]:  # Gymnasium's next-step auto-reset, with the environment's next seed
                seeds[i] += num_envs
                o, r, te, tr = env.reset(seed=seeds[i])[0], 0.0, False, False
            else:
                o, r, te, tr, info = env.step(actions[i])
                assert infos["outcome"][i] == info["outcome"]
            np.testing.assert_array_equal(obs[i], o)
            assert rewards[i] == r and terminations[i] == te and truncations[i] == tr
            assert infos["episode_seed"][i] == seeds[i]
        autoreset = terminations | truncations
        ended += int(autoreset.sum())
    assert ended >= 2 * num_envs


def test_thread_count_does_not_change_the_numbers(short_walk):
    runs = []
    for threads in (1, 2):
        vec = proxsim.VecWalkEnv(short_walk, 8, threads)
        vec.reset(seed=3)
        rng = np.random.default_rng(0)
        runs.append([vec.step(actions_for(rng, 8))[:2] for _ in range(60)])
    for (obs_1, rewards_1), (obs_2, rewards_2) in zip(*runs):
        np.testing.assert_array_equal(obs_1, obs_2)
        np.testing.assert_array_equal(rewards_1, rewards_2)


def test_gymnasium_vector_api(short_walk):
    vec = proxsim.VecWalkEnv(short_walk, 4, threads=1)
    single = proxsim.WalkEnv(short_walk)
    assert vec.num_envs == 4
    assert vec.single_observation_space.shape == single.observation_space.shape
    assert vec.single_action_space.shape == (2,)
    assert vec.observation_space.shape == (4,) + single.observation_space.shape
    assert vec.action_space.shape == (4, 2)
    assert vec.metadata["autoreset_mode"] in ("NextStep",) or str(vec.metadata["autoreset_mode"]).endswith("NEXT_STEP")
    obs, infos = vec.reset(seed=[5, 6, 7, 9])
    assert vec.observation_space.contains(obs)
    np.testing.assert_array_equal(infos["episode_seed"], [5, 6, 7, 9])
    obs, rewards, terminations, truncations, infos = vec.step(vec.action_space.sample())
    assert rewards.shape == terminations.shape == truncations.shape == (4,)
    for key in ("t_s", "outcome", "collided", "fell", "reached_goal", "episode_seed"):
        assert infos[key].shape == (4,) and infos["_" + key].all()
    # without a seed, each environment goes on with its next one
    _, infos = vec.reset()
    np.testing.assert_array_equal(infos["episode_seed"], [9, 10, 11, 13])
    vec.close()
    assert vec.closed


def test_bad_arguments_are_named(short_walk):
    vec = proxsim.VecWalkEnv(short_walk, 2)
    with pytest.raises(RuntimeError, match="reset"):
        vec.step(np.zeros((2, 2)))
    vec.reset()
    with pytest.raises(ValueError, match=r"shape \(2, 2\)"):
        vec.step(np.zeros((3, 2)))
    with pytest.raises(ValueError, match=r"actions\[1\]\[0\] \(walk\) is nan: expected a finite number"):
        vec.step(np.array([[1.0, 0.6], [np.nan, 0.6]]))
    with pytest.raises(ValueError, match="expected 2 seeds"):
        vec.reset(seed=[1, 2, 3])
    with pytest.raises(ValueError, match="num_envs"):
        proxsim.VecWalkEnv(short_walk, 0)
    with pytest.raises(proxsim.InputError):
        proxsim.VecWalkEnv(scenario("no_such_file.yaml"), 2)
    with pytest.raises(ValueError, match="robot"):
        proxsim.VecWalkEnv("builtin:world_demo", 2)


def test_its_environments_share_one_load_of_the_robot():
    """N environments of the H1 read its 21 meshes once, not N times: the bytes the process reads
    while VecWalkEnv builds 4 of them (/proc/self/io's rchar) stay below twice the meshes' size."""
    h1 = scenario("h1_dining_room.yaml")
    meshes = os.path.join(os.path.dirname(h1), "..", "..", "..", "shared", "robots", "h1_description", "meshes")
    if not os.path.isdir(meshes):
        pytest.skip("../shared/robots/h1_description is not here")
    mesh_bytes = sum(os.path.getsize(os.path.join(meshes, name)) for name in os.listdir(meshes))

    def bytes_read():
        with open("/proc/self/io") as io:
            return int(next(line for line in io if line.startswith("rchar:")).split()[1])

    before = bytes_read()
    envs = proxsim.VecWalkEnv(h1, num_envs=4, threads=2)
    read = bytes_read() - before
    assert envs.num_envs == 4
    assert mesh_bytes < read < 2 * mesh_bytes, (read, mesh_bytes)
    envs.close()

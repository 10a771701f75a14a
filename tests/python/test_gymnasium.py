"""WalkEnv and VecWalkEnv against Gymnasium itself (python/requirements.txt pins it; .venv/ has it):
Gymnasium's own environment checker passes on WalkEnv, and VecWalkEnv declares the auto-reset mode
with Gymnasium 1.x's own enum, the one its vector wrappers read."""
import gymnasium
import numpy as np
from gymnasium.utils.env_checker import check_env
from gymnasium.vector import AutoresetMode

import proxsim
from conftest import scenario


def test_walk_env_passes_gymnasiums_env_checker():
    # without info["raw"]: the checker compares two runs' infos with ==, and the raw observation
    # holds NaN for values that are none (a laser's signal), which is never equal to itself
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"), raw_info=False)
    assert isinstance(env, gymnasium.Env)
    # spaces, reset/step signatures and dtypes, seeding (the same seed gives the same episode)
    check_env(env, skip_render_check=True)
    env.close()


def test_the_raw_observation_is_as_deterministic_nan_for_nan():
    # what the checker cannot compare, compared here with NaN equal to NaN
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"))
    action = np.array([1.0, 0.6], dtype=np.float32)
    runs = []
    for _ in range(2):
        _, first = env.reset(seed=123)
        _, _, _, _, info = env.step(action)
        runs.append((first["raw"], info["raw"]))
    np.testing.assert_equal(runs[0], runs[1])
    assert np.isnan(runs[0][1]["readings"]["signal"]).any()  # the NaN the checker trips on is there
    env.close()


def test_vec_walk_env_declares_gymnasiums_next_step_autoreset():
    assert proxsim.VecWalkEnv.metadata["autoreset_mode"] is AutoresetMode.NEXT_STEP

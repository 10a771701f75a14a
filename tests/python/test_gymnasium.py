"""WalkEnv and VecWalkEnv against Gymnasium itself (python/requirements.txt pins it; .venv/ has it):
Gymnasium's own environment checker passes on WalkEnv, and VecWalkEnv declares the auto-reset mode
with Gymnasium 1.x's own enum, the one its vector wrappers read."""
import gymnasium
from gymnasium.utils.env_checker import check_env
from gymnasium.vector import AutoresetMode

import proxsim
from conftest import scenario


def test_walk_env_passes_gymnasiums_env_checker():
    env = proxsim.WalkEnv(scenario("paper_dining_room.yaml"))
    assert isinstance(env, gymnasium.Env)
    # spaces, reset/step signatures and dtypes, seeding (the same seed gives the same episode)
    check_env(env, skip_render_check=True)
    env.close()


def test_vec_walk_env_declares_gymnasiums_next_step_autoreset():
    assert proxsim.VecWalkEnv.metadata["autoreset_mode"] is AutoresetMode.NEXT_STEP

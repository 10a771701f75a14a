"""N WalkEnv episodes stepped together in C++ threads, with Gymnasium's vector-environment API.

    envs = proxsim.VecWalkEnv("data/scenarios/paper_dining_room.yaml", num_envs=64, threads=2)
    obs, infos = envs.reset(seed=3)          # obs: float32 (64, 3·n_sensors + 6); env i seeded 3 + i
    obs, rewards, terminations, truncations, infos = envs.step(envs.action_space.sample())

Every environment is WalkEnv's task (observation, action, reward, termination: see walk_env.py),
computed in C++ with the same arithmetic: environment i gives exactly the numbers of a WalkEnv
reset with the same seeds and given the same actions. The simulations are stepped on `threads`
threads with the GIL released; each has one thread of its own for its rays.

Auto-reset (Gymnasium's "next step" mode, metadata["autoreset_mode"]): when an episode ends,
the next step() resets that environment, ignoring its action, and returns the first observation
of its next episode with reward 0 and both flags false. Seeds: environment i's episodes are seeded
s_i, s_i + N, s_i + 2N, ... where s_i = seed + i after reset(seed=seed) (or seed[i] for a list of
N seeds), and the scenario's seed + i before any seeded reset: all distinct, and the same whatever
the thread count.

infos: arrays over the environments (each with its "_key" mask, all true): t_s, outcome (as
summary.json's robot.outcome), collided, fell, reached_goal, episode_seed.
"""
import numpy as np

from ._core import VecWalkCore
from .spaces import Box
from .walk_env import (COLLISION_PENALTY, FALL_PENALTY, MAX_STRIDE_M, MIN_STRIDE_M, check_penalties, check_strides,
                       walk_spaces)

try:
    from gymnasium.vector import AutoresetMode

    _NEXT_STEP = AutoresetMode.NEXT_STEP
except ImportError:  # no Gymnasium, or one older than 1.0: its name for the mode
    _NEXT_STEP = "NextStep"


def _batched(space, n):
    """A Box of n copies of `space` along a new first axis (Gymnasium's batch_space)."""
    return Box(np.broadcast_to(space.low, (n,) + space.shape), np.broadcast_to(space.high, (n,) + space.shape),
               dtype=space.dtype)


class VecWalkEnv:
    metadata = {"render_modes": [], "autoreset_mode": _NEXT_STEP}
    render_mode = None
    spec = None

    def __init__(self, scenario, num_envs, threads=1, *, min_stride_m=MIN_STRIDE_M, max_stride_m=MAX_STRIDE_M,
                 collision_penalty=COLLISION_PENALTY, fall_penalty=FALL_PENALTY):
        check_strides(min_stride_m, max_stride_m)
        check_penalties(collision_penalty, fall_penalty)
        for name, value in (("num_envs", num_envs), ("threads", threads)):
            if not isinstance(value, (int, np.integer)) or isinstance(value, bool):
                raise TypeError(f"{name}: expected an int, got {value!r}")
        self._core = VecWalkCore(str(scenario), int(num_envs), int(threads), float(min_stride_m),
                                 float(max_stride_m), float(collision_penalty), float(fall_penalty))
        self.num_envs = int(num_envs)
        self.single_observation_space, self.single_action_space = walk_spaces(
            len(self._core.sensor_names), min_stride_m, max_stride_m)
        self.observation_space = _batched(self.single_observation_space, self.num_envs)
        self.action_space = _batched(self.single_action_space, self.num_envs)
        self.closed = False

    @property
    def sensor_names(self):
        return self._core.sensor_names

    @property
    def unwrapped(self):
        return self

    @property
    def last_cpp_s(self):
        """Wall time of the last reset/step's work in C++ (the GIL released), seconds."""
        return self._core.last_cpp_s

    def reset(self, *, seed=None, options=None):
        """Starts every environment's next episode: seed None (each one's next seed), an int s
        (environment i seeded s + i) or a list of num_envs ints. Returns (obs, infos)."""
        if seed is None:
            seeds = None
        elif isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        else:
            seeds = [int(s) for s in seed]
        if seed is not None:
            self.action_space.seed(seeds[0])
        return self._core.reset(seeds)

    def step(self, actions):
        """actions: (num_envs, 2) [walk, stride_m] rows. Returns (obs, rewards, terminations,
        truncations, infos), each with a leading num_envs axis."""
        return self._core.step(actions)

    def close(self, **kwargs):
        self.closed = True

    def __enter__(self):
        return self

    def __exit__(self, *args):
        self.close()

"""A Gymnasium-style environment around proxsim.Simulation: a biped walks a
scenario's path while an agent decides, at every sample, whether it walks and
with what stride, from what its sensors and its own kinematics tell it.

    env = proxsim.WalkEnv("data/scenarios/paper_dining_room.yaml")
    obs, info = env.reset(seed=3)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

Observation (float32, shape (3·n_sensors + 6,)): for each sensor, in scenario
order, [d_m, detected, fresh]; then [pelvis x_m, pelvis y_m, yaw_rad,
gait_phase, stopped, distance_walked_m]. Sensors only, never the truth.

The agent drives the robot: the scenario's own strategy is dropped.

Action (float32, shape (2,)): [walk, stride_m]: walk >= 0.5 walks (a robot
that stood resumes), < 0.5 stops at the next double support; stride_m, clipped
to [min_stride_m, max_stride_m], is the stride from the next step on.

Reward: the metres gained toward the path's last waypoint since the last step,
minus collision_penalty when the robot's body meets the world (a collision:
summary.json robot.collisions) and minus fall_penalty when it falls (a step
its legs cannot take, gait.unsafe_steps: fall). The episode terminates when
the robot collided, fell or reached its goal (info["outcome"] says which, as
summary.json's robot.outcome does); it is truncated at the scenario's
duration_s. The reward and termination use the truth; the agent's
observation never does.

info: t_s, and after a step outcome, collided, fell, reached_goal; and "raw",
proxsim's whole observation dict (NaN where a value is none), unless
raw_info=False. With Gymnasium installed WalkEnv is a gymnasium.Env;
gymnasium.utils.env_checker.check_env passes with raw_info=False (its
determinism check compares infos with ==, and NaN is never equal to itself).
"""
import numpy as np

from ._core import Simulation
from .spaces import Box

try:  # a gymnasium.Env when Gymnasium is importable (gymnasium.utils.env_checker.check_env passes)
    from gymnasium import Env as _EnvBase
except ImportError:
    _EnvBase = object


# the task's defaults, shared with VecWalkEnv
MIN_STRIDE_M = 0.3
MAX_STRIDE_M = 1.0
COLLISION_PENALTY = 10.0
FALL_PENALTY = 10.0


def check_strides(min_stride_m, max_stride_m):
    if not (np.isfinite(min_stride_m) and np.isfinite(max_stride_m) and 0 < min_stride_m <= max_stride_m):
        raise ValueError(f"expected finite strides 0 < min_stride_m <= max_stride_m, got {min_stride_m}, {max_stride_m}")


def check_penalties(collision_penalty, fall_penalty):
    """A NaN or infinite penalty would make every reward NaN (or inf - inf): refused, named."""
    for name, value in (("collision_penalty", collision_penalty), ("fall_penalty", fall_penalty)):
        if not np.isfinite(float(value)):
            raise ValueError(f"{name}: expected a finite number, got {value!r}")


def check_action(action, shape):
    """action as a float array of `shape`, every value finite; the first bad value named."""
    action = np.asarray(action, dtype=float)
    if action.shape != shape:
        raise ValueError(f"expected an action [walk, stride_m] of shape {shape}, got shape {action.shape}: {action!r}")
    bad = np.argwhere(~np.isfinite(action))
    if len(bad):
        index = tuple(int(i) for i in bad[0])
        name = ("walk", "stride_m")[index[-1]]
        raise ValueError(f"action{list(index)} ({name}) is {action[index]!r}: expected a finite number")
    return action


def walk_spaces(n_sensors, min_stride_m, max_stride_m):
    """The observation and action spaces of one walking episode with n_sensors sensors."""
    inf = np.inf
    low = np.array([0.0, 0.0, 0.0] * n_sensors + [-inf, -inf, -np.pi, 0.0, 0.0, 0.0], dtype=np.float32)
    high = np.array([inf, 1.0, 1.0] * n_sensors + [inf, inf, np.pi, 1.0, 1.0, inf], dtype=np.float32)
    observation_space = Box(low, high, dtype=np.float32)
    action_space = Box(np.array([0.0, min_stride_m], dtype=np.float32),
                       np.array([1.0, max_stride_m], dtype=np.float32), dtype=np.float32)
    return observation_space, action_space


class WalkEnv(_EnvBase):
    metadata = {"render_modes": []}
    render_mode = None
    spec = None

    def __init__(self, scenario, *, threads=1, min_stride_m=MIN_STRIDE_M, max_stride_m=MAX_STRIDE_M,
                 collision_penalty=COLLISION_PENALTY, fall_penalty=FALL_PENALTY, raw_info=True):
        if isinstance(scenario, str) and scenario.startswith("builtin:"):
            self._sim = Simulation.builtin(scenario[len("builtin:"):], threads=threads, scenario_strategy=False)
        else:
            self._sim = Simulation(scenario, threads=threads, scenario_strategy=False)
        if self._sim.robot is None:
            raise ValueError("WalkEnv needs a scenario with a robot section (its sensors ride the robot)")
        check_strides(min_stride_m, max_stride_m)
        check_penalties(collision_penalty, fall_penalty)
        self._min_stride_m = float(min_stride_m)
        self._max_stride_m = float(max_stride_m)
        self._collision_penalty = float(collision_penalty)
        self._fall_penalty = float(fall_penalty)
        # info["raw"]: proxsim's whole observation, NaN where a value is none (a laser's signal)
        self._raw_info = bool(raw_info)
        self.observation_space, self.action_space = walk_spaces(len(self._sim.sensor_names), min_stride_m,
                                                                max_stride_m)
        self._goal = None
        self._last_distance = None
        self._walking = True
        self._collisions = 0

    @property
    def simulation(self):
        """The proxsim.Simulation underneath (for its truth(), summary() and sensor_names)."""
        return self._sim

    def _vector(self, obs):
        r = obs["readings"]
        robot = obs["robot"]
        per_sensor = np.stack([r["d_m"], r["detected"], r["fresh"]], axis=1).ravel()
        own = [robot["pelvis_W"][0], robot["pelvis_W"][1], np.radians(robot["yaw_deg"]), robot["gait_phase"],
               float(robot["stopped"]), robot["distance_walked_m"]]
        return np.concatenate([per_sensor, own]).astype(np.float32)

    def _distance_to_goal(self, obs):
        if self._goal is None:
            return 0.0
        return float(np.hypot(*(obs["robot"]["pelvis_W"][:2] - self._goal)))

    def reset(self, *, seed=None, options=None):
        if _EnvBase is not object:
            super().reset(seed=seed)  # Gymnasium's own np_random, seeded as its checker expects
        self._sim.reset(seed=seed)
        if seed is not None:
            self.action_space.seed(seed)
        summary = self._sim.summary()
        waypoints = summary["inputs"]["robot"]["path"]["waypoints_m"]
        self._goal = np.array(waypoints[-1], dtype=float) if waypoints else None
        self._walking = True
        self._collisions = 0
        obs = self._sim.step()
        self._last_distance = self._distance_to_goal(obs)
        return self._vector(obs), self._info({"t_s": obs["t_s"]}, obs)

    def step(self, action):
        action = check_action(action, (2,))
        walk = action[0] >= 0.5
        robot = self._sim.robot
        if walk != self._walking:
            robot.resume() if walk else robot.stop()
            self._walking = walk
        robot.set_stride(float(np.clip(action[1], self._min_stride_m, self._max_stride_m)))
        obs = self._sim.step()
        truth = self._sim.truth()
        distance = self._distance_to_goal(obs)
        reward = self._last_distance - distance
        self._last_distance = distance
        outcome = truth["outcome"]
        collided, fell = outcome == "collided", outcome == "fell"
        if truth["collisions"] > self._collisions:  # a new collision this step
            reward -= self._collision_penalty
        self._collisions = truth["collisions"]
        if fell:
            reward -= self._fall_penalty
        terminated = bool(collided or fell or outcome == "reached_goal")
        truncated = bool(self._sim.done and not terminated)
        info = self._info({"t_s": obs["t_s"], "outcome": outcome, "collided": collided, "fell": fell,
                           "reached_goal": truth["reached_goal"]}, obs)
        return self._vector(obs), float(reward), terminated, truncated, info

    def _info(self, info, obs):
        if self._raw_info:
            info["raw"] = obs
        return info

    def close(self):
        self._sim.close()

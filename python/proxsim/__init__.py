"""proxsim: simulated proximity sensors on a walking biped, in a closed loop.

    import proxsim
    sim = proxsim.Simulation("scenario.yaml", seed=7, threads=1, out=None)
    obs = sim.step()                 # what the robot knows at the next sample
    obs["readings"]["d_m"]           # one entry per sensor, scenario order
    sim.robot.stop()                 # commands take effect from the next step
    sim.truth()                      # the truth, for analysis only

Threads: one Simulation may be shared by threads; each call holds the
object's lock, and a second call made while another thread is inside step()
waits for it (docs/trust.md). With out=DIR the folder is locked until close().
Out-of-range seed or threads raise ValueError naming the argument.

Co-simulation (docs/cosimulation.md): with robot.locomotion: external (or
Simulation(..., locomotion="external")) the caller sets the robot's state at
every sample: sim.step(q={joint: rad}, X_WP=(xyz, quat_wxyz)).

See docs/strategies.md for the whole contract, proxsim.WalkEnv for a
Gymnasium-style environment and proxsim.VecWalkEnv for N of them stepped
together in C++ threads (Gymnasium's vector API).

proxsim.config_keys("map") lists a scenario section's keys (type, unit,
bounds, default, meaning), as docs/scenario.md's tables do.
"""
from ._core import InputError, Robot, Simulation, config_keys, config_sections
from .vec_walk_env import VecWalkEnv
from .walk_env import WalkEnv

__all__ = ["InputError", "Robot", "Simulation", "VecWalkEnv", "WalkEnv", "config_keys", "config_sections"]

# Gymnasium is not a dependency; when it is importable, the environments are
# registered with it so that gymnasium.make("proxsim/Walk-v0", scenario=...) and
# gymnasium.make_vec("proxsim/Walk-v0", num_envs=N, vectorization_mode="vector_entry_point",
# scenario=..., threads=2) work.
try:
    import gymnasium as _gymnasium

    if "proxsim/Walk-v0" not in _gymnasium.registry:
        try:
            _gymnasium.register(id="proxsim/Walk-v0", entry_point="proxsim.walk_env:WalkEnv",
                                vector_entry_point="proxsim.vec_walk_env:VecWalkEnv")
        except TypeError:  # a Gymnasium without vector entry points
            _gymnasium.register(id="proxsim/Walk-v0", entry_point="proxsim.walk_env:WalkEnv")
except ImportError:
    pass

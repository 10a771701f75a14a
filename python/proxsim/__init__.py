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

See docs/strategies.md for the whole contract, and proxsim.WalkEnv for a
Gymnasium-style environment.
"""
from ._core import InputError, Robot, Simulation
from .walk_env import WalkEnv

__all__ = ["InputError", "Robot", "Simulation", "WalkEnv"]

# Gymnasium is not a dependency; when it is importable, the environment is
# registered with it so that gymnasium.make("proxsim/Walk-v0", scenario=...) works.
try:
    import gymnasium as _gymnasium

    if "proxsim/Walk-v0" not in _gymnasium.registry:
        _gymnasium.register(id="proxsim/Walk-v0", entry_point="proxsim.walk_env:WalkEnv")
except ImportError:
    pass

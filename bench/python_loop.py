#!/usr/bin/env python3
"""The Python side of `proxsim bench`'s closed-loop section (not a test).

Prints one JSON object:
  python_stop_rule_loop_wall_s  the paper run driven from Python with the stop
                                rule written in Python (examples/python/stop_rule.py),
                                writing the run's files, the stepping loop's wall time
  python_step_s                 mean wall time of one sim.step() (paper run, its
                                built-in strategy, no files): C++ step + binding
  stop_requested_t_s            when the Python rule stopped the robot (a check)
  walk_env_step_s               mean wall time of one WalkEnv.step() (paper scenario, the
                                agent walking with a stride drawn anew at every step)
  walk_env_sim_step_s           mean wall time of the two binding calls WalkEnv.step()
                                makes (sim.step() and sim.truth()), same scenario, no strategy
  walk_env_python_s             mean wall time of the Python work WalkEnv.step() does
                                itself (checking the action, the observation vector,
                                the reward), on one observation
Best of --repeats runs each. Usage: python_loop.py OUT_DIR [--repeats N]
"""
import argparse
import json
import os
import sys
import time

import numpy as np

import proxsim

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "python"))
import stop_rule  # noqa: E402


def stop_rule_loop(out_dir):
    sim = proxsim.Simulation.builtin("paper", out=out_dir, scenario_strategy=False)
    stopping = False
    start = time.perf_counter()
    while not sim.done:
        obs = sim.step()
        if not stopping and stop_rule.obstacle_ahead(obs) >= 0:
            sim.robot.stop()
            stopping = True
    wall_s = time.perf_counter() - start
    sim.close()
    return wall_s, sim.summary()["robot"]["stop_requested_t_s"]


def step_only():
    sim = proxsim.Simulation.builtin("paper")
    start = time.perf_counter()
    while not sim.done:
        sim.step()
    return (time.perf_counter() - start) / sim.sample_count


def walk_env_step():
    env = proxsim.WalkEnv("builtin:paper")
    env.reset(seed=1)
    rng = np.random.default_rng(0)
    actions = [np.array([1.0, stride], dtype=np.float32) for stride in rng.uniform(0.3, 1.0, 400)]
    env.step(actions[0])  # the stride table is sampled once, on the first new stride
    start = time.perf_counter()
    steps = 0
    for action in actions[1:]:
        _, _, terminated, truncated, _ = env.step(action)
        steps += 1
        if terminated or truncated:
            break
    return (time.perf_counter() - start) / steps


def walk_env_sim_step():
    sim = proxsim.Simulation.builtin("paper", scenario_strategy=False)
    start = time.perf_counter()
    steps = 0
    while not sim.done and steps < 400:
        sim.step()
        sim.truth()
        steps += 1
    return (time.perf_counter() - start) / steps


def walk_env_python():
    env = proxsim.WalkEnv("builtin:paper")
    _, info = env.reset(seed=1)
    obs, action = info["raw"], np.array([1.0, 0.6], dtype=np.float32)
    repeats = 2000
    start = time.perf_counter()
    for _ in range(repeats):
        checked = np.asarray(action, dtype=float)
        if checked.shape != (2,) or not np.all(np.isfinite(checked)):
            raise ValueError("bad action")
        float(np.clip(checked[1], 0.3, 1.0))
        env._vector(obs)
        env._distance_to_goal(obs)
    return (time.perf_counter() - start) / repeats


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out_dir")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    loops = [stop_rule_loop(args.out_dir) for _ in range(args.repeats)]
    steps = [step_only() for _ in range(args.repeats)]
    print(json.dumps({"python_stop_rule_loop_wall_s": min(w for w, _ in loops),
                      "stop_requested_t_s": loops[0][1],
                      "python_step_s": min(steps),
                      "walk_env_step_s": min(walk_env_step() for _ in range(args.repeats)),
                      "walk_env_sim_step_s": min(walk_env_sim_step() for _ in range(args.repeats)),
                      "walk_env_python_s": min(walk_env_python() for _ in range(args.repeats))}))


if __name__ == "__main__":
    main()

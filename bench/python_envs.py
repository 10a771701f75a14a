#!/usr/bin/env python3
"""The Python side of `proxsim bench`'s python_envs section (not a test): co-simulation and the
batched environment, on the paper scenario. Prints one JSON object:

  own_gait_step_s            mean wall time of sim.step() on the paper run walked by its own gait
  external_step_s            the same run driven from outside by the gait run's recorded states:
                             sim.step(q=array, X_WP=(xyz, quat_wxyz), gait_phase=..., support_leg=...)
  external_by_name_step_s    the same with q as a {joint: rad} dict
  vec_steps_per_s            environment steps per second of VecWalkEnv(N, threads), auto-resets included
  vec_1_thread_steps_per_s   the same on one thread
  walk_env_steps_per_s       environment steps per second of N separate WalkEnvs stepped one after another
  vec_cpp_step_s             mean C++ work of one batched step (GIL released: the N simulations' steps)
  vec_python_overhead_s      mean wall time of one batched step minus that C++ work (argument
                             conversion, the output arrays, the infos, the Python wrapper)
  load_average_1min_before / _after   os.getloadavg()[0] around the section
Best of --repeats runs each, the batched and the separate environments interleaved. Usage: python_envs.py [--repeats N] [--num-envs N] [--threads T] [--steps S]
"""
import argparse
import json
import os
import time

import numpy as np

import proxsim


def own_gait_states():
    """The paper run walked by its gait: the mean step time, and every sample's state."""
    sim = proxsim.Simulation.builtin("paper")
    states = []
    elapsed = 0.0
    while not sim.done:
        start = time.perf_counter()
        sim.step()
        elapsed += time.perf_counter() - start
        states.append(sim.robot_state())
    return elapsed / len(states), states


def external_step(states, by_name):
    sim = proxsim.Simulation.builtin("paper", locomotion="external")
    names = sim.joint_names
    # what a co-simulation loop hands over: arrays it already has (or a dict built from them)
    prepared = [(dict(zip(names, s["q"])) if by_name else s["q"], (s["xyz"], s["quat_wxyz"]), s["gait_phase"],
                 s["support_leg"]) for s in states]
    start = time.perf_counter()
    for q, pose, phase, support in prepared:
        sim.step(q=q, X_WP=pose, gait_phase=phase, support_leg=support)
    return (time.perf_counter() - start) / len(prepared)


def actions(num_envs, steps):
    rng = np.random.default_rng(0)
    walk = (rng.uniform(size=(steps, num_envs)) < 0.95).astype(np.float32)
    stride = rng.uniform(0.3, 1.0, size=(steps, num_envs)).astype(np.float32)
    return np.stack([walk, stride], axis=2)


def vec_env(num_envs, threads, all_actions):
    env = proxsim.VecWalkEnv("builtin:paper", num_envs, threads)
    env.reset(seed=1)
    cpp_s = overhead_s = 0.0
    start = time.perf_counter()
    for a in all_actions:
        t0 = time.perf_counter()
        env.step(a)
        wall = time.perf_counter() - t0
        cpp_s += env.last_cpp_s
        overhead_s += wall - env.last_cpp_s
    wall_s = time.perf_counter() - start
    steps = len(all_actions)
    return num_envs * steps / wall_s, cpp_s / steps, overhead_s / steps


def walk_envs(num_envs, all_actions):
    envs = [proxsim.WalkEnv("builtin:paper") for _ in range(num_envs)]
    for i, env in enumerate(envs):
        env.reset(seed=1 + i)
    start = time.perf_counter()
    for a in all_actions:
        for i, env in enumerate(envs):
            _, _, terminated, truncated, _ = env.step(a[i])
            if terminated or truncated:
                env.reset()
    return num_envs * len(all_actions) / (time.perf_counter() - start)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--num-envs", type=int, default=64)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--steps", type=int, default=600)
    args = parser.parse_args()
    load_before = os.getloadavg()[0]
    states = own_gait_states()[1]
    gait, external, by_name = [], [], []
    for _ in range(args.repeats):  # interleaved, as below
        gait.append(own_gait_states()[0])
        external.append(external_step(states, False))
        by_name.append(external_step(states, True))
    result = {"own_gait_step_s": min(gait), "external_step_s": min(external), "external_by_name_step_s": min(by_name),
              "num_envs": args.num_envs, "threads": args.threads, "steps": args.steps}
    all_actions = actions(args.num_envs, args.steps)
    # the three interleaved, repeat by repeat: a change of the machine's load falls on all of them
    vec, vec_1_thread, singles = [], [], []
    for _ in range(args.repeats):
        vec.append(vec_env(args.num_envs, args.threads, all_actions))
        vec_1_thread.append(vec_env(args.num_envs, 1, all_actions)[0])
        singles.append(walk_envs(args.num_envs, all_actions))
    best = max(vec, key=lambda v: v[0])
    result["vec_steps_per_s"], result["vec_cpp_step_s"], result["vec_python_overhead_s"] = best
    result["vec_1_thread_steps_per_s"] = max(vec_1_thread)
    result["walk_env_steps_per_s"] = max(singles)
    result["load_average_1min_before"] = load_before
    result["load_average_1min_after"] = os.getloadavg()[0]
    print(json.dumps(result))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The Python side of `proxsim bench`'s closed-loop section (not a test).

Prints one JSON object:
  python_stop_rule_loop_wall_s  the paper run driven from Python with the stop
                                rule written in Python (examples/python/stop_rule.py),
                                writing the run's files, the stepping loop's wall time
  python_step_s                 mean wall time of one sim.step() (paper run, its
                                built-in strategy, no files): C++ step + binding
  stop_requested_t_s            when the Python rule stopped the robot (a check)
Best of --repeats runs each. Usage: python_loop.py OUT_DIR [--repeats N]
"""
import argparse
import json
import os
import sys
import time

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


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out_dir")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    loops = [stop_rule_loop(args.out_dir) for _ in range(args.repeats)]
    steps = [step_only() for _ in range(args.repeats)]
    print(json.dumps({"python_stop_rule_loop_wall_s": min(w for w, _ in loops),
                      "stop_requested_t_s": loops[0][1],
                      "python_step_s": min(steps)}))


if __name__ == "__main__":
    main()

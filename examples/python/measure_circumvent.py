#!/usr/bin/env python3
"""Measures the built-in `circumvent` strategy on data/scenarios/circumvent_obstacle.yaml
with its obstacle moved across the path, y from -0.5 to +0.5 m in 0.05 m steps
(issue 26's sweep; tests/circumvent_limits_test.cc asserts it), and the same
walk without the obstacle: the outcome, whether and when the goal is reached,
the true minimum clearance (against margin_m / 2) and the detour's length
(distance walked minus the distance walked without the obstacle). Prints a
Markdown table.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/measure_circumvent.py
"""
import os
import re
import tempfile

import proxsim

HERE = os.path.dirname(os.path.abspath(__file__))
SCENARIO = os.path.join(HERE, "..", "..", "data", "scenarios", "circumvent_obstacle.yaml")


def walk(text):
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", dir=os.path.dirname(SCENARIO), delete=False) as f:
        f.write(text)
    try:
        with proxsim.Simulation(f.name) as sim:
            walked_to_goal = None
            while not sim.done:
                obs = sim.step()
                if walked_to_goal is None and sim.truth()["reached_goal"]:
                    walked_to_goal = obs["robot"]["distance_walked_m"]
            robot = sim.summary()["robot"]
            robot["walked_to_goal_m"] = walked_to_goal
            return robot
    finally:
        os.unlink(f.name)


def main():
    text = open(SCENARIO).read()
    pose = "xyz_m: [2.5, 0.0, 0.075]"
    assert pose in text, "the example's obstacle pose changed: update this script"
    baseline = walk(re.sub(r"    - name: obstacle\n(      .*\n)+", "", text))
    margin = 0.15
    print("| obstacle centre y (m) | outcome | at t (s) | min clearance (m) | > margin/2 | walked to the goal (m) | detour (m) |")
    print("|---|---|---|---|---|---|---|")
    for i in range(21):
        dy = round(-0.5 + 0.05 * i, 2)
        robot = walk(text.replace(pose, f"xyz_m: [2.5, {dy}, 0.075]"))
        walked = robot["walked_to_goal_m"]
        print(f"| {dy:+.2f} | {robot['outcome']} | {robot['outcome_t_s']} | {robot['min_clearance_m']:.3f} | "
              f"{robot['min_clearance_m'] > margin / 2} | " +
              (f"{walked:.2f} | {walked - baseline['walked_to_goal_m']:+.2f} |" if walked is not None else "— | — |"))
    print(f"\nwithout the obstacle: goal reached {baseline['reached_goal']} at t = {baseline['reached_goal_t_s']} s, "
          f"walked {baseline['walked_to_goal_m']:.2f} m to it")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Going around an obstacle from a Python script: a walk-through.

The built-in `circumvent` strategy does this in C++ (src/strategy/); here the
same loop is written in Python, simpler, to show the parts a strategy needs:

 1. keep the points the sensors report above the floor (never the truth);
 2. when one stands on the path ahead, estimate the obstacle's lateral
    extent from the points kept near it;
 3. command a detour that keeps the robot's half-width plus a margin clear of
    that extent (sim.robot.set_path), replanning as more is seen;
 4. check the result against the truth afterwards (sim.truth(), the summary).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/circumvent.py \\
        [data/scenarios/circumvent_obstacle.yaml] [--out DIR]
"""
import argparse
import os

import numpy as np

import proxsim

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = os.path.join(HERE, "..", "..", "data", "scenarios", "circumvent_obstacle.yaml")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", nargs="?", default=DEFAULT_SCENARIO)
    parser.add_argument("--out")
    parser.add_argument("--margin-m", type=float, default=0.15)
    args = parser.parse_args()

    with proxsim.Simulation(args.scenario, out=args.out, scenario_strategy=False) as sim:
        goal = np.array(sim.summary()["inputs"]["robot"]["path"]["waypoints_m"][-1], dtype=float)
        extent = None  # [x_min, x_max, y_min, y_max] of the obstacle's points; it only grows
        side = 0       # +1: pass on the left, -1: on the right; kept once chosen
        commanded = None
        while not sim.done:
            obs = sim.step()
            robot, r = obs["robot"], obs["readings"]
            # 1. the points the sensors report, above the ground the robot stands on
            ground_z = min(p[2] for p in list(robot["soles_W"].values()) + list(robot["toes_W"].values()))
            points = r["origin_W"] + r["d_m"][:, None] * r["dir_W"]
            above = points[r["fresh"] & r["detected"] & (points[:, 2] - ground_z > 0.03), :2]
            pelvis = robot["pelvis_W"][:2]
            clear = robot["half_width_m"] + args.margin_m
            # 2. an obstacle: the first point on the path (the x axis here) within 1.5 m ahead,
            #    then every point near it
            for x, y in above:
                if extent is None and 0 < x - pelvis[0] < 1.5 and abs(y) < clear:
                    extent = [x, x, y, y]
                if extent is not None and extent[0] - 0.3 < x < extent[1] + 0.3 and extent[2] - 0.3 < y < extent[3] + 0.3:
                    extent = [min(extent[0], x), max(extent[1], x), min(extent[2], y), max(extent[3], y)]
            if extent is None:
                continue
            # 3. the detour, half-width + margin clear of the extent, on the side chosen first
            left, right = extent[3] + clear, extent[2] - clear
            if side == 0:
                side = 1 if abs(left) <= abs(right) else -1
            shift = left if side > 0 else right
            far_x = max(extent[1], extent[0] + 0.3) + clear + 0.2
            detour = [[extent[0] - clear, shift], [far_x, shift], [far_x + 1.0, 0.0]]
            # only the waypoints still ahead of the pelvis, then the goal (the gait never turns back)
            ahead = [w for w in detour if w[0] > pelvis[0] + 0.15] + [goal.tolist()]
            if commanded is None or len(ahead) != len(commanded) or np.abs(np.subtract(ahead, commanded)).max() > 0.03:
                commanded = ahead
                sim.robot.set_path(ahead)
                print(f"t = {obs['t_s']:.2f} s: path {np.round(ahead, 2).tolist()}")
        robot = sim.summary()["robot"]
    # 4. the truth, afterwards
    print(f"reached the goal: {robot['reached_goal']} (t = {robot['reached_goal_t_s']} s); "
          f"true minimum clearance {robot['min_clearance_m']:.3f} m; walked {robot['distance_walked_m']:.2f} m")


if __name__ == "__main__":
    main()

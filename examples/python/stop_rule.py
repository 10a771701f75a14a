#!/usr/bin/env python3
"""The built-in `stop` strategy, written in Python on what the robot knows.

Runs a scenario with its built-in strategy switched off and this rule in
charge: a fresh detection whose measured point stands more than 3 cm above
the ground the robot stands on, within 0.30 m of the leading toe's heading
line and at most stop_distance_m ahead of it, stops the robot. On the paper's
run it stops the robot at the same sample as the built-in rule.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/stop_rule.py [SCENARIO.yaml] [--out DIR]
"""
import argparse

import numpy as np

import proxsim


def obstacle_ahead(obs, stop_distance_m=0.5, min_height_m=0.03, corridor_half_width_m=0.30):
    """The index of the first sensor that reports an obstacle in the robot's way, or -1."""
    robot = obs["robot"]
    heading = robot["heading_W"]
    lateral = np.array([-heading[1], heading[0], 0.0])  # z × heading: to the robot's left
    toes = [robot["toes_W"]["left"], robot["toes_W"]["right"]]
    soles = [robot["soles_W"]["left"], robot["soles_W"]["right"]]
    front = max(toes, key=lambda p: p @ heading)  # the leading toe
    ground_z = min(p[2] for p in toes + soles)  # the ground under the stance foot
    readings = obs["readings"]
    # the points the sensors report: origin + d_m along the axis (never the truth)
    points = readings["origin_W"] + readings["d_m"][:, None] * readings["dir_W"]
    for i, p in enumerate(points):
        if not (readings["fresh"][i] and readings["detected"][i]):
            continue
        if p[2] - ground_z < min_height_m:
            continue  # the floor
        d = p - front
        if d @ heading <= stop_distance_m and abs(d @ lateral) <= corridor_half_width_m:
            return i
    return -1


def run(scenario=None, out=None, stop_distance_m=0.5):
    """Runs the scenario (None: the paper's) with the rule; returns the summary."""
    if scenario is None:
        sim = proxsim.Simulation.builtin("paper", out=out, scenario_strategy=False)
    else:
        sim = proxsim.Simulation(scenario, out=out, scenario_strategy=False)
    with sim:
        stopping = False
        while not sim.done:
            obs = sim.step()
            if not stopping and obs["robot"] is not None:
                trigger = obstacle_ahead(obs, stop_distance_m)
                if trigger >= 0:
                    sim.robot.stop()
                    stopping = True
                    print(f"t = {obs['t_s']:.2f} s: {sim.sensor_names[trigger]} sees an obstacle ahead; stopping")
        return sim.summary()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", nargs="?", help="a scenario file (default: the paper's run)")
    parser.add_argument("--out", help="write the run's files here, as `proxsim run` does")
    parser.add_argument("--stop-distance-m", type=float, default=0.5)
    args = parser.parse_args()
    robot = run(args.scenario, args.out, args.stop_distance_m)["robot"]
    print(f"stop requested at t = {robot['stop_requested_t_s']} s, standing at t = {robot['stop_t_s']} s, "
          f"walked {robot['distance_walked_m']:.2f} m, min clearance {robot['min_clearance_m']:.3f} m")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A stop rule on the terrain map: the robot stops as soon as its map holds a
hazard (obstacle, step, hole) within `ahead_m` of its leading toe, in a
corridor of ±0.30 m around its heading — the map, not the raw readings, is
what it watches. Prints each hazard when the map first holds it, and saves
the map's heights as it stood at the end (NumPy, NaN where unknown).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/map_hazard_stop.py \
        [SCENARIO.yaml] [--out DIR] [--save-elevation map.npy]

On the paper's run the map holds the obstacle at t = 3.52 s, 0.38 m ahead of
the toe, and the robot stops there.
"""
import argparse

import numpy as np

import proxsim


def hazard_ahead(hazards, robot, ahead_m=0.6, corridor_half_width_m=0.30):
    """The first hazard whose extent reaches into the corridor within ahead_m of the leading toe, or None."""
    heading = np.asarray(robot["heading_W"][:2])
    lateral = np.array([-heading[1], heading[0]])
    toes = [np.asarray(robot["toes_W"][side][:2]) for side in ("left", "right")]
    front = max(toes, key=lambda p: p @ heading)
    for h in hazards:
        # the extent's nearest point to the toe, along and across the heading
        half = np.array([h["size_x_m"], h["size_y_m"]]) / 2
        corners = np.array([[sx, sy] for sx in (-1, 1) for sy in (-1, 1)]) * half + [h["x_m"], h["y_m"]]
        along = (corners - front) @ heading
        across = (corners - front) @ lateral
        if along.max() >= 0 and along.min() <= ahead_m and across.min() <= corridor_half_width_m \
                and across.max() >= -corridor_half_width_m:
            return h
    return None


def run(scenario=None, out=None, ahead_m=0.6):
    """Runs the scenario (None: the paper's) with the map rule; returns (summary, final map)."""
    if scenario is None:
        sim = proxsim.Simulation.builtin("paper", out=out, scenario_strategy=False)
    else:
        sim = proxsim.Simulation(scenario, out=out, scenario_strategy=False)
    with sim:
        seen = 0
        stopping = False
        while not sim.done:
            obs = sim.step()
            terrain = sim.terrain_map()  # a copy of the map as it stands after this sample
            if terrain is None:
                raise SystemExit("this scenario builds no terrain map (it needs a robot)")
            for h in terrain["hazards"][seen:]:
                article = "an" if h["class"][0] in "aeiou" else "a"
                print(f"t = {obs['t_s']:.2f} s: the map holds {article} {h['class']} at ({h['x_m']:.2f}, {h['y_m']:.2f}) m, "
                      f"{100 * h['height_m']:+.0f} cm, {h['distance_at_detection_m']:.2f} m from the toe")
            seen = max(seen, len(terrain["hazards"]))
            if not stopping and hazard_ahead(terrain["hazards"], obs["robot"], ahead_m) is not None:
                sim.robot.stop()
                stopping = True
                print(f"t = {obs['t_s']:.2f} s: a hazard within {ahead_m} m ahead; stopping")
        return sim.summary(), terrain


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", nargs="?", help="a scenario file with a robot (default: the paper's run)")
    parser.add_argument("--out", help="write the run's files here, as `proxsim run` does")
    parser.add_argument("--ahead-m", type=float, default=0.6)
    parser.add_argument("--save-elevation", help="save the final map's heights (.npy)")
    args = parser.parse_args()
    summary, terrain = run(args.scenario, args.out, args.ahead_m)
    robot = summary["robot"]
    measured = int(np.isfinite(terrain["elevation"]).sum())
    print(f"stopped: {robot['stopped']} (at t = {robot['stop_t_s']} s), walked {robot['distance_walked_m']:.2f} m, "
          f"min clearance {robot['min_clearance_m']:.3f} m; the map: {measured} cells measured, "
          f"origin {terrain['origin_xy_m']}, {terrain['resolution_m']} m cells")
    if args.save_elevation:
        np.save(args.save_elevation, terrain["elevation"])


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Co-simulation: the Unitree H1 driven through proxsim from a state log in MuJoCo's conventions.

Another simulator moves the robot; proxsim places it in its scene at every sample and measures:
readings, truth, terrain map, collisions, outcome, the run's files and viewer (docs/cosimulation.md).
The log is MuJoCo's `qpos` of the H1 as Menagerie's unitree_h1/h1.xml orders it: the free joint
first (pelvis x, y, z in metres, then its quaternion w, x, y, z), then the 19 hinge joints in the
model's order (MUJOCO_H1_HINGES), one row per logged time.

Where the log comes from: there is no MuJoCo controller that walks the H1 here, so by default this
script first MAKES the log, honestly labelled: it walks the H1 by proxsim's own kinematic gait
(data/scenarios/h1_dining_room.yaml) and writes each sample's state converted to qpos order
(make_log). Give --log FILE to drive from a log of your own simulator instead (the same columns:
t_s, then qpos[0] ... qpos[25]). A live loop has the same body as drive(): build q and X_WP from
d.qpos after mj_step, call sim.step (examples/python/talos_mujoco_physics.py does it live, with
MuJoCo's physics moving TALOS; docs/cosimulation.md).

    PYTHONPATH=build/release/python .venv/bin/python3 examples/python/h1_mujoco_qpos.py --out h1-cosim
"""
import argparse
import os

import numpy as np

import proxsim

HERE = os.path.dirname(os.path.abspath(__file__))
SCENARIO = os.path.join(HERE, "..", "..", "data", "scenarios", "h1_dining_room.yaml")

# qpos[7:] of the H1 in MuJoCo: depth-first through the tree (left leg, right leg, torso, left
# arm, right arm), the order of the joints in Unitree's h1.urdf and of Menagerie's h1.xml (MuJoCo
# 2.2.2's mj_loadXML on h1.urdf compiles these hinges in this order: docs/cosimulation.md).
# proxsim's own joint order (sim.joint_names) is breadth-first: the names map one to the other.
MUJOCO_H1_HINGES = [
    "left_hip_yaw_joint", "left_hip_roll_joint", "left_hip_pitch_joint", "left_knee_joint", "left_ankle_joint",
    "right_hip_yaw_joint", "right_hip_roll_joint", "right_hip_pitch_joint", "right_knee_joint", "right_ankle_joint",
    "torso_joint",
    "left_shoulder_pitch_joint", "left_shoulder_roll_joint", "left_shoulder_yaw_joint", "left_elbow_joint",
    "right_shoulder_pitch_joint", "right_shoulder_roll_joint", "right_shoulder_yaw_joint", "right_elbow_joint",
]


def make_log(path):
    """A qpos log of the H1 walking by proxsim's gait (a stand-in for another simulator's log)."""
    rows = []
    with proxsim.Simulation(SCENARIO, scenario_strategy=False) as sim:
        position = {name: i for i, name in enumerate(sim.joint_names)}
        while not sim.done:
            sim.step()
            s = sim.robot_state()
            hinges = [s["q"][position[name]] for name in MUJOCO_H1_HINGES]
            rows.append([s["t_s"], *s["xyz"], *s["quat_wxyz"], *hinges])
    header = ("made by examples/python/h1_mujoco_qpos.py from proxsim's own gait on h1_dining_room.yaml, "
              "converted to MuJoCo qpos order (free joint xyz, quat wxyz, then the hinges of "
              "Menagerie's h1.xml)\nt_s," + ",".join(f"qpos{i}" for i in range(7 + len(MUJOCO_H1_HINGES))))
    np.savetxt(path, np.array(rows), delimiter=",", header=header, fmt="%.17g")


def state_from_qpos(qpos):
    """proxsim's step arguments from one MuJoCo qpos row."""
    X_WP = (qpos[0:3], qpos[3:7])  # the free joint: position, quaternion (w, x, y, z)
    q = dict(zip(MUJOCO_H1_HINGES, qpos[7:]))
    return q, X_WP


def drive(log_path, out):
    log = np.loadtxt(log_path, delimiter=",", ndmin=2)
    t_log, qpos_log = log[:, 0], log[:, 1:]
    if qpos_log.shape[1] != 7 + len(MUJOCO_H1_HINGES):
        raise SystemExit(f"{log_path}: {qpos_log.shape[1]} qpos columns, expected {7 + len(MUJOCO_H1_HINGES)}")
    first_detection, told = None, False
    with proxsim.Simulation(SCENARIO, out=out, locomotion="external") as sim:
        assert sorted(sim.joint_names) == sorted(MUJOCO_H1_HINGES)
        for sample in range(sim.sample_count):
            # the proxsim sample's time picks the log row at or just before it: a log at
            # another rate than the sensors' rate_hz is sampled, not assumed equal
            t_s = sample / sim.rate_hz
            k = max(int(np.searchsorted(t_log, t_s + 1e-9, side="right")) - 1, 0)
            q, X_WP = state_from_qpos(qpos_log[k])
            obs = sim.step(q=q, X_WP=X_WP)
            # the first reading of the obstacle (the truth names what a detection hit)
            hits = [i for i, name in enumerate(sim.truth()["object"]) if name == "obstacle"]
            seen = [i for i in hits if obs["readings"]["detected"][i]]
            if first_detection is None and seen:
                first_detection = (obs["t_s"], sim.sensor_names[seen[0]], obs["readings"]["d_m"][seen[0]])
            if sim.robot_state()["stop_requested"] and not told:
                told = True
                print(f"t = {obs['t_s']:.2f} s: proxsim's stop rule asks the robot to stop "
                      "(the other simulator's controller would obey; this log does not)")
        summary = sim.summary()
    return summary, first_detection


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--log", help="a qpos log (t_s, qpos...) of your own; default: make one from proxsim's gait")
    parser.add_argument("--out", default="h1-cosim-out", help="the run's output folder")
    args = parser.parse_args()
    log_path = args.log
    if log_path is None:
        os.makedirs(args.out + "-log", exist_ok=True)
        log_path = os.path.join(args.out + "-log", "h1_qpos.csv")
        make_log(log_path)
        print(f"wrote {log_path}: the H1's qpos from proxsim's own gait (MuJoCo's order), as another simulator would")
    summary, first = drive(log_path, args.out)
    robot = summary["robot"]
    if first:
        print(f"the obstacle first detected by {first[1]} at t = {first[0]:.2f} s, {first[2]:.2f} m away")
    print(f"outcome: {robot['outcome']} ({robot['outcome_detail']}); collisions: {len(robot['collisions'])}; "
          f"walked {robot['distance_walked_m']:.2f} m; files in {args.out}")


if __name__ == "__main__":
    main()

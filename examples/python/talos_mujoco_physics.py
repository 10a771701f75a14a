#!/usr/bin/env python3
"""Live co-simulation with MuJoCo physics: TALOS stands, squats and steps in place in MuJoCo while
proxsim's shin sensors measure, from the physical state, every sample (docs/cosimulation.md).

MuJoCo (the `mujoco` package of python/requirements.txt, the same library proxsim links) steps
Menagerie's TALOS, unchanged (../shared/robots/pal_talos/scene_position.xml: floating base, real
contacts with its floor, the model's own position actuators — joint PD control, kp per joint,
damping ratio 1), with a box added 0.8 m ahead. Every 10 ms the state (the free joint's qpos and
every hinge's) is handed to proxsim's external locomotion (data/scenarios/talos_mujoco_physics.yaml:
the same robot file, the same floor and box), which places the robot, casts the sensors' rays,
checks contacts and writes the run's files.

The motion, from the model's `walk_pose` keyframe:
  0 - 0.5 s   standing, under PD only;
  0.5 - 2.5 s a squat (knees 0.3 rad further and back), under PD only: no help;
  2.5 s on    stepping in place, each foot lifted in turn (knee +0.4 rad at the top) — ASSISTED: a
              soft support (a spring-damper applied to the pelvis through xfrc_applied) holds only
              the pelvis's height and attitude, as a harness would; PD alone does not balance TALOS
              on one foot, and this example has no balance controller.

    PYTHONPATH=build/release/python .venv/bin/python3 examples/python/talos_mujoco_physics.py --out talos-live
"""
import argparse
import os

import numpy as np

import mujoco
import proxsim

HERE = os.path.dirname(os.path.abspath(__file__))
SCENARIO = os.path.join(HERE, "..", "..", "data", "scenarios", "talos_mujoco_physics.yaml")
TALOS_DIR = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "robots", "pal_talos"))

SETTLE_S, SQUAT_END_S = 0.5, 2.5   # phases of the motion (above)
SQUAT_KNEE_RAD = 0.3               # the squat's extra knee bend at its bottom
STEP_PERIOD_S = 1.0                # one foot lifted per second
STEP_KNEE_RAD = 0.4                # the lifted leg's extra knee bend at the top of its step
STEP_HIP_ROLL_RAD = 0.08           # and its hip's roll outward there
# the soft support (stepping only): N/m and N·s/m on the pelvis's height, N·m/rad and N·m·s/rad on its attitude
SUPPORT_Z = (4000.0, 400.0)
SUPPORT_ATTITUDE = (800.0, 80.0)


def build_mujoco(talos_dir=TALOS_DIR):
    """Menagerie's scene (TALOS, its floor) with the scenario's box added; the model starts at walk_pose."""
    spec = mujoco.MjSpec.from_file(os.path.join(talos_dir, "scene_position.xml"))
    # the scenario's box: 0.3 x 0.8 x 0.5 m, its centre at (0.8, 0, 0.25)
    spec.worldbody.add_geom(name="box", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.15, 0.4, 0.25], pos=[0.8, 0, 0.25])
    m = spec.compile()
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, m.key("walk_pose").id)
    return m, d


def bend(ctrl, actuator, side, knee_rad):
    """A knee bend with the hip and the ankle taking half each, so that the foot keeps its pitch."""
    ctrl[actuator[f"leg_{side}_4_joint"]] += knee_rad
    ctrl[actuator[f"leg_{side}_3_joint"]] -= knee_rad / 2
    ctrl[actuator[f"leg_{side}_5_joint"]] -= knee_rad / 2


def controller_targets(t_s, ctrl0, actuator):
    """The PD targets at time t_s: the keyframe's, squatted or stepping (the module's docstring)."""
    ctrl = ctrl0.copy()
    if SETTLE_S <= t_s < SQUAT_END_S:
        knee = 0.5 * SQUAT_KNEE_RAD * (1 - np.cos(2 * np.pi * (t_s - SETTLE_S) / (SQUAT_END_S - SETTLE_S)))
        for side in ("left", "right"):
            bend(ctrl, actuator, side, knee)
    elif t_s >= SQUAT_END_S:
        phase = (t_s - SQUAT_END_S) / STEP_PERIOD_S
        side = "left" if int(phase) % 2 == 0 else "right"
        lift = np.sin(np.pi * (phase % 1.0))
        bend(ctrl, actuator, side, STEP_KNEE_RAD * lift)
        # the lifted leg swings a little outward (hip roll), clear of the standing one
        ctrl[actuator[f"leg_{side}_2_joint"]] += (1 if side == "left" else -1) * STEP_HIP_ROLL_RAD * lift
    return ctrl


def soft_support(m, d, base, z_target_m):
    """The assist: a spring-damper on the pelvis's height and attitude only (x, y and yaw free)."""
    k_z, c_z = SUPPORT_Z
    k_a, c_a = SUPPORT_ATTITUDE
    quat = d.qpos[3:7]
    attitude_error = 2 * quat[1:4] * np.sign(quat[0])  # small-angle rotation vector from upright
    attitude_error[2] = 0.0                            # yaw is not held
    w = d.qvel[3:6].copy()
    w[2] = 0.0
    force = np.zeros(6)
    force[2] = k_z * (z_target_m - d.qpos[2]) - c_z * d.qvel[2]
    force[3:6] = -k_a * attitude_error - c_a * w
    d.xfrc_applied[base] = force


def state_of(m, d, hinges):
    """proxsim's step arguments from MuJoCo's qpos: every hinge by name (proxsim's q is MuJoCo's qpos),
    and the free joint's position and quaternion (w, x, y, z)."""
    return {name: float(d.qpos[a]) for name, a in hinges.items()}, (d.qpos[0:3].copy(), d.qpos[3:7].copy())


def run(out=None, duration_s=None, talos_dir=TALOS_DIR, scenario=SCENARIO):
    """Steps MuJoCo and proxsim together. Returns a dict: the states handed to proxsim (`states`:
    q, X_WP, t_s), proxsim's summary, per sample proxsim's truth and readings (`truth`, `obs`), and
    what MuJoCo itself saw at each sample (`mujoco`: pelvis height, foot-floor contacts, whether
    the support acted, and MuJoCo's own mj_ray along each proxsim ray)."""
    m, d = build_mujoco(talos_dir)
    actuator = {m.actuator(i).name[: -len("_position")]: i for i in range(m.nu)}
    ctrl0 = d.ctrl.copy()
    hinges = {m.joint(j).name: m.jnt_qposadr[j] for j in range(m.njnt) if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE}
    base = m.body("base_link").id
    floor = m.geom("floor").id
    feet = {m.body(f).id for f in ("leg_left_6_link", "leg_right_6_link")}
    record = {"states": [], "truth": [], "obs": [], "mujoco": []}
    z_support = None
    with proxsim.Simulation(scenario, out=out) as sim:
        assert sim.external, "the scenario's robot must have locomotion: external"
        duration_s = duration_s or sim.summary()["inputs"]["duration_s"]
        physics_steps = round(1.0 / (sim.rate_hz * m.opt.timestep))   # 1 kHz physics, 100 Hz sensors
        samples = min(round(duration_s * sim.rate_hz), round(sim.summary()["inputs"]["duration_s"] * sim.rate_hz))
        for k in range(samples):
            assisted = False
            if k > 0:  # sample 0 is the keyframe itself, at t = 0
                for _ in range(physics_steps):
                    d.ctrl[:] = controller_targets(d.time, ctrl0, actuator)
                    if d.time >= SQUAT_END_S:
                        z_support = d.qpos[2] if z_support is None else z_support
                        soft_support(m, d, base, z_support)
                        assisted = True
                    mujoco.mj_step(m, d)
            else:
                mujoco.mj_forward(m, d)
            q, X_WP = state_of(m, d, hinges)
            obs = sim.step(q=q, X_WP=X_WP)
            truth = sim.truth()
            # MuJoCo's own ray along each of proxsim's rays (the robot's geoms left out: groups 0 and 1 only)
            rays = []
            for origin, direction in zip(obs["readings"]["origin_W"], obs["readings"]["dir_W"]):
                geom = np.array([-1], dtype=np.int32)
                distance = mujoco.mj_ray(m, d, origin, direction, np.array([1, 1, 0, 0, 0, 0], dtype=np.uint8), 1, -1,
                                         geom, None)
                rays.append((distance, m.geom(geom[0]).name if geom[0] >= 0 else None))
            contacts = [c for c in d.contact[: d.ncon] if floor in (c.geom1, c.geom2)]
            record["states"].append({"t_s": obs["t_s"], "q": q, "X_WP": X_WP})
            record["obs"].append(obs)
            record["truth"].append(truth)
            record["mujoco"].append({
                "t_s": d.time, "pelvis_z_m": float(d.qpos[2]), "assisted": assisted, "rays": rays,
                "feet_on_floor": sorted({m.body(m.geom_bodyid[g]).name for c in contacts for g in (c.geom1, c.geom2)
                                         if m.geom_bodyid[g] in feet}),
                "other_on_floor": sorted({m.body(m.geom_bodyid[g]).name for c in contacts for g in (c.geom1, c.geom2)
                                          if g != floor and m.geom_bodyid[g] not in feet}),
            })
        record["summary"] = sim.summary()
    return record


def replay(states, out=None, scenario=SCENARIO):
    """proxsim alone, driven by recorded states: the same scenario, the same calls."""
    with proxsim.Simulation(scenario, out=out) as sim:
        for s in states:
            sim.step(q=s["q"], X_WP=s["X_WP"])
        return sim.summary()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default="talos-live", help="proxsim's output folder")
    parser.add_argument("--talos", default=TALOS_DIR, help="Menagerie's pal_talos folder")
    args = parser.parse_args()
    record = run(out=args.out, talos_dir=args.talos)
    lows = [r["pelvis_z_m"] for r in record["mujoco"]]
    robot = record["summary"]["robot"]
    squat = [r["pelvis_z_m"] for r in record["mujoco"] if SETTLE_S <= r["t_s"] < SQUAT_END_S]
    print(f"{len(record['states'])} samples; pelvis from {max(lows):.3f} m down to {min(squat):.3f} m in the squat "
          f"(unassisted), stepping assisted from t = {SQUAT_END_S} s")
    print(f"proxsim: outcome {robot['outcome']}, collisions {len(robot['collisions'])}; "
          f"files in {args.out}/ (proxsim plot {args.out} draws them)")


if __name__ == "__main__":
    main()

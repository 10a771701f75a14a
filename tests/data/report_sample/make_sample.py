#!/usr/bin/env python3
"""Writes a SYNTHETIC proxsim run (readings.csv, poses.csv, profile.ply,
scene.json, summary.json) for developing and testing the report and viewer
without the C++ simulator.

  make_sample.py OUT            a biped walking toward an obstacle, four tibia
                                sensors (ideal, laser, ultrasonic, reflectance)
  make_sample.py OUT --no-robot world-mounted sensors facing a box, a sphere, a
                                cylinder and the floor, and one that sees nothing

The kinematics are a rough gait (no planted foot), the sensor models follow the
paper's (§5) presets, the noise is seeded: the files have the formats of the
output contract, not the physics of the real simulator.
"""
import argparse
import csv
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sample_geometry import cast, quat_from_rpy, quat_to_matrix  # noqa: E402

# sensor presets: min range, max range, max incidence (paper §5 / docs/sensors.md)
PRESETS = {"ideal": (0.0, 2.0, 90.0), "laser": (0.0, 2.0, 45.0),
           "ultrasonic": (0.1, 1.0, 15.0), "reflectance": (0.0, 1.0, 90.0)}
MOUNT_PITCH_DEG = float(os.environ.get("SAMPLE_PITCH", 15))
THIGH_M, TIBIA_M, ANKLE_M, HIP_Y_M = 0.45, 0.45, 0.08, 0.1


def obj(name, shape, xyz, rpy=(0, 0, 0), albedo=0.6, specular=0.0, **dims):
    o = {"name": name, "shape": shape, "xyz_m": list(xyz),
         "quat_wxyz": [round(v, 6) for v in quat_from_rpy(*np.radians(rpy))],
         "albedo": albedo, "specular": specular}
    o.update(dims)
    return o


def walk_scene():
    objects = [
        obj("floor", "plane", (0, 0, 0), albedo=0.5, specular=0.1),
        obj("obstacle", "box", (8.5, 0, 0.15), size_m=[0.25, 0.6, 0.3], albedo=0.8),
        obj("ball", "sphere", (9.2, 0.05, 0.15), radius_m=0.15),
        obj("post", "cylinder", (9.8, -0.05, 0.5), radius_m=0.1, length_m=1.0),
        obj("log", "cylinder", (8.85, 0, 0.08), rpy=(90, 0, 0), radius_m=0.08, length_m=1.2),
        obj("back_wall", "box", (10.5, 0, 1.25), size_m=[0.1, 4.0, 2.5]),
        obj("left_wall", "box", (5.0, 2.0, 1.25), size_m=[11.0, 0.1, 2.5]),
        obj("right_wall", "box", (5.0, -2.0, 1.25), size_m=[11.0, 0.1, 2.5]),
    ]
    for i, o in enumerate(objects):
        o["id"] = i
    return objects


def biped_links():
    cyl = lambda r, l, z: {"shape": "cylinder", "radius_m": r, "length_m": l,
                           "xyz_m": [0, 0, z], "quat_wxyz": [1, 0, 0, 0]}
    box = lambda s, xyz: {"shape": "box", "size_m": s, "xyz_m": xyz, "quat_wxyz": [1, 0, 0, 0]}
    links = [{"name": "pelvis", "shapes": [
        box([0.2, 0.3, 0.15], [0, 0, 0]), box([0.22, 0.36, 0.55], [0, 0, 0.38]),
        {"shape": "sphere", "radius_m": 0.11, "xyz_m": [0, 0, 0.78], "quat_wxyz": [1, 0, 0, 0]}]}]
    for side in ("left", "right"):
        links += [{"name": f"{side}_thigh", "shapes": [cyl(0.06, THIGH_M, -THIGH_M / 2)]},
                  {"name": f"{side}_tibia", "shapes": [cyl(0.05, TIBIA_M, -TIBIA_M / 2)]},
                  {"name": f"{side}_foot", "shapes": [box([0.24, 0.1, 0.05], [0.05, 0, -0.055])]}]
    return links


def leg_angles(phase):
    """Thigh and tibia pitch (rad, world) at a gait phase; positive = backward."""
    hip = 0.35 * np.cos(2 * np.pi * phase)
    swing = np.clip((phase - 0.6) / 0.4, 0, 1)
    knee = 0.12 * np.sin(np.pi * np.clip(phase / 0.6, 0, 1)) + 1.0 * np.sin(np.pi * swing) ** 2
    return -hip, -hip + knee


def biped_poses(t, stop_x):
    """World poses (xyz, quat) per link per sample, gait phase and support leg."""
    period, speed = 1.2, 0.5
    x = np.minimum(speed * t, stop_x)
    walking = speed * t < stop_x
    phase = np.where(walking, (t / period) % 1.0, 0.0)
    ang = {}
    for side, off in (("left", 0.0), ("right", 0.5)):
        th, tb = leg_angles((phase + off) % 1.0)
        ang[side] = (np.where(walking, th, 0.0), np.where(walking, tb, 0.0))
    reach = np.maximum(*[THIGH_M * np.cos(a[0]) + TIBIA_M * np.cos(a[1]) for a in ang.values()])
    z = reach + ANKLE_M
    poses = {"pelvis": (np.stack([x, np.zeros_like(x), z], 1), [quat_from_rpy(0, 0, 0)] * len(t))}
    for side, y in (("left", HIP_Y_M), ("right", -HIP_Y_M)):
        th, tb = ang[side]
        hip = np.stack([x, np.full_like(x, y), z], 1)
        knee = hip + THIGH_M * np.stack([-np.sin(th), 0 * th, -np.cos(th)], 1)
        ankle = knee + TIBIA_M * np.stack([-np.sin(tb), 0 * tb, -np.cos(tb)], 1)
        poses[f"{side}_thigh"] = (hip, [quat_from_rpy(0, a, 0) for a in th])
        poses[f"{side}_tibia"] = (knee, [quat_from_rpy(0, a, 0) for a in tb])
        poses[f"{side}_foot"] = (ankle, [quat_from_rpy(0, 0, 0)] * len(t))
    left_stance = ((phase % 1.0) < 0.6) | ~walking
    right_stance = (((phase + 0.5) % 1.0) < 0.6) | ~walking
    support = np.where(left_stance & right_stance, "double", np.where(left_stance, "left", "right"))
    return poses, np.where(walking, phase, 0.0), support


def measure(kind, t_hit, normal, dirs, rng):
    """Paper §5 models: status, detected, measured distance, truth, incidence, signal."""
    dmin, dmax, max_inc = PRESETS[kind]
    within = t_hit <= dmax
    d_true = np.where(within, t_hit, np.nan)
    cos_a = np.clip(-np.sum(normal * dirs, axis=1), 0, 1)
    inc = np.degrees(np.arccos(cos_a))
    status = np.where(~within, "no_echo", np.where(t_hit < dmin, "too_close",
                      np.where(inc > max_inc, "grazing", "ok")))
    ok = status == "ok"
    noise = 0.0 if kind == "ideal" else 0.01 * rng.standard_normal(len(t_hit))
    signal = np.full(len(t_hit), np.nan)
    if kind == "reflectance":
        d = np.where(ok, d_true, dmax)
        s = (dmax - d) / d ** 2 * cos_a ** 2 * (1 + noise)
        signal = np.where(ok, s, 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            d_m = (-1 + np.sqrt(1 + 4 * s * dmax)) / (2 * s)
    else:
        d_m = d_true * (1 + noise)
    d_m = np.where(ok, d_m, dmax)
    return status, ok, d_m, d_true, np.where(within, inc, np.nan), signal


def fmt(v):
    return "" if v is None or (isinstance(v, float) and not math.isfinite(v)) else f"{v:.6g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--no-robot", action="store_true")
    ap.add_argument("--duration", type=float, default=None)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rng = np.random.default_rng(7)
    rate = 50.0

    if args.no_robot:
        duration = args.duration or 2.0
        objects = [obj("floor", "plane", (0, 0, 0)),
                   obj("wall_box", "box", (1.05, 0, 0.5), rpy=(0, 0, 20), size_m=[0.1, 2.0, 1.0]),
                   obj("ball", "sphere", (0.6, 1.0, 0.3), radius_m=0.15),
                   obj("post", "cylinder", (0.8, -1.0, 0.5), radius_m=0.1, length_m=1.0)]
        for i, o in enumerate(objects):
            o["id"] = i
        mounts = [("ideal_box", "ideal", (0, 0, 0.3), 0), ("laser_box", "laser", (0, 0.1, 0.3), 0),
                  ("ultrasonic_box", "ultrasonic", (0, -0.1, 0.3), 0),
                  ("reflectance_ball", "reflectance", (0, 1.0, 0.3), 0),
                  ("laser_floor", "laser", (0, -0.5, 0.5), 30), ("laser_sky", "laser", (0, 0.5, 0.5), -60)]
        sensors = [{"index": i, "name": n, "type": k, "link": "world", "min_range_m": PRESETS[k][0],
                    "max_range_m": PRESETS[k][1], "max_incidence_deg": PRESETS[k][2]}
                   for i, (n, k, _, _) in enumerate(mounts)]
        robot, links = None, None
    else:
        duration = args.duration or 20.0
        objects = walk_scene()
        links = biped_links()
        robot = {"links": links}
        mounts = [("ideal_left_tibia", "ideal", "left_tibia"), ("laser_left_tibia", "laser", "left_tibia"),
                  ("ultrasonic_right_tibia", "ultrasonic", "right_tibia"),
                  ("reflectance_right_tibia", "reflectance", "right_tibia")]
        sensors = [{"index": i, "name": n, "type": k, "link": l, "min_range_m": PRESETS[k][0],
                    "max_range_m": PRESETS[k][1], "max_incidence_deg": PRESETS[k][2]}
                   for i, (n, k, l) in enumerate(mounts)]

    t = np.arange(int(round(duration * rate))) / rate
    n = len(t)
    if robot:
        poses, phase, support = biped_poses(t, stop_x=7.95)
    rows, ply = [], []
    for s in sensors:
        if robot:
            p_link, q_link = poses[s["link"]]
            mount_q = quat_from_rpy(0, np.radians(MOUNT_PITCH_DEG), 0)
            origins = np.empty((n, 3))
            dirs = np.empty((n, 3))
            for i in range(n):
                R = quat_to_matrix(q_link[i])
                origins[i] = p_link[i] + R @ np.array([0.06, 0, -0.15])
                dirs[i] = R @ quat_to_matrix(mount_q) @ np.array([1.0, 0, 0])
        else:
            _, _, xyz, pitch = mounts[s["index"]]
            origins = np.tile(xyz, (n, 1)).astype(float)
            dirs = np.tile([math.cos(math.radians(pitch)), 0, -math.sin(math.radians(pitch))], (n, 1))
        t_hit, normal, idx = cast(objects, origins, dirs)
        status, ok, d_m, d_true, inc, signal = measure(s["type"], t_hit, normal, dirs, rng)
        within = np.isfinite(d_true)
        for i in range(n):
            hit = origins[i] + t_hit[i] * dirs[i] if within[i] else [None] * 3
            name = objects[idx[i]]["name"] if within[i] else ""
            rows.append([fmt(t[i]), s["name"], s["type"], status[i], int(ok[i]), fmt(d_m[i]), fmt(d_true[i]),
                         fmt(inc[i]), fmt(signal[i]) if s["type"] == "reflectance" else "",
                         *[fmt(v) for v in hit], *[fmt(v) for v in origins[i]], *[fmt(v) for v in dirs[i]],
                         name, fmt(phase[i]) if robot else "", support[i] if robot else ""])
            if ok[i]:
                p = origins[i] + d_m[i] * dirs[i]
                ply.append((*p, s["index"], t[i], idx[i]))
    rows.sort(key=lambda r: float(r[0]))

    header = ("t_s,sensor,type,status,detected,d_m,d_true_m,incidence_deg,signal,hit_x_m,hit_y_m,hit_z_m,"
              "origin_x_m,origin_y_m,origin_z_m,dir_x,dir_y,dir_z,object,gait_phase,support_leg").split(",")
    with open(os.path.join(args.out, "readings.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    # columns.json as proxsim writes it beside readings.csv, for this file's columns
    # (a subset of proxsim's: `proxsim columns` lists them all)
    codes = {"sensor": "sensors", "type": "types", "status": "statuses", "object": "objects",
             "support_leg": "support_legs"}
    columns = [{"name": c, "dtype": "|b1" if c == "detected" else "<i4" if c in codes else "<f8",
                **({"codes": codes[c]} if c in codes else {})} for c in header]
    with open(os.path.join(args.out, "columns.json"), "w") as f:
        json.dump({"columns": columns, "sensors": [s["name"] for s in sensors],
                   "types": list(PRESETS), "statuses": ["ok", "no_echo", "too_close", "grazing"],
                   "objects": [o["name"] for o in objects], "support_legs": ["left", "right", "double"]}, f, indent=1)
    if robot:
        with open(os.path.join(args.out, "poses.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["t_s", "link", "x", "y", "z", "qw", "qx", "qy", "qz"])
            for i in range(n):
                for link in links:
                    p, q = poses[link["name"]]
                    w.writerow([fmt(t[i]), link["name"], *[fmt(v) for v in p[i]], *[fmt(v) for v in q[i]]])
    elif os.path.exists(os.path.join(args.out, "poses.csv")):
        os.remove(os.path.join(args.out, "poses.csv"))
    with open(os.path.join(args.out, "profile.ply"), "w") as f:
        f.write(f"ply\nformat ascii 1.0\ncomment proxsim synthetic sample\nelement vertex {len(ply)}\n"
                "property float x\nproperty float y\nproperty float z\nproperty int sensor\n"
                "property float t_s\nproperty int object\nend_header\n")
        for x, y, z, si, ts, oi in ply:
            f.write(f"{x:.5f} {y:.5f} {z:.5f} {si} {ts:.4f} {oi}\n")
    scene = {"duration_s": duration, "rate_hz": rate, "objects": objects, "robot": robot, "sensors": sensors}
    with open(os.path.join(args.out, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
    with open(os.path.join(args.out, "summary.json"), "w") as f:
        json.dump({"synthetic": True, "samples": n, "detections": len(ply)}, f, indent=1)
    print(f"make_sample: wrote {n} samples × {len(sensors)} sensors, {len(ply)} profile points to {args.out}")


if __name__ == "__main__":
    main()

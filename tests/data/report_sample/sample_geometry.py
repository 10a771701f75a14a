"""Tiny exact ray caster and rotation helpers for the synthetic report sample.

Only the sample generator uses it: it lets make_sample.py write readings that
look like a real run's (floor seen in swing, an obstacle ahead) without the C++
simulator. Shapes follow scene.json: box (full extents), sphere, cylinder (axis =
local z, centred), plane (z = 0 of its frame, facing +z).
"""
import numpy as np


def quat_from_rpy(roll, pitch, yaw):
    """Quaternion (w, x, y, z) of R = Rz(yaw)·Ry(pitch)·Rx(roll), angles in radians."""
    cr, sr = np.cos(roll / 2), np.sin(roll / 2)
    cp, sp = np.cos(pitch / 2), np.sin(pitch / 2)
    cy, sy = np.cos(yaw / 2), np.sin(yaw / 2)
    return np.array([cr * cp * cy + sr * sp * sy,
                     sr * cp * cy - cr * sp * sy,
                     cr * sp * cy + sr * cp * sy,
                     cr * cp * sy - sr * sp * cy])


def quat_to_matrix(q):
    """Rotation matrix of a unit quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def _box(o, d, half):
    # slabs: entry = max of near planes, exit = min of far planes
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (-half - o) / d
        t2 = (half - o) / d
    tn = np.nanmax(np.minimum(t1, t2), axis=1)
    tf = np.nanmin(np.maximum(t1, t2), axis=1)
    t = np.where((tn <= tf) & (tn > 1e-9), tn, np.inf)
    axis = np.argmax(np.minimum(t1, t2), axis=1)
    n = np.zeros_like(o)
    n[np.arange(len(o)), axis] = -np.sign(d[np.arange(len(o)), axis])
    return t, n


def _sphere(o, d, r):
    # |o + t d|^2 = r^2, nearest positive root
    b = np.sum(o * d, axis=1)
    c = np.sum(o * o, axis=1) - r * r
    disc = b * b - c
    t = -b - np.sqrt(np.maximum(disc, 0))
    t = np.where((disc >= 0) & (t > 1e-9), t, np.inf)
    p = o + t[:, None] * d
    return t, p / r


def _cylinder(o, d, r, length):
    # side: x^2 + y^2 = r^2 within |z| <= length/2; caps: z = ±length/2 within r
    a = d[:, 0] ** 2 + d[:, 1] ** 2
    b = o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1]
    c = o[:, 0] ** 2 + o[:, 1] ** 2 - r * r
    disc = b * b - a * c
    with np.errstate(divide="ignore", invalid="ignore"):
        ts = (-b - np.sqrt(np.maximum(disc, 0))) / a
    zs = o[:, 2] + ts * d[:, 2]
    ts = np.where((disc >= 0) & (a > 1e-12) & (ts > 1e-9) & (np.abs(zs) <= length / 2), ts, np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        tc = (-np.sign(d[:, 2]) * length / 2 - o[:, 2]) / d[:, 2]
    pc = o + tc[:, None] * d
    tc = np.where((tc > 1e-9) & (pc[:, 0] ** 2 + pc[:, 1] ** 2 <= r * r), tc, np.inf)
    t = np.minimum(ts, tc)
    p = o + np.where(np.isfinite(t), t, 0)[:, None] * d
    n = np.stack([p[:, 0], p[:, 1], np.zeros(len(o))], axis=1) / r
    cap = tc < ts
    n[cap] = 0
    n[cap, 2] = -np.sign(d[cap, 2])
    return t, n


def _plane(o, d):
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -o[:, 2] / d[:, 2]
    t = np.where((t > 1e-9) & (o[:, 2] > 0), t, np.inf)
    n = np.zeros_like(o)
    n[:, 2] = 1
    return t, n


@np.errstate(invalid="ignore", divide="ignore")
def cast(objects, origins, dirs):
    """First hit of each ray (origins, dirs: N×3 world) against scene objects.

    Returns (t, normal N×3 world, object index, -1 when nothing was hit).
    """
    best_t = np.full(len(origins), np.inf)
    best_n = np.zeros_like(origins)
    best_i = np.full(len(origins), -1)
    for idx, ob in enumerate(objects):
        R = quat_to_matrix(ob["quat_wxyz"])
        o = (origins - np.asarray(ob["xyz_m"])) @ R
        d = dirs @ R
        shape = ob["shape"]
        if shape == "box":
            t, n = _box(o, d, np.asarray(ob["size_m"]) / 2)
        elif shape == "sphere":
            t, n = _sphere(o, d, ob["radius_m"])
        elif shape == "cylinder":
            t, n = _cylinder(o, d, ob["radius_m"], ob["length_m"])
        elif shape == "plane":
            t, n = _plane(o, d)
        else:
            continue
        closer = t < best_t
        best_t[closer] = t[closer]
        best_n[closer] = (n @ R.T)[closer]
        best_i[closer] = idx
    return best_t, best_n, best_i

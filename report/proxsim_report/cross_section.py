"""The true cross-section of the scene along the walking path, from scene.json.

Along vertical lines standing on the (laterally offset) path, every convex
shape (box, sphere, cylinder) is cut exactly into one z interval [bottom, top];
a mesh gives the lowest and highest z where the line crosses its triangles;
a plane (the z = 0 plane of its frame, solid below) gives one height per line,
or, when vertical, the path distance where the path crosses it.
"""
from dataclasses import dataclass

import numpy as np


def quat_to_matrix(q):
    """Rotation matrix of a quaternion (w, x, y, z), normalised first."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


@dataclass
class Section:
    """One object's cut: bottom/top per path sample (NaN where missed)."""
    name: str
    object_id: int
    bottom: np.ndarray
    top: np.ndarray
    solid_below: bool = False     # planes: the solid reaches down from `top`
    wall_s: float = None          # vertical plane: path distance of the crossing
    wall_solid_after: bool = True


def _line_slab(o, d, lo, hi):
    """Parameter interval of lines o + z d (N×3, d shared) inside lo ≤ p ≤ hi."""
    t_lo = np.full(len(o), -np.inf)
    t_hi = np.full(len(o), np.inf)
    for a in range(3):
        if abs(d[a]) < 1e-12:
            outside = (o[:, a] < lo[a]) | (o[:, a] > hi[a])
            t_lo[outside], t_hi[outside] = np.inf, -np.inf
        else:
            t1, t2 = (lo[a] - o[:, a]) / d[a], (hi[a] - o[:, a]) / d[a]
            t_lo = np.maximum(t_lo, np.minimum(t1, t2))
            t_hi = np.minimum(t_hi, np.maximum(t1, t2))
    return t_lo, t_hi


def _line_sphere(o, d, r):
    b = o @ d
    disc = b * b - (np.sum(o * o, axis=1) - r * r)
    root = np.sqrt(np.maximum(disc, 0))
    miss = disc < 0
    return np.where(miss, np.inf, -b - root), np.where(miss, -np.inf, -b + root)


def _line_cylinder(o, d, r, length):
    # inside the infinite cylinder x² + y² ≤ r² ...
    a = d[0] ** 2 + d[1] ** 2
    if a < 1e-12:
        inside = o[:, 0] ** 2 + o[:, 1] ** 2 <= r * r
        t_lo, t_hi = np.where(inside, -np.inf, np.inf), np.where(inside, np.inf, -np.inf)
    else:
        b = o[:, 0] * d[0] + o[:, 1] * d[1]
        disc = b * b - a * (o[:, 0] ** 2 + o[:, 1] ** 2 - r * r)
        root = np.sqrt(np.maximum(disc, 0))
        t_lo = np.where(disc < 0, np.inf, (-b - root) / a)
        t_hi = np.where(disc < 0, -np.inf, (-b + root) / a)
    # ... and between the caps
    c_lo, c_hi = _line_slab(o, d, np.array([-np.inf, -np.inf, -length / 2]),
                            np.array([np.inf, np.inf, length / 2]))
    return np.maximum(t_lo, c_lo), np.minimum(t_hi, c_hi)


def _mesh_interval(xy, obj, R, c):
    """Lowest and highest z where vertical lines at xy cross the mesh's triangles."""
    v = np.asarray(obj.get("vertices_m", []), dtype=float).reshape(-1, 3) @ R.T + c
    tri = np.asarray(obj.get("triangles", []), dtype=int).reshape(-1, 3)
    lo = np.full(len(xy), np.inf)
    hi = np.full(len(xy), -np.inf)
    for start in range(0, len(tri), 2000):
        a, b, cc = (v[tri[start:start + 2000, k]] for k in range(3))
        # barycentric coordinates of each line's foot in each triangle's xy shadow
        e1, e2 = (b - a)[:, :2], (cc - a)[:, :2]
        det = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
        ok = np.abs(det) > 1e-12
        rel = xy[:, None, :] - a[None, :, :2]
        with np.errstate(divide="ignore", invalid="ignore"):
            u = (rel[..., 0] * e2[:, 1] - rel[..., 1] * e2[:, 0]) / det
            w = (e1[:, 0] * rel[..., 1] - e1[:, 1] * rel[..., 0]) / det
        inside = ok & (u >= 0) & (w >= 0) & (u + w <= 1)
        z = a[:, 2] + u * (b - a)[:, 2] + w * (cc - a)[:, 2]
        lo = np.minimum(lo, np.where(inside, z, np.inf).min(axis=1))
        hi = np.maximum(hi, np.where(inside, z, -np.inf).max(axis=1))
    return lo, hi


def cut_object(obj, path, s, lateral=0.0):
    """Section of one scene.json object along vertical lines at path distances s."""
    xy = path.point_at(s, lateral)
    R = quat_to_matrix(obj.get("quat_wxyz", [1, 0, 0, 0]))
    c = np.asarray(obj.get("xyz_m", [0, 0, 0]), dtype=float)
    name, oid, shape = obj.get("name", "?"), int(obj.get("id", -1)), obj.get("shape")
    nan = np.full(len(s), np.nan)
    if shape == "plane":
        n = R[:, 2]
        if abs(n[2]) > 1e-6:
            z = c[2] - (n[0] * (xy[:, 0] - c[0]) + n[1] * (xy[:, 1] - c[1])) / n[2]
            return Section(name, oid, nan, z, solid_below=n[2] > 0)
        side = (xy - c[:2]) @ n[:2]
        flips = np.nonzero(np.diff(np.sign(side)))[0]
        if len(flips) == 0:
            return None
        k = flips[0]
        after = side[k + 1:][side[k + 1:] != 0]   # the first sample strictly past the plane
        return Section(name, oid, nan, nan, wall_s=float(s[k]),
                       wall_solid_after=bool(len(after) == 0 or after[0] < 0))
    if shape == "mesh":
        lo, hi = _mesh_interval(xy, obj, R, c)
    else:
        # the vertical lines, in the object's frame: o + z·d
        o = (np.column_stack([xy, np.zeros(len(s))]) - c) @ R
        d = R.T @ np.array([0.0, 0.0, 1.0])
        if shape == "box":
            half = np.asarray(obj["size_m"], dtype=float) / 2
            t_lo, t_hi = _line_slab(o, d, -half, half)
        elif shape == "sphere":
            t_lo, t_hi = _line_sphere(o, d, float(obj["radius_m"]))
        elif shape == "cylinder":
            t_lo, t_hi = _line_cylinder(o, d, float(obj["radius_m"]), float(obj["length_m"]))
        else:
            return None
        lo, hi = t_lo, t_hi   # z of the world line = parameter t, since |d| = 1 and it starts at z = 0
    hit = lo <= hi
    if not hit.any():
        return None
    return Section(name, oid, np.where(hit, lo, np.nan), np.where(hit, hi, np.nan))


def cut_scene(scene, path, s, lateral=0.0):
    """Sections of every object of scene.json that the path's vertical surface meets."""
    cuts = [cut_object(o, path, s, lateral) for o in scene.get("objects", [])]
    return [c for c in cuts if c is not None]

"""The walking path: the horizontal axis of the profile figures.

With a robot, the path is the pelvis (or root link) track on the floor, as a
polyline; points are projected onto it as (s = distance along the path,
lateral = signed offset, left positive). Without a robot, the path is the
world x axis (s = x, lateral = y). Beyond its ends the path goes on straight.
"""
import numpy as np


class WalkPath:
    def __init__(self, xy):
        """xy: K×2 path vertices in order (at least two, distinct)."""
        self.xy = np.asarray(xy, dtype=float)
        seg = np.diff(self.xy, axis=0)
        self.seg_len = np.linalg.norm(seg, axis=1)
        self.seg_dir = seg / self.seg_len[:, None]
        self.s_start = np.concatenate([[0.0], np.cumsum(self.seg_len)])[:-1]
        self.length = float(self.seg_len.sum())

    def project(self, xy):
        """(s, lateral) of points xy (N×2) on the path."""
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        rel = xy[:, None, :] - self.xy[None, :-1, :]
        along = np.einsum("nkj,kj->nk", rel, self.seg_dir)
        # the first and last segments extend to infinity, inner ones are clamped
        lo = np.zeros(len(self.seg_len))
        hi = self.seg_len.copy()
        lo[0], hi[-1] = -np.inf, np.inf
        along_c = np.clip(along, lo, hi)
        foot = self.xy[None, :-1, :] + along_c[..., None] * self.seg_dir[None]
        dist = np.linalg.norm(xy[:, None, :] - foot, axis=2)
        k = np.argmin(dist, axis=1)
        n = np.arange(len(xy))
        d = self.seg_dir[k]
        r = rel[n, k]
        lateral = d[:, 0] * r[:, 1] - d[:, 1] * r[:, 0]
        return self.s_start[k] + along_c[n, k], lateral

    def point_at(self, s, lateral=0.0):
        """World xy (N×2) at distances s along the path, offset sideways by lateral."""
        s = np.asarray(s, dtype=float)
        k = np.clip(np.searchsorted(self.s_start, s, side="right") - 1, 0, len(self.seg_len) - 1)
        d = self.seg_dir[k]
        p = self.xy[k] + (s - self.s_start[k])[:, None] * d
        left = np.stack([-d[:, 1], d[:, 0]], axis=1)
        return p + np.asarray(lateral)[..., None] * left


def _root_link(run):
    links = [l["name"] for l in (run.scene.get("robot") or {}).get("links", [])]
    for name in ("pelvis", "base_link", "base", "torso"):
        if name in run.poses:
            return name
    return next((l for l in links if l in run.poses), next(iter(run.poses), None))


def simplify(xy, tolerance_m):
    """Ramer–Douglas–Peucker: the fewest vertices of the polyline xy that stay
    within tolerance_m of it (a straight walk with its sway becomes one segment)."""
    keep = np.zeros(len(xy), dtype=bool)
    keep[[0, -1]] = True
    stack = [(0, len(xy) - 1)]
    while stack:
        a, b = stack.pop()
        if b <= a + 1:
            continue
        d = xy[b] - xy[a]
        rel = xy[a + 1:b] - xy[a]
        length = np.hypot(*d)
        dist = (np.abs(d[0] * rel[:, 1] - d[1] * rel[:, 0]) / length if length > 1e-12
                else np.hypot(rel[:, 0], rel[:, 1]))
        k = int(np.argmax(dist))
        if dist[k] > tolerance_m:
            keep[a + 1 + k] = True
            stack += [(a, a + 1 + k), (a + 1 + k, b)]
    return xy[keep]


def path_of_run(run, tolerance_m=0.03):
    """The run's walking path: the root link's floor track, or the x axis."""
    root = _root_link(run)
    if root is not None:
        xy = run.poses[root][1][:, :2]
        xy = xy[np.all(np.isfinite(xy), axis=1)]
        # drop standing still (repeated points), then straighten the sway
        moved = np.concatenate([[True], np.hypot(*np.diff(xy, axis=0).T) > 1e-6]) if len(xy) else []
        xy = xy[moved]
        keep = simplify(xy, tolerance_m) if len(xy) >= 2 else xy
        if len(keep) >= 2:
            return WalkPath(keep), True
        # a robot that stands still: the x axis through where it stands
        start = xy[0] if len(xy) else np.zeros(2)
        return WalkPath(np.array([start, start + [1.0, 0.0]])), True
    return WalkPath(np.array([[0.0, 0.0], [1.0, 0.0]])), False

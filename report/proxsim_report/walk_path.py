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


def path_of_run(run, min_step_m=0.02):
    """The run's walking path: the root link's floor track, or the x axis."""
    root = _root_link(run)
    if root is not None:
        xy = run.poses[root][1][:, :2]
        keep = [xy[0]]
        for p in xy[1:]:
            if np.linalg.norm(p - keep[-1]) >= min_step_m:
                keep.append(p)
        if len(keep) >= 2:
            return WalkPath(np.array(keep)), True
        # a robot that stands still: the x axis through where it stands
        return WalkPath(np.array([xy[0], xy[0] + [1.0, 0.0]])), True
    return WalkPath(np.array([[0.0, 0.0], [1.0, 0.0]])), False

"""Reads a run's terrain map (OUT/terrain/: meta.json, the .npy arrays,
hazards.csv) and the score summary.json gives it (None when the run has no
map), and the height range the figure and the viewer both colour over."""
import csv
import json
import os
from dataclasses import dataclass

import numpy as np


@dataclass
class TerrainData:
    resolution_m: float
    origin_xy_m: tuple          # (x0, y0): cell (i, j) covers x0 + j·r .. x0 + (j+1)·r, y0 + i·r ..
    elevation: np.ndarray       # (ny, nx) float32, NaN where never measured
    variance: np.ndarray
    upper_bound: np.ndarray     # NaN where no bound
    truth: np.ndarray           # NaN where no surface
    first_update_t_s: np.ndarray  # NaN where never measured
    hazards: list               # dicts of hazards.csv, numbers as floats
    score: dict                 # summary.json "terrain" ({} when absent)

    @property
    def extent(self):
        """(x_min, x_max, y_min, y_max) of the arrays, for imshow."""
        ny, nx = self.elevation.shape
        x0, y0 = self.origin_xy_m
        return (x0, x0 + nx * self.resolution_m, y0, y0 + ny * self.resolution_m)


def load_terrain(out_dir):
    """The run's terrain map, or None when it wrote none."""
    folder = os.path.join(out_dir, "terrain")
    meta_path = os.path.join(folder, "meta.json")
    if not os.path.isfile(meta_path):
        return None
    with open(meta_path) as f:
        meta = json.load(f)
    arrays = {name: np.load(os.path.join(folder, f"{name}.npy"))
              for name in ("elevation", "variance", "upper_bound", "truth", "first_update_t_s")}
    hazards = []
    with open(os.path.join(folder, "hazards.csv")) as f:
        for row in csv.DictReader(f):
            hazards.append({k: (v if k == "class" else (float(v) if v != "" else float("nan"))) for k, v in row.items()})
    score = {}
    try:
        with open(os.path.join(out_dir, "summary.json")) as f:
            score = json.load(f).get("terrain") or {}
    except (OSError, ValueError):
        pass
    return TerrainData(meta["resolution_m"], tuple(meta["origin_xy_m"]), hazards=hazards, score=score, **arrays)


def height_limits(terrain):
    """(low, high) of the height colour scale: the 0.5–99.5 percentiles of the
    map's and the truth's heights (a stray point does not flatten the scale),
    widened to at least 10 cm (a flat floor is not all one colour's extreme)."""
    values = np.concatenate([a[np.isfinite(a)].ravel() for a in (terrain.elevation, terrain.truth)])
    if values.size == 0:
        return -0.05, 0.05
    lo, hi = float(np.percentile(values, 0.5)), float(np.percentile(values, 99.5))
    return (lo - 0.05, hi + 0.05) if hi - lo < 0.1 else (lo, hi)


def measured_cells(terrain):
    """The cells that hold a height, in the order they first did: (x_m, y_m,
    elevation_m, first_update_t_s) arrays of the cells' centres."""
    iy, ix = np.nonzero(np.isfinite(terrain.elevation))
    t = terrain.first_update_t_s[iy, ix].astype(np.float64)
    order = np.lexsort((ix, iy, t))
    iy, ix, t = iy[order], ix[order], t[order]
    x0, y0 = terrain.origin_xy_m
    r = terrain.resolution_m
    return x0 + (ix + 0.5) * r, y0 + (iy + 0.5) * r, terrain.elevation[iy, ix].astype(np.float64), t

"""The 3D replay viewer's files in OUT/report/: viewer.js (the prebuilt bundle,
copied), data.js (`window.PROXSIM_DATA = {...}`: the scene, link poses per
sample, each sensor's readings as column arrays, the profile points, the
terrain map's cells and hazards, multi-zone sensors' zone points) and index.html, which loads both with plain
<script> tags so it opens from disk."""
import html
import json
import os

import numpy as np

from .run_data import STATUSES, RunError
from .safe_files import write_bytes, write_text
from .style import (HAZARD_COLORS, HAZARD_LABELS, STATUS_COLORS, STATUS_LABELS, VIRIDIS_STOPS, object_color,
                    sensor_color)
from .terrain_data import height_limits, measured_cells


def _col(a, digits=4):
    """A JSON-ready list: rounded floats, None for NaN."""
    a = np.round(np.asarray(a, dtype=float), digits)
    return [None if not np.isfinite(v) else (int(v) if v == int(v) else float(v)) for v in a.tolist()]


def _ray_ends(sensor):
    """End of each sample's ray: the hit point, or origin + d_max·dir."""
    end = sensor.p_origin + sensor.d_max_m * sensor.dir
    hit = np.all(np.isfinite(sensor.p_hit), axis=1)
    end[hit] = sensor.p_hit[hit]
    return end


def _number(v, digits=4):
    """A JSON-ready number: rounded, None for NaN."""
    return None if not np.isfinite(v) else round(float(v), digits)


def _surface_height(terrain, h):
    """Where to mark a hazard: the map's surface in its extent (its highest
    measured cell, else its highest free-space bound), 0 when neither is known."""
    x0, y0 = terrain.origin_xy_m
    r = terrain.resolution_m
    ny, nx = terrain.elevation.shape
    j0 = max(int(np.floor((h["x_m"] - h["size_x_m"] / 2 - x0) / r + 1e-6)), 0)
    j1 = min(int(np.ceil((h["x_m"] + h["size_x_m"] / 2 - x0) / r - 1e-6)), nx)
    i0 = max(int(np.floor((h["y_m"] - h["size_y_m"] / 2 - y0) / r + 1e-6)), 0)
    i1 = min(int(np.ceil((h["y_m"] + h["size_y_m"] / 2 - y0) / r - 1e-6)), ny)
    for layer in (terrain.elevation, terrain.upper_bound):
        block = layer[i0:i1, j0:j1]
        if np.isfinite(block).any():
            return float(np.nanmax(block))
    return 0.0


def terrain_viewer_data(terrain):
    """The map's layer for the viewer: the measured cells in the order they
    first held a height (each drawn with its final height from then on), the
    colour scale, and the hazards with the time each was found."""
    if terrain is None:
        return None
    x, y, z, t = measured_cells(terrain)
    z_lo, z_hi = height_limits(terrain)
    hazards = [{"class": h["class"], "label": HAZARD_LABELS.get(h["class"], h["class"]),
                "color": HAZARD_COLORS.get(h["class"], "#000000"),
                "x": round(h["x_m"], 4), "y": round(h["y_m"], 4),
                "sizeX": round(h["size_x_m"], 4), "sizeY": round(h["size_y_m"], 4),
                "height": round(h["height_m"], 4), "z": round(_surface_height(terrain, h), 4),
                "t": _number(h["first_detection_t_s"]), "distance": _number(h["distance_at_detection_m"])}
               for h in sorted(terrain.hazards, key=lambda h: h["first_detection_t_s"])]
    return {"resolution": terrain.resolution_m, "x": _col(x), "y": _col(y), "z": _col(z), "t": _col(t),
            "zRange": [round(z_lo, 4), round(z_hi, 4)], "colorStops": VIRIDIS_STOPS, "hazards": hazards}


def _plain_folder_name(name):
    """A single folder name (what proxsim writes: SensorFolderName), not a path."""
    return isinstance(name, str) and name not in ("", ".", "..") and "/" not in name and "\0" not in name


def zones_viewer_data(run):
    """Each multi-zone sensor's zones for the viewer (zones/ of the run, when
    written): its grid, the sample times, and per sample every zone's nearest
    target's point (zone-major; None where the zone has none)."""
    columns_path = os.path.join(run.out_dir, "zones", "columns.json")
    if not os.path.exists(columns_path):
        return []
    with open(columns_path) as f:
        columns = json.load(f)
    index = {s.name: s.index for s in run.sensors}
    zones = []
    for name, sensor in columns["sensors"].items():
        # a folder inside zones/, never one the file names elsewhere (an absolute path, '..')
        if not _plain_folder_name(sensor.get("folder")):
            raise RunError(f"{columns_path}: sensor {name!r}: folder {sensor.get('folder')!r} is not a folder "
                           "name inside zones/")
        folder = os.path.join(run.out_dir, "zones", sensor["folder"])
        p_path = os.path.join(folder, "p_W.npy")
        if not os.path.exists(p_path) or name not in index:
            continue
        nearest = np.load(p_path)[:, :, 0, :]  # samples x zones x 3: each zone's first target
        zones.append({"sensor": index[name], "nx": sensor["zones"][0], "ny": sensor["zones"][1],
                      "t": _col(np.load(os.path.join(folder, "t_s.npy"))), "p": _col(nearest.ravel())})
    return zones


def _poses_data(poses, key):
    """Poses by name as the viewer reads them: one time column, and per name [x y z qw qx qy qz] per sample."""
    if not poses:
        return None
    t = next(iter(poses.values()))[0]
    return {"t": _col(t), key: {name: _col(np.column_stack([p, q]).ravel()) for name, (_, p, q) in poses.items()}}


def viewer_data(run, terrain=None):
    """The dict written as window.PROXSIM_DATA; terrain: the run's map (terrain_data.load_terrain) or None."""
    code = {s: i for i, s in enumerate(STATUSES)}
    sensors = []
    for s in run.sensors:
        sensors.append({
            "index": s.index, "name": s.name, "type": s.type, "color": sensor_color(s.index),
            "dMin": s.d_min_m, "dMax": s.d_max_m,
            "t": _col(s.t_s), "status": [code.get(v, 1) for v in s.status],
            "dM": _col(s.d_m), "dTrue": _col(s.d_true_m),
            "origin": _col(s.p_origin.ravel()), "end": _col(_ray_ends(s).ravel()),
        })
    poses = _poses_data(run.poses, "links")
    prof = run.profile
    order = np.argsort(prof["t_s"], kind="stable")
    profile = {k: (_col(prof[k][order]) if k not in ("sensor", "object") else
                   [int(v) for v in prof[k][order]]) for k in ("x", "y", "z", "sensor", "t_s", "object")}
    return {
        "version": 1,
        "scene": run.scene,
        "statuses": list(STATUSES),
        "statusColors": [STATUS_COLORS[s] for s in STATUSES],
        "statusLabels": [STATUS_LABELS[s] for s in STATUSES],
        "objectColors": {str(o.get("id", i)): object_color(int(o.get("id", i)))
                         for i, o in enumerate(run.scene.get("objects", []))},
        "poses": poses,
        "sensors": sensors,
        "profile": profile,
        "events": [{"t": e["t_s"], "event": e["event"], "detail": e.get("detail", "")} for e in (run.events or [])],
        "collisions": [{"t": c["t_s"], "link": c["link"], "p": c["p_W"]} for c in (run.collisions or [])],
        "fall": {"t": run.fall["t_s"], "p": run.fall.get("p_W")} if run.fall else None,
        "terrain": terrain_viewer_data(terrain),
        "zones": zones_viewer_data(run),
        "objectPoses": _poses_data(run.object_poses, "objects"),
    }


INDEX_HTML = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>proxsim replay — {title}</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
</head>
<body>
<div id="proxsim-viewer"></div>
<noscript>The replay needs JavaScript.</noscript>
<script src="data.js"></script>
<script src="viewer.js"></script>
</body>
</html>
"""


def write_viewer(run, report_dir, bundle_path, terrain=None):
    """Copies the bundle and writes data.js and index.html into report_dir."""
    with open(bundle_path, "rb") as f:
        write_bytes(os.path.join(report_dir, "viewer.js"), f.read())
    data = json.dumps(viewer_data(run, terrain), separators=(",", ":"), allow_nan=False)
    write_text(os.path.join(report_dir, "data.js"), "window.PROXSIM_DATA = " + data + ";\n")
    title = html.escape(os.path.basename(os.path.abspath(run.out_dir)))
    write_text(os.path.join(report_dir, "index.html"), INDEX_HTML.format(title=title))

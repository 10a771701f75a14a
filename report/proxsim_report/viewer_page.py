"""The 3D replay viewer's files in OUT/report/: viewer.js (the prebuilt bundle,
copied), data.js (`window.PROXSIM_DATA = {...}`: the scene, link poses per
sample, each sensor's readings as column arrays, the profile points) and
index.html, which loads both with plain <script> tags so it opens from disk."""
import html
import json
import os
import shutil

import numpy as np

from .run_data import STATUSES
from .style import STATUS_COLORS, STATUS_LABELS, object_color, sensor_color


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


def viewer_data(run):
    """The dict written as window.PROXSIM_DATA."""
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
    poses = None
    if run.poses:
        t = next(iter(run.poses.values()))[0]
        poses = {"t": _col(t), "links": {name: _col(np.column_stack([p, q]).ravel())
                                         for name, (_, p, q) in run.poses.items()}}
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


def write_viewer(run, report_dir, bundle_path):
    """Copies the bundle and writes data.js and index.html into report_dir."""
    shutil.copyfile(bundle_path, os.path.join(report_dir, "viewer.js"))
    with open(os.path.join(report_dir, "data.js"), "w") as f:
        f.write("window.PROXSIM_DATA = ")
        json.dump(viewer_data(run), f, separators=(",", ":"), allow_nan=False)
        f.write(";\n")
    title = html.escape(os.path.basename(os.path.abspath(run.out_dir)))
    with open(os.path.join(report_dir, "index.html"), "w") as f:
        f.write(INDEX_HTML.format(title=title))

"""Reads a run's output files (readings.csv or the npy columns in readings/,
poses.csv, profile.ply, scene.json) into flat NumPy columns: one SensorSeries
per sensor, link poses per sample and the profile points. Empty CSV fields
become NaN (numbers) or '' (names); the npy columns give the same arrays."""
import csv
import json
import os
from dataclasses import dataclass, field

import numpy as np

STATUSES = ("ok", "no_echo", "too_close", "grazing", "self", "dropout", "crosstalk")


class RunError(Exception):
    """A run directory that cannot be drawn (missing or malformed file)."""


@dataclass
class SensorSeries:
    """One sensor's readings over time, in columns (one entry per sample)."""
    index: int
    name: str
    type: str
    d_min_m: float
    d_max_m: float
    max_incidence_deg: float
    t_s: np.ndarray = field(default=None)
    status: np.ndarray = field(default=None)      # str, one of STATUSES
    detected: np.ndarray = field(default=None)    # bool
    d_m: np.ndarray = field(default=None)         # measured distance (d_max when not detected)
    d_true_m: np.ndarray = field(default=None)    # noise-free distance, NaN when nothing in range
    incidence_deg: np.ndarray = field(default=None)
    signal: np.ndarray = field(default=None)
    p_hit: np.ndarray = field(default=None)       # N×3 world, NaN rows when nothing was hit
    p_origin: np.ndarray = field(default=None)    # N×3 world
    dir: np.ndarray = field(default=None)         # N×3 world, unit
    object: np.ndarray = field(default=None)      # str, '' when nothing was hit


@dataclass
class Run:
    """Everything a report draws from one output directory."""
    out_dir: str
    scene: dict
    sensors: list            # SensorSeries, in scene order
    poses: dict              # link name -> (t_s N, p N×3, quat_wxyz N×4); empty when no robot
    profile: dict            # x, y, z, sensor, t_s, object: 1-D arrays (detections, world frame)
    events: list = None      # summary.json robot.events: [{t_s, event, detail}], [] without a robot
    fall: dict = None        # summary.json robot.fall: {t_s, p_W (or None), detail}, None when it did not fall
    collisions: list = None  # summary.json robot.collisions: [{t_s, link, object | other_link, depth_m, p_W}]
    outcome: dict = None     # summary.json robot.{outcome, outcome_t_s, outcome_detail}; None without a robot
    object_poses: dict = None  # moving object name -> (t_s N, p N×3, quat_wxyz N×4); empty when none moves


def _read_robot(out_dir):
    """summary.json's robot section ({} without a robot, or when the summary cannot be read)."""
    try:
        with open(os.path.join(out_dir, "summary.json")) as f:
            return json.load(f).get("robot") or {}
    except (OSError, ValueError):
        return {}


def _read_events(robot):
    """The strategy's and the episode's events."""
    return list(robot.get("events") or [])


def _read_outcome(robot):
    """How the episode ended: {name, t_s, detail}, or None (no robot, or a summary from before outcomes)."""
    if "outcome" not in robot:
        return None
    return {"name": robot["outcome"], "t_s": robot.get("outcome_t_s"), "detail": robot.get("outcome_detail", "")}


def _floats(rows, key):
    return np.array([float(r[key]) if r[key] != "" else np.nan for r in rows])


def _read_scene(out_dir):
    path = os.path.join(out_dir, "scene.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise RunError(f"cannot read {path}: {e}") from e


def _column_table(path):
    """columns.json: the readings' columns (name, dtype, and for a coded column
    the list its codes index) and those lists of names — proxsim's one
    definition of the columns (`proxsim columns`), written by every run."""
    try:
        with open(path) as f:
            table = json.load(f)
        for column in table["columns"]:
            if not isinstance(column.get("name"), str) or not isinstance(column.get("dtype"), str):
                raise ValueError(f"a column without a name or a dtype: {column}")
            if "codes" in column and column["codes"] not in table:
                raise KeyError(f"no list {column['codes']!r} for column {column['name']!r}")
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise RunError(f"cannot read {path}: {e}") from e
    return table


def _kind(column):
    """'code', 'float', 'bool' or 'int': how a column's values are read."""
    if "codes" in column:
        return "code"
    return {"<f8": "float", "|b1": "bool"}.get(column["dtype"], "int")


def _readings_csv(out_dir):
    """readings.csv as {sensor name: {column: array}}, sensors in order of first
    row, each sensor's rows sorted by time (stable). Codes are the names the
    CSV writes; an empty field is NaN (numbers) or '' (names)."""
    table = _column_table(os.path.join(out_dir, "columns.json"))
    path = os.path.join(out_dir, "readings.csv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        raise RunError(f"cannot read {path}: {e}") from e
    by_sensor = {}
    for r in rows:
        by_sensor.setdefault(r["sensor"], []).append(r)
    columns = {}
    for name, rs in by_sensor.items():
        rs.sort(key=lambda r: float(r["t_s"]))
        c = {}
        for column in table["columns"]:
            key, kind = column["name"], _kind(column)
            if kind == "float":
                c[key] = _floats(rs, key)
            elif kind == "code":
                c[key] = np.array([r[key] for r in rs], dtype=object)
            elif kind == "bool":
                c[key] = np.array([r[key] == "1" for r in rs], dtype=bool)
            else:
                c[key] = np.array([int(r[key]) for r in rs], dtype=np.int64)
        columns[name] = c
    return columns, table


def _load_npy(folder, column, rows):
    path = os.path.join(folder, column + ".npy")
    try:
        values = np.load(path)
    except (OSError, ValueError) as e:
        raise RunError(f"cannot read {path}: {e}") from e
    if values.shape != (rows,):
        raise RunError(f"{path}: shape {values.shape}, but columns.json says {rows} rows")
    return values


def _decode(codes, names):
    """Codes to names; a code outside the list (−1, 255: none) becomes ''."""
    lookup = np.array(list(names) + [""], dtype=object)
    index = codes.astype(np.int64)
    index[(index < 0) | (index >= len(names))] = len(names)
    return lookup[index]


def _readings_npy(out_dir):
    """The same as _readings_csv, from `proxsim run --format npy`'s readings/:
    one .npy per column, described by readings/columns.json. NaN stays NaN;
    a code with no name (none) becomes ''."""
    folder = os.path.join(out_dir, "readings")
    path = os.path.join(folder, "columns.json")
    table = _column_table(path)
    try:
        rows = int(table["rows"])
    except (KeyError, TypeError, ValueError) as e:
        raise RunError(f"cannot read {path}: {e}") from e
    raw = {column["name"]: _load_npy(folder, column["name"], rows) for column in table["columns"]}
    decoded = {column["name"]: _decode(raw[column["name"]], table[column["codes"]])
               for column in table["columns"] if _kind(column) == "code"}

    # sensors in order of first row, each one's rows sorted by time (stable), as from the CSV
    columns = {}
    sensor = raw["sensor"]
    present, first_row = np.unique(sensor, return_index=True)
    for code in present[np.argsort(first_row)]:
        mine = np.flatnonzero(sensor == code)
        mine = mine[np.argsort(raw["t_s"][mine], kind="stable")]
        c = {}
        for column in table["columns"]:
            key, kind = column["name"], _kind(column)
            if kind == "code":
                c[key] = decoded[key][mine]
            elif kind == "float":
                c[key] = raw[key][mine].astype(np.float64, copy=False)
            elif kind == "bool":
                c[key] = raw[key][mine].astype(bool, copy=False)
            else:
                c[key] = raw[key][mine].astype(np.int64, copy=False)
        columns[decoded["sensor"][mine[0]]] = c
    return columns, table


def _readings_format(out_dir):
    """'npy' or 'csv': the readings the run's summary.json lists among its
    outputs (a stale readings.csv may sit beside a newer readings/), else
    readings.csv, else readings/ when only that exists."""
    try:
        with open(os.path.join(out_dir, "summary.json")) as f:
            outputs = json.load(f).get("outputs", [])
    except (OSError, ValueError, AttributeError):
        outputs = []
    if "readings/" in outputs:
        return "npy"
    if "readings.csv" in outputs or os.path.exists(os.path.join(out_dir, "readings.csv")):
        return "csv"
    return "npy" if os.path.isdir(os.path.join(out_dir, "readings")) else "csv"


def _no_readings(table):
    """A sensor with no rows: every column empty."""
    empty = {"float": lambda: np.zeros(0), "code": lambda: np.array([], dtype=object),
             "bool": lambda: np.zeros(0, dtype=bool), "int": lambda: np.zeros(0, dtype=np.int64)}
    return {column["name"]: empty[_kind(column)]() for column in table["columns"]}


def _read_readings(out_dir, scene):
    """One SensorSeries per sensor, from readings.csv or readings/ (npy)."""
    by_sensor, table = _readings_npy(out_dir) if _readings_format(out_dir) == "npy" else _readings_csv(out_dir)
    # sensors in scene.json order; any sensor only in the readings comes after
    specs = {s["name"]: s for s in scene.get("sensors", [])}
    names = [s["name"] for s in scene.get("sensors", [])]
    names += [n for n in by_sensor if n not in specs]
    sensors = []
    for i, name in enumerate(names):
        c = by_sensor.get(name) or _no_readings(table)
        spec = specs.get(name, {})
        d_m = c["d_m"]
        s = SensorSeries(
            index=int(spec.get("index", i)), name=name,
            type=spec.get("type", c["type"][0] if len(c["type"]) else "?"),
            d_min_m=float(spec.get("min_range_m", 0.0)),
            d_max_m=float(spec.get("max_range_m", np.nanmax(d_m) if len(d_m) else 1.0)),
            max_incidence_deg=float(spec.get("max_incidence_deg", 90.0)))
        s.t_s = c["t_s"]
        if len(s.t_s) and not np.all(np.isfinite(s.t_s)):
            raise RunError(f"{out_dir}: sensor '{name}': a t_s that is not a finite number "
                           f"({s.t_s[~np.isfinite(s.t_s)][0]!r}); not a run proxsim wrote")
        s.status = c["status"]
        s.detected = c["detected"]
        s.d_m = d_m
        s.d_true_m = c["d_true_m"]
        s.incidence_deg = c["incidence_deg"]
        s.signal = c["signal"]
        s.p_hit = np.stack([c[k] for k in ("hit_x_m", "hit_y_m", "hit_z_m")], 1).reshape(-1, 3)
        s.p_origin = np.stack([c[k] for k in ("origin_x_m", "origin_y_m", "origin_z_m")], 1).reshape(-1, 3)
        s.dir = np.stack([c[k] for k in ("dir_x", "dir_y", "dir_z")], 1).reshape(-1, 3)
        s.object = c["object"]
        sensors.append(s)
    return sensors


def _read_poses(out_dir, file_name="poses.csv", key="link"):
    """poses.csv (the robot's links) or objects_poses.csv (the moving objects), by name."""
    path = os.path.join(out_dir, file_name)
    if not os.path.exists(path):
        return {}
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    by_link = {}
    for r in rows:
        by_link.setdefault(r[key], []).append(r)
    poses = {}
    for link, rs in by_link.items():
        rs.sort(key=lambda r: float(r["t_s"]))
        p = np.stack([_floats(rs, k) for k in ("x", "y", "z")], 1)
        q = np.stack([_floats(rs, k) for k in ("qw", "qx", "qy", "qz")], 1)
        poses[link] = (_floats(rs, "t_s"), p, q)
    return poses


def _read_profile(out_dir):
    """ASCII PLY vertices with their named properties (any order)."""
    path = os.path.join(out_dir, "profile.ply")
    empty = {k: np.zeros(0) for k in ("x", "y", "z", "sensor", "t_s", "object")}
    if not os.path.exists(path):
        return empty
    with open(path) as f:
        lines = f.read().splitlines()
    props, count, start = [], 0, None
    for i, line in enumerate(lines):
        parts = line.split()
        if parts[:2] == ["element", "vertex"]:
            try:
                count = int(parts[2])
            except (IndexError, ValueError):
                raise RunError(f"{path}:{i + 1}: expected 'element vertex COUNT', got {line!r}") from None
        elif parts and parts[0] == "property":
            props.append(parts[-1])
        elif line.strip() == "end_header":
            start = i + 1
            break
    if start is None:
        raise RunError(f"{path}: no end_header")
    # the count within the lines the file holds: a 170-byte header declaring 1e8 vertices once took 2.4 GB
    if not 0 <= count <= len(lines) - start:
        raise RunError(f"{path}: the header declares {count} vertices but the file holds {len(lines) - start} "
                       "lines after it")
    if count == 0:
        return empty
    data = np.loadtxt(lines[start:start + count], ndmin=2)
    cols = {name: data[:, j] for j, name in enumerate(props)}
    for k in ("sensor", "object"):
        cols[k] = cols.get(k, np.full(count, -1)).astype(int)
    return {k: cols.get(k, np.zeros(count)) for k in ("x", "y", "z", "sensor", "t_s", "object")}


def load_run(out_dir):
    """Reads a finished run; raises RunError naming the file when one is unreadable."""
    scene = _read_scene(out_dir)
    robot = _read_robot(out_dir)
    return Run(out_dir=out_dir, scene=scene, sensors=_read_readings(out_dir, scene),
               poses=_read_poses(out_dir), profile=_read_profile(out_dir), events=_read_events(robot),
               collisions=list(robot.get("collisions") or []), fall=robot.get("fall"), outcome=_read_outcome(robot),
               object_poses=_read_poses(out_dir, "objects_poses.csv", "object"))

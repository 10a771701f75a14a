"""A finished proxsim run as a ROS 2 bag (docs/ros2.md).

    python -m proxsim.ros2_bag RUN_DIR BAG_DIR     (what `proxsim export RUN_DIR --ros2 BAG_DIR` runs)

The bag is written by PyPI's `rosbags` (pinned by python/requirements.txt):
its Writer with MCAP storage and CDR serialization writes the file and
metadata.yaml (rosbag2's format version 8, ROS 2 Jazzy's), and every message
is a class of its typestore of ROS 2 Jazzy's standard messages, serialized by
it; nothing here encodes CDR or MCAP. Only the run's documented files are
read (docs/outputs.md): summary.json, scene.json, readings.csv (or readings/),
poses.csv, joints.csv, zones/, profile.ply.

Frames: `world`; each robot link by its name (poses.csv); each sensor by its
name, mounted on its link (or `world`) as the scenario says, +x its axis.
Times are the run's: t_s from 0 as seconds after the epoch.

The bag appears whole: written into a temporary folder beside BAG_DIR and
renamed when complete. This file imports only the standard library, numpy and
rosbags, so that it runs as a script (`python -I ros2_bag.py`) too.
Exit 0 done; 2 bad input (the run's files, the arguments), named; 1 anything else.
"""
import csv
import json
import math
import os
import re
import shutil
import sys

import numpy as np

try:
    from rosbags.interfaces import Qos, QosDurability, QosHistory, QosLiveliness, QosReliability, QosTime
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore
except ImportError as missing:  # a Python without the venv's packages: say what to do, not a traceback
    if __name__ != "__main__":
        raise
    sys.exit(f"proxsim export: the ROS 2 bag needs PyPI's rosbags ({missing}); scripts/install-deps.sh installs it "
             "into .venv/, then configure the build again so that proxsim runs the venv's Python")

BAD_INPUT = 2
BAG_VERSION = 8  # rosbag2's metadata version of ROS 2 Jazzy (rosbags writes 8 or 9)
TYPESTORE = get_typestore(Stores.ROS2_JAZZY)
T = TYPESTORE.types

# REP 117: what a Range reports for each status that is not a distance
# (docs/outputs.md, the rep117 convention: grazing is no echo for the device;
# ok and crosstalk report the echo they heard)
REP117_RANGE = {"too_close": -math.inf, "no_echo": math.inf, "grazing": math.inf,
                "self": math.nan, "dropout": math.nan, "not_sampled": math.nan}
# rcl_interfaces/msg/Log levels of the run's events, as the MCAP export's /events
SERIOUS_EVENTS = {"collision", "fall", "cannot_step"}
# /tf_static is latched in ROS 2: a late subscriber still gets the mountings
LATCHED = Qos(QosHistory.KEEP_LAST, 1, QosReliability.RELIABLE, QosDurability.TRANSIENT_LOCAL, QosTime(0, 0),
              QosTime(0, 0), QosLiveliness.AUTOMATIC, QosTime(0, 0), False)


class RunFolderError(Exception):
    """Bad input: a missing or malformed run file; the message names it."""


# --- reading the run's files -------------------------------------------------

def _read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as error:
        raise RunFolderError(f"{path}: cannot read it ({error.strerror})") from error
    except ValueError as error:
        raise RunFolderError(f"{path}: not JSON ({error})") from error


def _read_csv(path, expected):
    """{column: list of strings} of a CSV file (RFC 4180 quoting, as proxsim writes names)."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
    except OSError as error:
        raise RunFolderError(f"{path}: cannot read it ({error.strerror})") from error
    header = rows[0] if rows else []
    missing = [name for name in expected if name not in header]
    if missing:
        raise RunFolderError(f"{path}: expected the columns {','.join(expected)}; missing {','.join(missing)}")
    for k, row in enumerate(rows[1:]):
        if len(row) != len(header):
            raise RunFolderError(f"{path}:{k + 2}: {len(row)} fields where the header has {len(header)}")
    return {name: [row[i] for row in rows[1:]] for i, name in enumerate(header)}


def _floats(texts):
    """CSV numbers as float64, an empty field ("none") as NaN."""
    return np.array([float(t) if t != "" else math.nan for t in texts], dtype=np.float64)


def _load_npy(path):
    try:
        return np.load(path, allow_pickle=False)
    except (OSError, ValueError) as error:
        raise RunFolderError(f"{path}: not a readable .npy file ({error})") from error


def read_readings(run_dir, summary):
    """The readings' columns the bag needs: t_s, t_reported_s, d_m (float64), sensor and status (names);
    variance_m2 too when the run wrote it (rep117 convention)."""
    npy = "readings/" in summary.get("outputs", []) or not os.path.exists(os.path.join(run_dir, "readings.csv"))
    wanted = ["t_s", "t_reported_s", "d_m", "sensor", "status", "variance_m2"]
    if npy:
        meta = _read_json(os.path.join(run_dir, "readings", "columns.json"))
        columns = {}
        for column in meta["columns"]:
            if column["name"] not in wanted:
                continue
            data = _load_npy(os.path.join(run_dir, "readings", column["name"] + ".npy"))
            if column.get("codes"):
                names = meta[column["codes"]]
                data = [names[code] if 0 <= code < len(names) else "" for code in data.tolist()]
            columns[column["name"]] = data
    else:
        text = _read_csv(os.path.join(run_dir, "readings.csv"), wanted[:5])
        columns = {name: text[name] for name in wanted if name in text}
        for name in ("t_s", "t_reported_s", "d_m", "variance_m2"):
            if name in columns:
                columns[name] = _floats(columns[name])
    return columns


def read_poses(run_dir, name, key):
    """poses.csv (key `link`) or joints.csv (key `joint`): [(t_s, {name: row values as floats})] per sample,
    in file order; [] when the run wrote no such file."""
    path = os.path.join(run_dir, name)
    if not os.path.exists(path):
        return []
    values = ["x", "y", "z", "qw", "qx", "qy", "qz"] if key == "link" else ["position"]
    columns = _read_csv(path, ["t_s", key, *values])
    numbers = np.stack([_floats(columns[v]) for v in values], axis=1)
    samples = []
    for t_text, who, row in zip(columns["t_s"], columns[key], numbers):
        t_s = float(t_text)
        if not samples or samples[-1][0] != t_s:
            samples.append((t_s, {}))
        samples[-1][1][who] = row
    return samples


def read_profile(run_dir):
    """profile.ply (ASCII) as {property: float64 array}."""
    path = os.path.join(run_dir, "profile.ply")
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
    except OSError as error:
        raise RunFolderError(f"{path}: cannot read it ({error.strerror})") from error
    if not lines or lines[0] != "ply" or "end_header" not in lines:
        raise RunFolderError(f"{path}: not an ASCII PLY file")
    end = lines.index("end_header")
    count, names = 0, []
    for line in lines[1:end]:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            names.append(words[2])
    body = [line.split() for line in lines[end + 1:end + 1 + count]]
    if len(body) != count or any(len(v) != len(names) for v in body):
        raise RunFolderError(f"{path}: its header declares {count} vertices of {len(names)} values; the body differs")
    values = np.array(body, dtype=np.float64).reshape(count, len(names))
    return {name: values[:, i] for i, name in enumerate(names)}


# --- geometry -----------------------------------------------------------------

def quaternion_from_rpy(roll, pitch, yaw):
    """R = Rz(yaw)·Ry(pitch)·Rx(roll), as URDF and the scenario, as (w, x, y, z)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr, sy * cp * sr + cy * sp * cr,
            sy * cp * cr - cy * sp * sr)


def rotation_matrix(w, x, y, z):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


# --- messages -----------------------------------------------------------------

def stamp(t_s):
    """A run time in seconds as builtin_interfaces/Time, rounded to the nanosecond."""
    ns = round(t_s * 1e9)
    return T["builtin_interfaces/msg/Time"](sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def header(t_s, frame_id):
    return T["std_msgs/msg/Header"](stamp=stamp(t_s), frame_id=frame_id)


def transform(t_s, parent, child, xyz, wxyz):
    return T["geometry_msgs/msg/TransformStamped"](
        header=header(t_s, parent), child_frame_id=child,
        transform=T["geometry_msgs/msg/Transform"](
            translation=T["geometry_msgs/msg/Vector3"](x=float(xyz[0]), y=float(xyz[1]), z=float(xyz[2])),
            rotation=T["geometry_msgs/msg/Quaternion"](x=float(wxyz[1]), y=float(wxyz[2]), z=float(wxyz[3]),
                                                       w=float(wxyz[0]))))


# PointField datatypes of the numpy types the clouds use
_POINT_FIELD_TYPES = {np.dtype("<f4"): 7, np.dtype("<f8"): 8, np.dtype("u1"): 2, np.dtype("<u2"): 4,
                      np.dtype("<u4"): 6, np.dtype("<i4"): 5}


def point_cloud(t_s, frame_id, points):
    """A sensor_msgs/PointCloud2 of a numpy structured array (one field per column, little-endian, packed),
    unordered (height 1); dense only when no point has a NaN coordinate."""
    fields = [T["sensor_msgs/msg/PointField"](name=name, offset=offset, datatype=_POINT_FIELD_TYPES[dtype], count=1)
              for name, (dtype, offset) in points.dtype.fields.items()]
    dense = bool(np.isfinite(points["x"]).all() and np.isfinite(points["y"]).all() and np.isfinite(points["z"]).all())
    return T["sensor_msgs/msg/PointCloud2"](
        header=header(t_s, frame_id), height=1, width=len(points), fields=fields, is_bigendian=False,
        point_step=points.dtype.itemsize, row_step=points.dtype.itemsize * len(points),
        data=np.frombuffer(points.tobytes(), dtype=np.uint8), is_dense=dense)


ZONE_POINT = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("distance", "<f4"), ("zone", "<u2"),
                       ("target", "u1"), ("status", "u1")])
PROFILE_POINT = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("sensor", "<u4"), ("object", "<i4")])


def topic_names(sensors):
    """/sensors/NAME per sensor, NAME made a valid ROS 2 name token (letters, digits, underscores; not
    starting with a digit), made unique by its index when two names become the same."""
    topics, seen = [], set()
    for index, sensor in enumerate(sensors):
        token = re.sub(r"_+", "_", re.sub(r"[^A-Za-z0-9_]", "_", sensor["name"])).strip("_") or "sensor"
        if token[0].isdigit():
            token = "s" + token
        if token in seen:
            token = f"{token}_{index}"
        seen.add(token)
        topics.append("/sensors/" + token)
    return topics


def sensor_specs(summary, scene):
    """Each sensor of scene.json with its inputs from summary.json (range, beam, type), in scenario order."""
    inputs = {s["name"]: s for s in summary.get("inputs", {}).get("sensors", [])}
    specs = []
    for sensor in scene["sensors"]:
        spec = inputs.get(sensor["name"])
        if spec is None:
            raise RunFolderError(f"summary.json: no inputs.sensors entry for the sensor {sensor['name']!r} "
                                 "of scene.json")
        specs.append({**spec, "link": sensor["link"], "min_range_m": sensor["min_range_m"],
                      "max_range_m": sensor["max_range_m"]})
    return specs


def range_messages(readings, spec):
    """(bag time s, Range) per row of this sensor in the readings; header stamp t_s, bag time when reported."""
    ultrasonic = spec["type"] == "ultrasonic"
    radiation = T["sensor_msgs/msg/Range"].ULTRASOUND if ultrasonic else T["sensor_msgs/msg/Range"].INFRARED
    beam = spec.get("beam")
    # a single ray sees along its axis only; a beam's cone is its full aperture
    fov = math.radians(beam["aperture_deg"]) if beam else 0.0
    variance = readings.get("variance_m2")
    for k, name in enumerate(readings["sensor"]):
        if name != spec["name"]:
            continue
        status = readings["status"][k]
        value = float(readings["d_m"][k]) if status in ("ok", "crosstalk") else REP117_RANGE.get(status, math.nan)
        # Range.variance: 0 is "unknown" (the run gives it only in the rep117 convention)
        var = float(variance[k]) if variance is not None and math.isfinite(variance[k]) else 0.0
        t_s = float(readings["t_s"][k])
        message = T["sensor_msgs/msg/Range"](
            header=header(t_s, spec["name"]), radiation_type=radiation, field_of_view=fov,
            min_range=spec["min_range_m"], max_range=spec["max_range_m"], range=value, variance=var)
        yield float(readings["t_reported_s"][k]), message


def sensor_pose_at(spec, link_poses):
    """X_WS of a sensor at a sample: its link's pose (poses.csv; identity for `world`) times its mounting."""
    xyz, rpy = spec["pose"]["xyz_m"], [math.radians(a) for a in spec["pose"]["rpy_deg"]]
    R_LS, p_LS = rotation_matrix(*quaternion_from_rpy(*rpy)), np.array(xyz, dtype=np.float64)
    if spec["link"] == "world":
        return R_LS, p_LS
    row = link_poses[spec["link"]]
    R_WL = rotation_matrix(*row[3:7])
    return R_WL @ R_LS, R_WL @ p_LS + row[:3]


def zone_messages(run_dir, spec, zones_meta, poses_by_t):
    """(t_s, PointCloud2) per sample of a multi-zone sensor: every zone's every target in the sensor's frame
    (its world point, zones/NAME/p_W.npy, moved into the sensor frame at that sample), NaN without a target."""
    meta = zones_meta["sensors"].get(spec["name"])
    if meta is None:
        raise RunFolderError(f"zones/columns.json: no entry for the multi-zone sensor {spec['name']!r}")
    folder = os.path.join(run_dir, "zones", meta["folder"])
    t_s, d_m, status, p_W = (_load_npy(os.path.join(folder, f + ".npy")) for f in ("t_s", "d_m", "status", "p_W"))
    zones, targets = d_m.shape[1], d_m.shape[2]
    for k, t in enumerate(t_s.tolist()):
        if spec["link"] != "world" and t not in poses_by_t:
            raise RunFolderError(f"{folder}/t_s.npy: sample t = {t} s has no row in poses.csv")
        R_WS, p_WS = sensor_pose_at(spec, poses_by_t.get(t, {}))
        p_S = (p_W[k].reshape(-1, 3) - p_WS) @ R_WS  # R_WS^T (p_W - p_WS), row by row
        points = np.zeros(zones * targets, dtype=ZONE_POINT)
        points["x"], points["y"], points["z"] = p_S[:, 0], p_S[:, 1], p_S[:, 2]
        points["distance"] = d_m[k].reshape(-1)
        points["zone"] = np.repeat(np.arange(zones), targets)
        points["target"] = np.tile(np.arange(targets), zones)
        points["status"] = status[k].reshape(-1)
        yield t, point_cloud(t, spec["name"], points)


def profile_messages(profile):
    """(t_s, PointCloud2) per sample with detections: that sample's points of profile.ply, in `world`."""
    if not len(profile.get("t_s", [])):
        return
    times = profile["t_s"]
    for t in np.unique(times):
        at = times == t
        points = np.zeros(int(at.sum()), dtype=PROFILE_POINT)
        for name in ("x", "y", "z", "sensor", "object"):
            points[name] = profile[name][at]
        yield float(t), point_cloud(float(t), "world", points)


def event_messages(summary, t0, t_end):
    """(t_s, Log) of the summary's warnings (at the start), the robot's events and its outcome, as the MCAP
    export's /events: WARN for a warning and for collision, fall, cannot_step; ERROR when it collided or fell."""
    Log = T["rcl_interfaces/msg/Log"]
    logs = [(t0, Log.WARN, "proxsim", w) for w in summary.get("warnings", [])]
    robot = summary.get("robot")
    if robot:
        for e in robot.get("events", []):
            level = Log.WARN if e["event"] in SERIOUS_EVENTS else Log.INFO
            logs.append((e["t_s"], level, "robot", f"{e['event']}: {e['detail']}"))
        if robot.get("outcome"):
            level = Log.ERROR if robot["outcome"] in ("collided", "fell") else Log.INFO
            t = robot.get("outcome_t_s")
            logs.append((t_end if t is None else t, level, "outcome", f"{robot['outcome']}: {robot['outcome_detail']}"))
    logs.sort(key=lambda log: log[0])  # stable: warnings, then events in order, the outcome last
    for t, level, name, text in logs:
        yield t, Log(stamp=stamp(t), level=level, name=name, msg=text, file="", function="", line=0)


# --- the bag ------------------------------------------------------------------

def run_topics(run_dir):
    """Every topic of the run's bag: [(topic, msgtype, qos, [(bag time s, message)...])], messages in time order."""
    if not os.path.exists(os.path.join(run_dir, "summary.json")):
        raise RunFolderError(f"{run_dir}: not a run's output folder (no summary.json)")
    summary = _read_json(os.path.join(run_dir, "summary.json"))
    scene = _read_json(os.path.join(run_dir, "scene.json"))
    specs = sensor_specs(summary, scene)
    readings = read_readings(run_dir, summary)
    poses = read_poses(run_dir, "poses.csv", "link")
    joints = read_poses(run_dir, "joints.csv", "joint")
    profile = read_profile(run_dir)
    times = sorted({float(t) for t in readings["t_s"]} | {t for t, _ in poses})
    t0, t_end = (times[0], times[-1]) if times else (0.0, 0.0)

    topics = []
    tf = [(t, T["tf2_msgs/msg/TFMessage"](transforms=[transform(t, "world", link, row[:3], row[3:7])
                                                      for link, row in links.items()]))
          for t, links in poses]
    if tf:
        topics.append(("/tf", "tf2_msgs/msg/TFMessage", (), tf))
    mounts = [transform(t0, spec["link"], spec["name"], spec["pose"]["xyz_m"],
                        quaternion_from_rpy(*[math.radians(a) for a in spec["pose"]["rpy_deg"]])) for spec in specs]
    if mounts:
        topics.append(("/tf_static", "tf2_msgs/msg/TFMessage", (LATCHED,),
                       [(t0, T["tf2_msgs/msg/TFMessage"](transforms=mounts))]))
    if joints:
        topics.append(("/joint_states", "sensor_msgs/msg/JointState", (), [
            (t, T["sensor_msgs/msg/JointState"](header=header(t, ""), name=list(q), position=np.array(
                [v[0] for v in q.values()], dtype=np.float64), velocity=np.zeros(0), effort=np.zeros(0)))
            for t, q in joints]))
    zones_meta = None
    poses_by_t = dict(poses)
    for spec, topic in zip(specs, topic_names(specs)):
        if spec["type"] == "multizone":
            zones_meta = zones_meta or _read_json(os.path.join(run_dir, "zones", "columns.json"))
            topics.append((topic + "/zones", "sensor_msgs/msg/PointCloud2", (),
                           list(zone_messages(run_dir, spec, zones_meta, poses_by_t))))
        else:
            topics.append((topic + "/range", "sensor_msgs/msg/Range", (), list(range_messages(readings, spec))))
    cloud = list(profile_messages(profile))
    if cloud:
        topics.append(("/profile", "sensor_msgs/msg/PointCloud2", (), cloud))
    events = list(event_messages(summary, t0, t_end))
    if events:
        topics.append(("/events", "rcl_interfaces/msg/Log", (), events))
    return summary, topics


def write_bag(run_dir, bag_dir):
    """Writes the run in run_dir as a ROS 2 bag in bag_dir (new, or an empty folder); returns
    {topic: message count}. The bag appears whole or not at all."""
    bag_dir = os.path.normpath(bag_dir)
    if os.path.lexists(bag_dir) and not (os.path.isdir(bag_dir) and not os.listdir(bag_dir)):
        raise RunFolderError(f"{bag_dir}: exists and is not an empty folder; give a new folder for the bag")
    summary, topics = run_topics(run_dir)
    # built beside bag_dir, named as it (rosbags names the .mcap file after its folder), then moved in place
    staging = os.path.join(os.path.dirname(os.path.abspath(bag_dir)), f".{os.path.basename(bag_dir)}.tmp-{os.getpid()}")
    os.mkdir(staging)
    try:
        staged = os.path.join(staging, os.path.basename(bag_dir))
        writer = Writer(staged, version=BAG_VERSION, storage_plugin=StoragePlugin.MCAP)
        inputs = summary.get("inputs", {})
        for key, value in (("source", inputs.get("source")), ("seed", inputs.get("seed")),
                           ("proxsim_version", summary.get("versions", {}).get("proxsim")),
                           ("run_dir", os.path.abspath(run_dir))):
            writer.set_custom_data(f"proxsim.{key}", "" if value is None else str(value))
        writer.open()
        queue = []
        for order, (topic, msgtype, qos, messages) in enumerate(topics):
            connection = writer.add_connection(topic, msgtype, typestore=TYPESTORE, offered_qos_profiles=list(qos))
            queue.extend((round(t * 1e9), order, k, connection, msgtype, m) for k, (t, m) in enumerate(messages))
        # in time order across topics (a tie: the topic listed first, then its own order)
        queue.sort(key=lambda item: item[:3])
        for ns, _, _, connection, msgtype, message in queue:
            writer.write(connection, ns, TYPESTORE.serialize_cdr(message, msgtype))
        writer.close()
        if os.path.isdir(bag_dir):
            os.rmdir(bag_dir)  # the empty folder given: the bag takes its place
        os.rename(staged, bag_dir)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return {topic: len(messages) for topic, _, _, messages in topics}


def main(argv):
    if len(argv) != 2:
        print("usage: python -m proxsim.ros2_bag RUN_DIR BAG_DIR", file=sys.stderr)
        return BAD_INPUT
    run_dir, bag_dir = argv
    try:
        counts = write_bag(run_dir, bag_dir)
    except RunFolderError as error:
        print(f"proxsim export: {error}", file=sys.stderr)
        return BAD_INPUT
    except OSError as error:  # the bag's folder cannot be written: not the input's fault
        print(f"proxsim export: cannot write the bag {bag_dir}: {error}", file=sys.stderr)
        return 1
    print(f"ros2: {bag_dir} — {sum(counts.values())} messages on {len(counts)} topics")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

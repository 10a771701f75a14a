"""Runs as ROS 2 bags (docs/ros2.md): runs made through the real CLI (`run --ros2`, `export --ros2`), read
back with rosbags' own reader (AnyReader, which the writer does not use), every message checked against
the run's files, read here with the csv module and numpy."""
import csv
import json
import math
import os
from pathlib import Path

import numpy as np
import pytest

from conftest import run_cli, scenario

rosbags = pytest.importorskip("rosbags", reason="rosbags is in .venv/ (scripts/install-deps.sh)")
from rosbags.highlevel import AnyReader  # noqa: E402

# Every status a single-distance sensor can have without crosstalk, each from a sensor placed to give it:
# near: an ultrasonic sensor 5 cm from a wall, below its 0.1 m minimum (too_close); sky: looking up at
# nothing (no_echo); graze: a laser 10° below the horizon, the floor at 80° incidence past its 45°
# (grazing); drop: half its detections lost (dropout, ok); back: behind the walking robot, at its pelvis
# (self); cone: a 30° beam on the left tibia at 10 Hz (field of view, fewer rows); tof: a VL53L5CX on the
# pelvis (zones).
STATUS_SCENARIO = """proxsim: 1
seed: 3
duration_s: 1.0
rate_hz: 50
scene:
  builtin: empty
  objects:
    - {name: ground, plane: {}}
    - {name: wall, box: {size_m: [0.1, 1.0, 1.0]}, pose: {xyz_m: [3.0, 2.0, 0.5]}}
robot:
  model: builtin:biped
  path: {waypoints_m: [[0, 0], [3, 0]]}
sensors:
  - {name: near, type: ultrasonic, link: world, pose: {xyz_m: [2.9, 2.0, 0.5]}}
  - {name: sky, type: ideal, link: world, pose: {xyz_m: [0, 3, 0.5], rpy_deg: [0, -90, 0]}}
  - {name: graze, type: laser, link: world, pose: {xyz_m: [0, -2, 0.1], rpy_deg: [0, 10, 0]}}
  - {name: drop, type: ideal, link: world, noise: {dropout: 0.5}, pose: {xyz_m: [0, -3, 0.5], rpy_deg: [0, 90, 0]}}
  - {name: back, type: ideal, link: world, pose: {xyz_m: [-0.6, 0, 0.98]}}
  - {name: cone, type: ultrasonic, link: left_tibia, rate_hz: 10, beam: {aperture_deg: 30, rays: 7},
     pose: {xyz_m: [0.06, 0, -0.2], rpy_deg: [0, 20, 0]}}
  - {name: tof, type: vl53l5cx, link: pelvis, see_robot: false, pose: {xyz_m: [0.1, 0, 0], rpy_deg: [0, 40, 0]}}
"""
# REP 117, as docs/ros2.md states it per status (ok: the measured distance)
EXPECTED_RANGE = {"too_close": -math.inf, "no_echo": math.inf, "grazing": math.inf, "self": math.nan,
                  "dropout": math.nan}


def read_bag(bag):
    """{topic: [(bag time ns, message)]}, every message of the bag, and its connections by topic."""
    messages, connections = {}, {}
    with AnyReader([Path(bag)]) as reader:
        for connection in reader.connections:
            connections[connection.topic] = connection
        for connection, timestamp, raw in reader.messages():
            messages.setdefault(connection.topic, []).append(
                (timestamp, reader.deserialize(raw, connection.msgtype)))
    return messages, connections


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def ns(t_s):
    return round(float(t_s) * 1e9)


def stamp_ns(stamp):
    return stamp.sec * 1_000_000_000 + stamp.nanosec


def quat_matrix(w, x, y, z):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def pitch_quaternion(pitch_deg):
    """(w, x, y, z) of a rotation about y: written out here, not the writer's rpy conversion."""
    half = math.radians(pitch_deg) / 2
    return (math.cos(half), 0.0, math.sin(half), 0.0)


def check_tf_equals_poses(run, messages):
    """/tf: one message per sample of poses.csv, each link's transform equal to its row within 1e-9 m."""
    samples = {}
    for row in read_csv(run / "poses.csv"):
        samples.setdefault(row["t_s"], []).append(row)
    tf = messages["/tf"]
    assert len(tf) == len(samples)
    for (timestamp, message), (t_s, rows) in zip(tf, samples.items()):
        assert timestamp == ns(t_s)
        assert [t.child_frame_id for t in message.transforms] == [r["link"] for r in rows]
        for t, r in zip(message.transforms, rows):
            assert t.header.frame_id == "world" and stamp_ns(t.header.stamp) == ns(t_s)
            p, q = t.transform.translation, t.transform.rotation
            assert max(abs(p.x - float(r["x"])), abs(p.y - float(r["y"])), abs(p.z - float(r["z"]))) <= 1e-9
            assert max(abs(q.w - float(r["qw"])), abs(q.x - float(r["qx"])), abs(q.y - float(r["qy"])),
                       abs(q.z - float(r["qz"]))) <= 1e-12
    return tf


def check_ranges(run, messages, sensors):
    """Each single-distance sensor's Range messages: one per row of readings.csv, REP 117 by status."""
    rows = read_csv(run / "readings.csv")
    statuses = set()
    for name, spec in sensors.items():
        mine = [r for r in rows if r["sensor"] == name]
        got = messages[f"/sensors/{name}/range"]
        assert len(got) == len(mine) > 0, name
        for (timestamp, m), r in zip(got, mine):
            statuses.add(r["status"])
            assert timestamp == ns(r["t_reported_s"]) and stamp_ns(m.header.stamp) == ns(r["t_s"])
            assert m.header.frame_id == name
            assert m.radiation_type == spec["radiation_type"], name
            assert m.field_of_view == pytest.approx(spec["fov_rad"], abs=1e-7), name
            assert (m.min_range, m.max_range) == pytest.approx(spec["range_m"]), name
            if r["status"] in ("ok", "crosstalk"):
                assert m.range == np.float32(float(r["d_m"])), (name, r)
            else:
                want = EXPECTED_RANGE[r["status"]]
                assert (math.isnan(m.range) and math.isnan(want)) or m.range == want, (name, r)
    return statuses


@pytest.fixture(scope="module")
def status_run(tmp_path_factory):
    """The status scenario run with --ros2, and its bag read back."""
    root = tmp_path_factory.mktemp("ros2")
    (root / "s.yaml").write_text(STATUS_SCENARIO)
    result = run_cli("run", str(root / "s.yaml"), "--out", str(root / "run"), "--ros2", str(root / "bag"),
                     "--no-report")
    assert result.returncode == 0, result.stderr
    return root / "run", root / "bag", read_bag(root / "bag")


def test_every_status_reads_back_as_rep117(status_run):
    run, _, (messages, _) = status_run
    ultrasound, infrared = 0, 1  # sensor_msgs/Range's constants
    sensors = {
        "near": {"radiation_type": ultrasound, "fov_rad": 0.0, "range_m": (0.1, 1.0)},
        "sky": {"radiation_type": infrared, "fov_rad": 0.0, "range_m": (0.0, 2.0)},
        "graze": {"radiation_type": infrared, "fov_rad": 0.0, "range_m": (0.0, 2.0)},
        "drop": {"radiation_type": infrared, "fov_rad": 0.0, "range_m": (0.0, 2.0)},
        "back": {"radiation_type": infrared, "fov_rad": 0.0, "range_m": (0.0, 2.0)},
        "cone": {"radiation_type": ultrasound, "fov_rad": math.radians(30), "range_m": (0.1, 1.0)},
    }
    statuses = check_ranges(run, messages, sensors)
    assert {"ok", "too_close", "no_echo", "grazing", "self", "dropout"} <= statuses
    assert len(messages["/sensors/cone/range"]) == 10  # its own 10 Hz, not the run's 50
    assert "/sensors/tof/range" not in messages  # a multi-zone sensor is a cloud


def test_tf_joints_and_mountings_equal_the_run(status_run):
    run, _, (messages, connections) = status_run
    tf = check_tf_equals_poses(run, messages)
    # the mountings, once, latched; the cone's pose written out from the scenario
    [(timestamp, static)] = messages["/tf_static"]
    assert timestamp == 0
    assert connections["/tf_static"].ext.offered_qos_profiles[0].durability.name == "TRANSIENT_LOCAL"
    mounts = {t.child_frame_id: t for t in static.transforms}
    assert set(mounts) == {"near", "sky", "graze", "drop", "back", "cone", "tof"}
    cone = mounts["cone"]
    assert cone.header.frame_id == "left_tibia" and mounts["near"].header.frame_id == "world"
    p, q = cone.transform.translation, cone.transform.rotation
    assert (p.x, p.y, p.z) == pytest.approx((0.06, 0, -0.2), abs=1e-12)
    assert (q.w, q.x, q.y, q.z) == pytest.approx(pitch_quaternion(20), abs=1e-12)
    # joints: joints.csv as it is, and each knee's angle is the angle between its thigh and tibia in /tf
    joints = read_csv(run / "joints.csv")
    states = messages["/joint_states"]
    assert len(states) == len(tf)
    names = states[0][1].name
    assert {"left_knee_pitch", "right_knee_pitch"} <= set(names)
    for k, (timestamp, state) in enumerate(states):
        rows = joints[k * len(names):(k + 1) * len(names)]
        assert [r["joint"] for r in rows] == list(state.name)
        assert timestamp == ns(rows[0]["t_s"]) and stamp_ns(state.header.stamp) == ns(rows[0]["t_s"])
        assert list(state.position) == [float(r["position"]) for r in rows]
        links = {t.child_frame_id: t.transform.rotation for t in tf[k][1].transforms}
        for side in ("left", "right"):
            thigh, tibia = (quat_matrix(links[f"{side}_{n}"].w, links[f"{side}_{n}"].x, links[f"{side}_{n}"].y,
                                        links[f"{side}_{n}"].z) for n in ("thigh", "tibia"))
            relative = thigh.T @ tibia  # a rotation about y by the knee angle
            angle = math.atan2(relative[0, 2], relative[0, 0])
            assert abs(abs(angle) - abs(state.position[list(state.name).index(f"{side}_knee_pitch")])) <= 1e-9


def test_zone_clouds_equal_the_zone_files(status_run):
    run, _, (messages, _) = status_run
    folder = run / "zones" / "tof"
    t_s, d_m, status, p_W = (np.load(folder / f"{name}.npy") for name in ("t_s", "d_m", "status", "p_W"))
    clouds = messages["/sensors/tof/zones"]
    assert len(clouds) == len(t_s) > 0
    tf = {timestamp: {t.child_frame_id: t.transform for t in m.transforms} for timestamp, m in messages["/tf"]}
    mount = {t.child_frame_id: t.transform for t in messages["/tf_static"][0][1].transforms}["tof"]
    valid = 0
    for k, (timestamp, cloud) in enumerate(clouds):
        assert timestamp == ns(t_s[k]) and cloud.header.frame_id == "tof"
        assert [f.name for f in cloud.fields] == ["x", "y", "z", "distance", "zone", "target", "status"]
        dtype = np.dtype({"names": [f.name for f in cloud.fields], "offsets": [f.offset for f in cloud.fields],
                          "formats": ["<f4", "<f4", "<f4", "<f4", "<u2", "u1", "u1"], "itemsize": cloud.point_step})
        points = np.frombuffer(np.asarray(cloud.data, dtype=np.uint8).tobytes(), dtype=dtype)
        assert cloud.width == 64 and cloud.height == 1
        assert (points["status"] == status[k].reshape(-1)).all()
        assert (points["distance"] == d_m[k].reshape(-1).astype(np.float32)).all()
        assert (points["zone"] == np.arange(64)).all()
        # back into the world through /tf (pelvis) and /tf_static (the mounting)
        pelvis = tf[timestamp]["pelvis"]
        R_WL = quat_matrix(pelvis.rotation.w, pelvis.rotation.x, pelvis.rotation.y, pelvis.rotation.z)
        R_LS = quat_matrix(mount.rotation.w, mount.rotation.x, mount.rotation.y, mount.rotation.z)
        p_WL = np.array([pelvis.translation.x, pelvis.translation.y, pelvis.translation.z])
        p_LS = np.array([mount.translation.x, mount.translation.y, mount.translation.z])
        p_S = np.stack([points["x"], points["y"], points["z"]], axis=1).astype(np.float64)
        world = (R_WL @ (R_LS @ p_S.T + p_LS[:, None])).T + p_WL
        expected = p_W[k].reshape(-1, 3)
        assert (np.isnan(world) == np.isnan(expected)).all()
        hit = ~np.isnan(expected[:, 0])
        valid += int(hit.sum())
        assert np.abs(world[hit] - expected[hit]).max(initial=0) <= 1e-6  # float32 points
    assert valid > 0


def test_profile_events_and_metadata(status_run):
    run, bag, (messages, connections) = status_run
    # the profile: profile.ply's points, one cloud per sample time that has any
    with open(run / "profile.ply") as f:
        lines = f.read().split("\n")
    end = lines.index("end_header")
    count = int(next(line.split()[2] for line in lines if line.startswith("element vertex")))
    ply = np.array([line.split() for line in lines[end + 1:end + 1 + count]], dtype=np.float64)
    clouds = messages["/profile"]
    assert len(clouds) == len(np.unique(ply[:, 4]))
    got = []
    for timestamp, cloud in clouds:
        names = [f.name for f in cloud.fields]
        assert names == ["x", "y", "z", "sensor", "object"] and cloud.header.frame_id == "world"
        points = np.frombuffer(np.asarray(cloud.data, dtype=np.uint8).tobytes(),
                               dtype=np.dtype({"names": names, "formats": ["<f4", "<f4", "<f4", "<u4", "<i4"],
                                               "offsets": [f.offset for f in cloud.fields]}))
        got += [(p["x"], p["y"], p["z"], p["sensor"], timestamp, p["object"]) for p in points]
    assert len(got) == count
    for g, row in zip(got, ply):
        assert np.allclose(g[:3], row[:3], atol=1e-6) and g[3] == row[3] and g[4] == ns(row[4]) and g[5] == row[5]
    # events: the robot's events then its outcome, as log lines
    summary = json.loads((run / "summary.json").read_text())
    logs = messages["/events"]
    robot = summary["robot"]
    # (the run's warnings first: here its sensor 'back' sees only the robot)
    assert [m.msg for _, m in logs] == summary["warnings"] + [
        f"{e['event']}: {e['detail']}" for e in robot["events"]] + [f"{robot['outcome']}: {robot['outcome_detail']}"]
    assert any("sensor 'back' saw only the robot's own body" in w for w in summary["warnings"])
    assert logs[-1][1].name == "outcome"
    # metadata.yaml: what `ros2 bag info` reads, its counts the bag's
    import yaml  # Debian's python3-yaml, which rosbags needs too

    info = yaml.safe_load((bag / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    assert info["storage_identifier"] == "mcap" and info["version"] == 8
    assert info["relative_file_paths"] == ["bag.mcap"] and (bag / "bag.mcap").is_file()
    counts = {t["topic_metadata"]["name"]: t["message_count"] for t in info["topics_with_message_count"]}
    assert counts == {topic: len(m) for topic, m in messages.items()}
    assert all(t["topic_metadata"]["serialization_format"] == "cdr" for t in info["topics_with_message_count"])
    assert sorted(os.listdir(bag)) == ["bag.mcap", "metadata.yaml"]


def test_the_paper_run_gives_500_ranges_per_sensor(tmp_path):
    result = run_cli("run", "--out", str(tmp_path / "run"), "--no-report")
    assert result.returncode == 0, result.stderr
    empty = tmp_path / "bag"
    empty.mkdir()  # an empty folder is taken: the bag goes into it
    result = run_cli("export", str(tmp_path / "run"), "--ros2", str(empty))
    assert result.returncode == 0, result.stderr
    messages, _ = read_bag(empty)
    for name in ("ideal", "laser", "ultrasonic", "reflectance"):
        assert len(messages[f"/sensors/{name}/range"]) == 500, name
    assert len(check_tf_equals_poses(tmp_path / "run", messages)) == 500
    # its strategy's events (obstacle_ahead, stopped) and its outcome, at their times, INFO (20)
    robot = json.loads((tmp_path / "run" / "summary.json").read_text())["robot"]
    want = [(ns(e["t_s"]), "robot", f"{e['event']}: {e['detail']}") for e in robot["events"]]
    want.append((ns(robot["outcome_t_s"]), "outcome", f"{robot['outcome']}: {robot['outcome_detail']}"))
    logs = messages["/events"]
    assert [(t, m.name, m.msg) for t, m in logs] == want and len(want) >= 3
    assert {m.level for _, m in logs} == {20} and all(stamp_ns(m.stamp) == t for t, m in logs)


def test_npy_runs_give_the_same_bag_messages(tmp_path, status_run):
    _, _, (csv_messages, _) = status_run
    (tmp_path / "s.yaml").write_text(STATUS_SCENARIO)
    result = run_cli("run", str(tmp_path / "s.yaml"), "--out", str(tmp_path / "run"), "--format", "npy",
                     "--ros2", str(tmp_path / "bag"), "--no-report")
    assert result.returncode == 0, result.stderr
    messages, _ = read_bag(tmp_path / "bag")
    assert messages.keys() == csv_messages.keys()
    for name in ("near", "drop", "cone"):
        a, b = messages[f"/sensors/{name}/range"], csv_messages[f"/sensors/{name}/range"]
        # repr: NaN equal to NaN, -inf and inf as themselves
        assert [(t, repr(m.range), stamp_ns(m.header.stamp)) for t, m in a] == \
            [(t, repr(m.range), stamp_ns(m.header.stamp)) for t, m in b], name


def test_bad_bag_folders_are_refused_with_nothing_written(tmp_path, status_run):
    run, _, _ = status_run
    before = sorted(p.name for p in run.iterdir())
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "mine.txt").write_text("a user's file")
    (tmp_path / "a_file").write_text("")
    cases = {
        "": "an empty path",
        str(run): "the run's folder",
        str(run / "bag"): "the run's folder",
        str(run / "readings.csv"): "the run's folder",
        str(tmp_path / "full"): "a folder that holds files",
        str(tmp_path / "a_file"): "not a folder",
        str(tmp_path / "no" / "such" / "bag"): "does not exist",
    }
    for bag, message in cases.items():
        result = run_cli("export", str(run), "--ros2", bag)
        assert result.returncode == 2, (bag, result.stderr)
        assert message in result.stderr, (bag, result.stderr)
    assert sorted(p.name for p in run.iterdir()) == before
    assert os.listdir(tmp_path / "full") == ["mine.txt"]
    # export needs something to write; a run with a bad --ros2 is refused before it starts
    assert run_cli("export", str(run)).returncode == 2
    result = run_cli("run", "--out", str(tmp_path / "never"), "--ros2", str(tmp_path / "full"), "--no-report")
    assert result.returncode == 2 and not (tmp_path / "never").exists(), result.stderr
    # a folder that is not a run
    (tmp_path / "not_a_run").mkdir()
    result = run_cli("export", str(tmp_path / "not_a_run"), "--ros2", str(tmp_path / "bag2"))
    assert result.returncode == 2 and not (tmp_path / "bag2").exists(), result.stderr


def test_every_mcap_export_writes_a_layout_that_plots_each_sensor(tmp_path, status_run):
    """The Foxglove layout beside an MCAP export (docs/foxglove.md): it parses, its 3D panel is on `world`,
    it has one Plot per sensor of that sensor's d_m, a Log panel on /events, and its tree holds every panel."""
    run, _, _ = status_run
    result = run_cli("export", str(run), "--mcap", str(tmp_path / "walk.mcap"))
    assert result.returncode == 0, result.stderr
    layout = json.loads((tmp_path / "walk.layout.json").read_text())
    panels = layout["configById"]
    assert panels["3D!world"]["followTf"] == "world"
    assert panels["3D!world"]["topics"]["/profile"]["decayTime"] >= 0.98  # the profile kept for the whole run
    plotted = {}
    for panel_id, config in panels.items():
        if panel_id.startswith("Plot!"):
            [path] = config["paths"]
            plotted[path["label"]] = path["value"]
    names = [s["name"] for s in json.loads((run / "scene.json").read_text())["sensors"]]
    assert plotted == {name: f"/sensors/{name}/reading.d_m" for name in names}
    assert panels["RosOut!events"]["topicToRender"] == "/events"

    def leaves(node):
        return [node] if isinstance(node, str) else leaves(node["first"]) + leaves(node["second"])
    assert sorted(leaves(layout["layout"])) == sorted(panels)


def test_odd_sensor_names_without_a_robot(tmp_path):
    """Names that are not ROS names: the bag's topics are made valid (docs/ros2.md), the frame ids stay the
    names; the layout quotes the MCAP topic in its message path. Without a robot: no /tf, no /joint_states."""
    (tmp_path / "s.yaml").write_text(
        "proxsim: 1\nduration_s: 0.2\nrate_hz: 10\nscene:\n  objects:\n    - {name: ground, plane: {}}\n"
        "sensors:\n"
        "  - {name: 'front left.1', type: laser, pose: {xyz_m: [0, 0, 0.5], rpy_deg: [0, 90, 0]}}\n"
        "  - {name: '2nd', type: reflectance, pose: {xyz_m: [0, 0, 0.5], rpy_deg: [0, 90, 0]}}\n")
    result = run_cli("run", str(tmp_path / "s.yaml"), "--out", str(tmp_path / "run"), "--no-report",
                     "--ros2", str(tmp_path / "bag"), "--mcap", str(tmp_path / "odd.mcap"))
    assert result.returncode == 0, result.stderr
    messages, _ = read_bag(tmp_path / "bag")
    assert set(messages) == {"/tf_static", "/sensors/front_left_1/range", "/sensors/s2nd/range", "/profile"}
    assert {m.header.frame_id for _, m in messages["/sensors/front_left_1/range"]} == {"front left.1"}
    assert [m.range for _, m in messages["/sensors/s2nd/range"]] == pytest.approx([0.5] * 2, abs=0.05)
    [(_, static)] = messages["/tf_static"]
    assert {(t.header.frame_id, t.child_frame_id) for t in static.transforms} == {("world", "front left.1"),
                                                                                   ("world", "2nd")}
    layout = json.loads((tmp_path / "odd.layout.json").read_text())
    paths = {c["paths"][0]["value"] for k, c in layout["configById"].items() if k.startswith("Plot!")}
    assert paths == {'"/sensors/front left.1/reading".d_m', "/sensors/2nd/reading.d_m"}
    assert "RosOut!events" not in layout["configById"]  # no robot, no warnings: no /events


def test_parts_report_their_datasheet_cone_and_range(tmp_path):
    """field_of_view, min_range, max_range and radiation_type of named parts, against their datasheets'
    figures as docs/sensors.md gives them: the VL53L1X's 27° cone and 0.04-3.6 m (long mode), 15° and 1.7 m
    at a 4x4 ROI; the VL53L0X's 25° and 0.03-2 m; the HC-SR04's 60° cone, 0.02-4 m, ultrasound. In ROS's
    convention (outputs.range_convention: rep117) the run gives each reading's variance: Range.variance."""
    (tmp_path / "s.yaml").write_text(
        "proxsim: 1\nduration_s: 0.2\nrate_hz: 10\noutputs: {range_convention: rep117}\n"
        "scene:\n  objects:\n    - {name: ground, plane: {}}\n"
        "sensors:\n"
        "  - {name: wide, type: vl53l1x, pose: {xyz_m: [0, 0, 0.5], rpy_deg: [0, 90, 0]}}\n"
        "  - {name: narrow, type: vl53l1x, roi: [4, 4], pose: {xyz_m: [0, 0, 0.5], rpy_deg: [0, 90, 0]}}\n"
        "  - {name: l0, type: vl53l0x, pose: {xyz_m: [0, 0, 0.5], rpy_deg: [0, 90, 0]}}\n"
        "  - {name: sonar, type: hc_sr04, rate_hz: 10, pose: {xyz_m: [0, 0, 0.5], rpy_deg: [0, 90, 0]}}\n")
    result = run_cli("run", str(tmp_path / "s.yaml"), "--out", str(tmp_path / "run"), "--no-report",
                     "--ros2", str(tmp_path / "bag"))
    assert result.returncode == 0, result.stderr
    messages, _ = read_bag(tmp_path / "bag")
    want = {"wide": (1, 27, 0.04, 3.6), "narrow": (1, 15, 0.04, 1.7), "l0": (1, 25, 0.03, 2.0),
            "sonar": (0, 60, 0.02, 4.0)}
    for name, (radiation, fov_deg, low, high) in want.items():
        ranges = messages[f"/sensors/{name}/range"]
        assert len(ranges) == 2, name
        for _, m in ranges:
            assert m.radiation_type == radiation, name
            assert m.field_of_view == pytest.approx(math.radians(fov_deg), rel=1e-6), name
            assert (m.min_range, m.max_range) == pytest.approx((low, high), rel=1e-6), name
            assert m.range == pytest.approx(0.5, abs=0.05), name  # the floor 0.5 m below, each detects it
        variances = [float(r["variance_m2"]) for r in read_csv(tmp_path / "run" / "readings.csv") if r["sensor"] == name]
        assert [m.variance for _, m in ranges] == [np.float32(v) for v in variances] and min(variances) > 0, name


def test_crosstalk_reports_the_echo_it_heard(tmp_path):
    """The shipped sonar pair (data/scenarios/sonar_pair_thighs.yaml): each hears the other's ping
    (crosstalk), which the device reports as a distance; every Range as REP 117 gives its status."""
    result = run_cli("run", scenario("sonar_pair_thighs.yaml"), "--out", str(tmp_path / "run"), "--no-report", "--ros2", str(tmp_path / "bag"))
    assert result.returncode == 0, result.stderr
    messages, _ = read_bag(tmp_path / "bag")
    spec = {"radiation_type": 0, "fov_rad": math.radians(60), "range_m": (0.02, 4.0)}
    statuses = check_ranges(tmp_path / "run", messages, {"sonar_left_thigh": spec, "sonar_right_thigh": spec})
    assert {"ok", "crosstalk", "no_echo", "grazing"} <= statuses

"""PAL's TALOS, Menagerie's MJCF unchanged (../shared/robots/pal_talos beside the project; skipped,
saying so, when absent), through the CLI: `proxsim inspect` reads it through the MuJoCo proxsim
links and finds its legs; data/scenarios/talos_dining_room.yaml walks it, and its poses.csv, read
back through MuJoCo's own compile of the same file (tests/python/mjcf_poses.py), shows at every
sample: every link where MuJoCo's forward kinematics puts it for the same qpos, every joint
within its range, no foot geom below the floor, the feet planted (a contact point does not slide).
The same with the crouch of talos_position.xml's `walk_pose` keyframe (gait.keyframe)."""
import json
import os

import numpy as np
import pytest

import mujoco
from conftest import SOURCE_DIR, run_cli, scenario
from mjcf_poses import geom_points_W, qpos_from_frames, read_poses

TALOS_DIR = os.path.normpath(os.path.join(SOURCE_DIR, "..", "shared", "robots", "pal_talos"))
needs_talos = pytest.mark.skipif(not os.path.isfile(os.path.join(TALOS_DIR, "talos.xml")),
                                 reason=f"TALOS is not at {TALOS_DIR} (read from beside the project, never copied)")
FEET = ("leg_left_6_link", "leg_right_6_link")
ON_FLOOR_M = 1e-4  # a foot point this close to the floor touches it


@needs_talos
def test_inspect_reads_talos_through_current_mujoco_and_finds_its_legs():
    result = run_cli("inspect", os.path.join(TALOS_DIR, "talos.xml"), "--json")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert report["robot"]["loader"] == "MuJoCo " + mujoco.mj_versionString()
    assert report["legs_accepted"], report["legs_problems"]
    assert report["legs"]["left"] == {"hip": "leg_left_3_joint", "knee": "leg_left_4_joint",
                                      "ankle": "leg_left_5_joint", "foot": "leg_left_6_link",
                                      "ankle_zero_deg": 0.0}  # TALOS's soles lie flat at joint zero
    assert report["legs"]["right"]["knee"] == "leg_right_4_joint"
    # every hinge MuJoCo compiled is a joint with MuJoCo's range
    m = mujoco.MjModel.from_xml_path(os.path.join(TALOS_DIR, "talos.xml"))
    joints = {j["name"]: j for j in report["joints"]}
    for j in range(m.njnt):
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE:
            limits = joints[m.joint(j).name]["limits"]
            assert (limits["lower"], limits["upper"]) == tuple(m.jnt_range[j])


def walk_and_check(tmp_path, scenario_path, model_file):
    out = str(tmp_path / "out")
    result = run_cli("run", scenario_path, "--out", out, "--no-report")
    assert result.returncode == 0, result.stdout + result.stderr
    with open(os.path.join(out, "summary.json")) as f:
        robot = json.load(f)["robot"]
    assert robot["outcome"] == "stopped" and robot["stop_reason"] == "strategy", robot
    assert robot["collisions"] == [] and robot["distance_walked_m"] > 1.5, robot

    m = mujoco.MjModel.from_xml_path(os.path.join(TALOS_DIR, model_file))
    d = mujoco.MjData(m)
    hinges = [j for j in range(m.njnt) if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE]
    foot_geoms = {f: [g for g in range(m.ngeom) if m.geom_bodyid[g] == m.body(f).id] for f in FEET}
    frames = read_poses(os.path.join(out, "poses.csv"))
    times = sorted(frames)
    worst = {"fk_m": 0.0, "range_rad": -np.inf, "below_floor_m": -np.inf, "slip_m": 0.0, "speed_rad_s": 0.0}
    previous = None
    for t in times:
        qpos = qpos_from_frames(m, frames[t])
        d.qpos[:] = qpos
        mujoco.mj_kinematics(m, d)
        # every body where MuJoCo puts it for this qpos
        for b in range(1, m.nbody):
            p, R = frames[t][m.body(b).name]
            worst["fk_m"] = max(worst["fk_m"], np.abs(d.xpos[b] - p).max(), np.abs(d.xmat[b].reshape(3, 3) - R).max())
        # every hinge within its range, and its speed over the sample
        for j in hinges:
            a = m.jnt_qposadr[j]
            lo, hi = m.jnt_range[j]
            worst["range_rad"] = max(worst["range_rad"], lo - qpos[a], qpos[a] - hi)
            if previous is not None:
                worst["speed_rad_s"] = max(worst["speed_rad_s"], abs(qpos[a] - previous[0][a]) / (t - previous[1]))
        # the feet: never below the floor; a point on the floor stays where it is until it lifts
        touching = {}
        for f, geoms in foot_geoms.items():
            points = np.vstack([geom_points_W(m, d, g) for g in geoms])
            worst["below_floor_m"] = max(worst["below_floor_m"], -points[:, 2].min())
            touching[f] = points[points[:, 2] < ON_FLOOR_M]
            if previous is not None and len(previous[2][f]) and len(touching[f]):
                # the points touching at the last sample that still touch: their horizontal motion
                last = previous[2][f]
                for p in last:
                    near = np.linalg.norm(touching[f] - p, axis=1).min()
                    if p[2] < ON_FLOOR_M and near < 0.01:
                        worst["slip_m"] = max(worst["slip_m"], near)
        previous = (qpos, t, touching)
    print(f"[ measured ] {os.path.basename(scenario_path)}: {len(times)} samples, FK vs MuJoCo {worst['fk_m']:.2e}, "
          f"worst range excess {worst['range_rad']:+.4f} rad, lowest foot point {-worst['below_floor_m']:+.2e} m, "
          f"contact slip {worst['slip_m']:.2e} m, fastest joint {worst['speed_rad_s']:.2f} rad/s; gait {robot['gait']}")
    assert worst["fk_m"] < 1e-9
    assert worst["range_rad"] <= 1e-9
    assert worst["below_floor_m"] < 1e-6
    assert worst["slip_m"] < 1e-3
    return robot, worst


@needs_talos
def test_talos_walks_the_dining_room_within_its_ranges_feet_planted(tmp_path):
    robot, _ = walk_and_check(tmp_path, scenario("talos_dining_room.yaml"), "talos.xml")
    assert robot["gait"]["crouch_knee_deg"] == 0


@needs_talos
def test_talos_walks_crouched_as_its_walk_pose_keyframe_stands(tmp_path):
    robot, _ = walk_and_check(tmp_path, scenario("talos_crouched_dining_room.yaml"), "talos_position.xml")
    # the keyframe bends both knees 0.8 rad with its root at 1.025 m: the gait walks with that knee bend,
    # and its pelvis, placed by the geometry at heel strike, stands within 1 cm of the keyframe's
    assert robot["gait"]["crouch_knee_deg"] == pytest.approx(np.degrees(0.8), abs=1e-9)
    assert robot["gait"]["pelvis_height_m"] == pytest.approx(1.025, abs=0.01)


@needs_talos
def test_an_unknown_keyframe_is_refused_naming_the_models_keyframes(tmp_path):
    with open(scenario("talos_crouched_dining_room.yaml")) as f:
        text = f.read().replace("../../../shared/robots/pal_talos", TALOS_DIR).replace("walk_pose", "home")
    path = tmp_path / "home.yaml"
    path.write_text(text)
    result = run_cli("validate", str(path))
    assert result.returncode == 2
    message = result.stdout + result.stderr
    assert "gait.keyframe: no keyframe 'home' in the model (its keyframes: 'walk_pose')" in message, message

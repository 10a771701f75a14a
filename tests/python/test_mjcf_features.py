"""An MJCF using what today's models use — <include>, <default> classes, compiler autolimits and
degrees, <frame>, joint `ref` on a hinge and a slide, fromto capsules — is read as MuJoCo compiles
it: proxsim's joint value is MuJoCo's qpos (ref included), so for random qpos within the ranges
every body is where MuJoCo's own forward kinematics puts it (a sensor on each body, through the
external locomotion, to 1e-9 m); `proxsim inspect` gives MuJoCo's ranges in radians; and a model
MuJoCo refuses is an exit-2 message naming MuJoCo's version and its reason."""
import json

import numpy as np

import mujoco
import proxsim
from conftest import run_cli

MAIN = """<mujoco model="features">
  <compiler angle="degree" autolimits="true"/>
  <default>
    <default class="leg"><joint type="hinge" axis="0 1 0" range="-90 90"/><geom type="capsule" size="0.03"/></default>
  </default>
  <worldbody>
    <body name="pelvis" pos="0 0 1">
      <freejoint/>
      <geom type="box" size="0.1 0.15 0.05"/>
      <include file="leg.xml"/>
      <frame pos="0 0 0.1" euler="0 0 30">
        <body name="head" pos="0.05 0 0.05">
          <joint name="neck" type="hinge" axis="0 0 1" range="-45 45" ref="20"/>
          <geom type="sphere" size="0.08"/>
          <body name="visor">
            <joint name="visor_slide" type="slide" axis="1 0 0" range="-0.02 0.04" ref="0.01"/>
            <geom type="box" size="0.02 0.05 0.02" pos="0.08 0 0"/>
          </body>
        </body>
      </frame>
    </body>
  </worldbody>
</mujoco>
"""
LEG = """<mujoco>
  <body name="thigh" pos="0 0.1 0" childclass="leg">
    <joint name="hip" ref="-10"/>
    <geom fromto="0 0 0 0 0 -0.4"/>
    <frame euler="0 15 0">
      <body name="shin" pos="0 0 -0.4">
        <joint name="knee" range="0 120" ref="5"/>
        <geom fromto="0 0 0 0 0 -0.4"/>
      </body>
    </frame>
  </body>
</mujoco>
"""
BODIES = ["pelvis", "thigh", "shin", "head", "visor"]


def write_model(tmp_path):
    (tmp_path / "leg.xml").write_text(LEG)
    (tmp_path / "robot.xml").write_text(MAIN)
    sensors = "".join(f"  - {{name: on_{b}, type: ideal, link: {b}}}\n" for b in BODIES)
    (tmp_path / "s.yaml").write_text("proxsim: 1\nduration_s: 10\nrate_hz: 10\nscene: {builtin: empty}\n"
                                     "robot: {model: robot.xml, locomotion: external}\nsensors:\n" + sensors)
    return mujoco.MjModel.from_xml_path(str(tmp_path / "robot.xml"))


def test_proxsim_places_every_body_where_mujoco_does_for_the_same_qpos(tmp_path):
    m = write_model(tmp_path)
    d = mujoco.MjData(m)
    assert m.qpos0[m.joint("neck").qposadr[0]] == np.radians(20)  # the refs MuJoCo compiled
    rng = np.random.default_rng(7)
    worst = 0.0
    with proxsim.Simulation(str(tmp_path / "s.yaml"), locomotion="external") as sim:
        for _ in range(20):
            qpos = m.qpos0.copy()
            qpos[0:3] = rng.uniform(-1, 1, 3) + [0, 0, 1]
            quat = rng.normal(size=4)
            qpos[3:7] = quat / np.linalg.norm(quat)
            for j in range(1, m.njnt):  # each hinge or slide anywhere within its range
                qpos[m.jnt_qposadr[j]] = rng.uniform(*m.jnt_range[j])
            d.qpos[:] = qpos
            mujoco.mj_kinematics(m, d)
            q = {m.joint(j).name: float(qpos[m.jnt_qposadr[j]]) for j in range(1, m.njnt)}
            sim.reset()  # each state is a new episode's first: anywhere
            obs = sim.step(q=q, X_WP=(qpos[0:3], qpos[3:7]))
            for i, body in enumerate(BODIES):
                b = m.body(body).id
                worst = max(worst, np.abs(obs["readings"]["origin_W"][i] - d.xpos[b]).max(),
                            np.abs(obs["readings"]["dir_W"][i] - d.xmat[b].reshape(3, 3)[:, 0]).max())
    assert worst < 1e-9, worst


def test_inspect_gives_mujocos_compiled_ranges_in_radians(tmp_path):
    m = write_model(tmp_path)
    result = run_cli("inspect", str(tmp_path / "robot.xml"), "--json")
    assert result.returncode == 0, result.stderr
    joints = {j["name"]: j for j in json.loads(result.stdout)["joints"]}
    for name in ("hip", "knee", "neck", "visor_slide"):
        limits = joints[name]["limits"]
        assert (limits["lower"], limits["upper"]) == tuple(m.joint(name).range), name  # autolimits: limited
    assert joints["knee"]["limits"]["upper"] == np.radians(120)


def test_a_model_mujoco_refuses_names_mujoco_and_its_reason(tmp_path):
    (tmp_path / "bad.xml").write_text('<mujoco><worldbody><body><joint actuatorfrcrange="a b"/>'
                                      '<geom size="0.1"/></body></worldbody></mujoco>')
    result = run_cli("inspect", str(tmp_path / "bad.xml"))
    assert result.returncode == 2
    message = result.stdout + result.stderr
    assert f"MuJoCo {mujoco.mj_versionString()} could not load the MJCF" in message, message
    assert "actuatorfrcrange" in message, message

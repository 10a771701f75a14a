"""A proxsim run's poses.csv read back through MuJoCo's own model (the same MJCF, compiled by the
`mujoco` package): each sample's qpos recovered from the link frames, MuJoCo's forward kinematics
on it, and the foot geoms' lowest points. Shared by the MJCF tests."""
import numpy as np

import mujoco


def read_poses(path):
    """{t_s: {link: (p (3,), R (3, 3))}} from poses.csv, in time order."""
    rows = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding=None)
    frames = {}
    for r in rows:
        R = np.zeros(9)
        mujoco.mju_quat2Mat(R, np.array([r["qw"], r["qx"], r["qy"], r["qz"]], dtype=float))
        frames.setdefault(float(r["t_s"]), {})[str(r["link"])] = (np.array([r["x"], r["y"], r["z"]], dtype=float),
                                                                R.reshape(3, 3))
    return frames


def _hinge_angle(R_rel, axis):
    """The angle of the rotation R_rel about `axis` (R_rel is a rotation about it)."""
    u = np.cross(axis, [1.0, 0.0, 0.0])
    if np.linalg.norm(u) < 0.5:
        u = np.cross(axis, [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = R_rel @ u
    return float(np.arctan2(axis @ np.cross(u, v), u @ v))


def qpos_from_frames(m, frame):
    """MuJoCo's qpos for one sample's link frames: the root's free joint from its link, each hinge
    from its body's frame in its parent's (bodies with one hinge on their origin, as TALOS's)."""
    qpos = m.qpos0.copy()
    for b in range(1, m.nbody):
        name = m.body(b).name
        p, R = frame[name]
        for j in range(m.body_jntadr[b], m.body_jntadr[b] + m.body_jntnum[b]):
            a = m.jnt_qposadr[j]
            if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
                quat = np.zeros(4)
                mujoco.mju_mat2Quat(quat, R.ravel())
                qpos[a:a + 3], qpos[a + 3:a + 7] = p, quat
            elif m.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE:
                assert m.body_jntnum[b] == 1 and not m.jnt_pos[j].any(), name
                _, R_parent = frame[m.body(m.body_parentid[b]).name]
                R_body = np.zeros(9)
                mujoco.mju_quat2Mat(R_body, m.body_quat[b])
                R_rel = (R_parent @ R_body.reshape(3, 3)).T @ R
                qpos[a] = m.qpos0[a] + _hinge_angle(R_rel, m.jnt_axis[j])
    return qpos


def geom_points_W(m, d, g):
    """World points of geom g's surface that bound it from below: a mesh's vertices, a box's corners."""
    R = d.geom_xmat[g].reshape(3, 3)
    if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH:
        i = m.geom_dataid[g]
        local = m.mesh_vert[m.mesh_vertadr[i]:m.mesh_vertadr[i] + m.mesh_vertnum[i]]
    elif m.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
        s = m.geom_size[g]
        local = np.array([[x, y, z] for x in (-s[0], s[0]) for y in (-s[1], s[1]) for z in (-s[2], s[2])])
    else:
        raise ValueError(f"geom {g}: only meshes and boxes are read here")
    return local @ R.T + d.geom_xpos[g]

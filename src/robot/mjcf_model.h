// MuJoCo models (MJCF) as proxsim robots, read through the libmujoco of PyPI's
// `mujoco` wheel (cmake/mujoco.cmake; mj_loadXML, which also compiles the
// model: defaults, <frame>, <include>, autolimits, fromto, meshes, angles in
// degrees all resolved). RobotModel::FromMjcfFile maps the compiled
// model into proxsim's tree of links and 1-DoF joints (docs/robots.md,
// "MuJoCo models"):
//
//  - the world body's single child body is the root link (a <freejoint/> on it
//    is the floating base proxsim places itself); every other body is a link
//    of its name, with its mass;
//  - a body's hinge joints become revolute joints (continuous when not
//    limited), its slide joints prismatic ones, with their ranges; the
//    joint's `ref` (qpos0) is folded into its frame, so that proxsim's q is
//    MuJoCo's qpos and the reference pose (q = 0) is qpos = 0; a body
//    without joints hangs from its parent by a fixed joint `fixed:BODY`. A
//    joint whose anchor is off the body's origin, or a body with several
//    joints, gets a link per joint between them (`BODY.JOINT`, no geometry)
//    and a fixed joint back to the body's frame: MuJoCo turns a body about
//    each joint's anchor in turn, proxsim's child frames sit on their joint;
//  - geoms (of the group chosen, or every geom) become the link's shapes:
//    box, sphere and cylinder exactly, a capsule as a cylinder and two
//    spheres (exactly its surface), an ellipsoid as a triangle mesh
//    (kEllipsoidRings rings, within kEllipsoidMeshDepth of it), a mesh with its compiled vertices and faces;
//  - each site becomes a link of its name, fixed to its body (`site:SITE`),
//    so that a sensor may mount on it (`link: SITE`).
//
//  - the world body's geoms (a scene file that includes the robot, such as
//    Menagerie's scene.xml: a floor, furniture) are not the robot: they are
//    kept apart (RobotModel::scene_geoms), converted as a body's are (every
//    group), each a scene object `model:GEOM` in the world frame (unnamed:
//    `model:geom_K`, K its place among the world's geoms; a capsule's ends
//    `model:GEOM:top` and `:bottom`). The plane z = 0 facing up is the
//    ground, whatever its drawn size (MuJoCo's contacts take a plane as
//    unbounded); another plane, a height field or an sdf is named as not
//    taken, refused only by a scenario that takes the model's scene;
//
//  - joint couplings (<equality><joint>) that hold at the reference pose are
//    kept (proxsim holds the joints the gait does not drive there);
//  - keyframes become RobotKeyframe (each joint's qpos, the root's pose).
//
// Anything that would change what the robot's surface or motion is, and
// proxsim cannot follow, is an InputError naming it: ball joints, free joints
// below the root, joints attaching the root to the world, equality
// constraints other than joint couplings (or a coupling the reference pose
// breaks), mocap bodies, skins, plane and height-field geoms on a body,
// several trees under the world. What does not change it
// (actuators, MuJoCo sensors, tendons, contacts, visuals) is not read:
// proxsim is kinematic.
#pragma once

#include <cmath>
#include <memory>

#include "core/geometry.h"
#include "scene/shape.h"

namespace proxsim {

/// Rings (latitude bands) of an ellipsoid's mesh; each ring has twice as many
/// segments, so that a cell spans θ = π / kEllipsoidRings both ways.
constexpr int kEllipsoidRings = 48;
/// How far inside the ellipsoid the mesh's faces may lie, as a share of it:
/// the mesh lies between the ellipsoid and the ellipsoid scaled by
/// (1 − kEllipsoidMeshDepth) (its vertices on the surface). A face's plane is
/// 1 − √(1 − ρ²) from a unit sphere's surface for a circumradius ρ ≤ θ/√2:
/// 1 − √(1 − θ²/2) ≈ 1.07e-3 (1 mm on a 1 m ellipsoid).
inline const double kEllipsoidMeshDepth =
    1.0 - std::sqrt(1.0 - 0.5 * (3.14159265358979323846 / kEllipsoidRings) * (3.14159265358979323846 / kEllipsoidRings));

/// Whether an MJCF file may give its world body geoms of its own (a scene
/// file's floor and furniture), read from its text and its includes' without
/// compiling it: false only when none can be — no <geom> under <worldbody>
/// outside every <body> (through <frame>, <replicate> and <include>); an
/// <attach>, <composite> or <flexcomp> there, a compiler's `fusestatic`, or a
/// file it cannot read, is a yes.
bool MjcfMayHaveWorldGeoms(const std::string& path);

/// The ellipsoid of semi-axes `radii` (x, y, z) centred on its frame, as a
/// closed triangle mesh with outward faces.
std::shared_ptr<const TriangleMesh> EllipsoidMesh(const Vec3& radii);

}  // namespace proxsim

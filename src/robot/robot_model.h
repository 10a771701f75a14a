// A robot as a tree of rigid links joined by 1-DoF joints, read from URDF
// (urdfdom) or from a MuJoCo model (MJCF, robot/mjcf_model.h), with the links' geometry so that the robot is geometry in the
// scene, and forward kinematics over the tree.
//
// Frames: W world, L a link frame (URDF: a link's frame is its parent joint's
// frame), J a joint frame, O a shape's own frame in its link. X_PJ is a joint's
// origin in its parent link; the child link frame C is J moved by the joint
// value q along/about the joint axis (expressed in J), so X_PC = X_PJ·M(q).
//
// Geometry: each link's <visual> elements, or its <collision> ones, as
// UrdfOptions::geometry says (a link without any of that kind uses the other).
// Boxes, spheres and cylinders map to proxsim shapes; meshes (any format the
// mesh loader reads, with the URDF's scale) are found as robot/mesh_uri.h
// says and loaded once per file and scale, however many links use them. A
// mesh that cannot be found or read is an InputError naming the URDF, the
// link, the URI and the folders searched.
//
// The built-in biped (data/robots/biped.urdf) is sized like the paper's robot:
// at q = 0 the legs hang straight down; thigh frames at the hips, tibia frames
// at the knees (tibia along −z), foot frames at the ankles; positive
// *_hip_pitch = hip flexion (axis 0 −1 0), *_knee_pitch = knee flexion (axis
// 0 1 0), *_ankle_pitch = dorsiflexion (axis 0 −1 0). Standing at q = 0 with
// the pelvis 0.98 m above the floor puts the soles at z = 0. The gait does
// not rely on any of this: it reads what it needs from the model (gait/leg_kinematics.h).
#pragma once

#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/geometry.h"
#include "robot/urdf_options.h"
#include "scene/scene.h"
#include "scene/shape.h"

namespace proxsim {

/// One shape fixed on a link.
struct LinkShape {
  Shape shape;
  Pose X_LO = Pose::Identity();  ///< shape frame O in its link L
};

struct RobotLink {
  std::string name;
  int parent_joint = -1;            ///< index of the joint whose child this is; −1 for the root
  std::vector<int> child_joints;    ///< joints whose parent this is
  std::vector<LinkShape> shapes;    ///< the geometry UrdfOptions chose (or the other kind when the link has none)
  LinkGeometryKind shapes_kind = LinkGeometryKind::kVisual;  ///< which kind `shapes` came from
  double mass_kg = 0.0;             ///< 0 when the URDF gives no <inertial>
};

enum class JointType { kRevolute, kContinuous, kPrismatic, kFixed };

struct RobotJoint {
  std::string name;
  JointType type = JointType::kFixed;
  int parent_link = -1;
  int child_link = -1;
  Pose X_PJ = Pose::Identity();  ///< joint frame J in the parent link P (URDF <origin>)
  Vec3 axis_J = Vec3::UnitX();   ///< unit axis in J (URDF <axis>)
  double lower = 0.0;            ///< rad or m; only meaningful for revolute/prismatic
  double upper = 0.0;            ///< rad or m
  bool has_limits = false;       ///< the URDF gives <limit>
  double velocity = 0.0;         ///< <limit velocity>: rad/s or m/s (0 when not given)
  double effort = 0.0;           ///< <limit effort>: N·m or N (0 when not given)
};

/// A named pose the model file gives (an MJCF <keyframe><key name=…>): what the
/// robot's makers call its standing or walking pose, e.g. Menagerie's `home`.
struct RobotKeyframe {
  std::string name;
  std::vector<double> q_by_joint;  ///< one value per joint, indexed like joint(i) (rad or m; 0 for fixed joints)
  bool has_root = false;           ///< the key gives the root's pose (a free joint's qpos)
  Pose X_WRoot = Pose::Identity(); ///< root link in W at the key (identity without has_root)
};

/// A geom of an MJCF's world body, not of the robot: the floor and the things
/// a scene file draws around the robot it includes (MuJoCo Menagerie's
/// scene.xml), which the model offers as scene objects (robot/mjcf_model.h
/// says how each maps; a scenario takes them unless `robot.model_scene: ignore`).
struct ModelSceneGeom {
  std::string geom;                  ///< its name in the file, or geom_K for an unnamed one (K: its place among the world body's geoms, from 0)
  std::string type;                  ///< MuJoCo's type name: box, sphere, capsule, cylinder, ellipsoid, mesh, plane, hfield…
  int group = 0;                     ///< its MuJoCo geom group (robot.geom_group does not filter the world's geoms)
  bool ground_plane = false;         ///< the plane z = 0 facing up: the ground, taken only by a scene without one
  std::vector<SceneObject> objects;  ///< what proxsim makes of it, in the world frame (a capsule: three); none when refused
  std::string problem;               ///< why proxsim cannot take it (a plane off the ground, a height field); empty when taken
};

/// A URDF robot: links, joints, shapes and forward kinematics.
class RobotModel {
 public:
  /// Reads a URDF file and its meshes. Throws InputError naming the file when
  /// it is missing, not a valid URDF (urdfdom refuses it: bad XML, a missing
  /// link, a cycle, no root), has invalid geometry, or names a mesh that
  /// cannot be found or read.
  static RobotModel FromUrdfFile(const std::string& path, const UrdfOptions& options = {});

  /// Parses URDF text; `source` names it in messages and its folder resolves
  /// relative mesh paths and starts the search for packages.
  static RobotModel FromUrdfText(const std::string& urdf_text, const std::string& source,
                                 const UrdfOptions& options = {});

  /// Reads a MuJoCo model (MJCF) through the wheel's libmujoco: its bodies, hinge and slide
  /// joints, geoms and sites, as robot/mjcf_model.h maps them, and the world
  /// body's geoms apart (scene_geoms()). Throws InputError naming the file and
  /// what MuJoCo refused, or each element of the robot proxsim cannot follow
  /// (a ball joint, a closed chain, a plane geom on a body…).
  static RobotModel FromMjcfFile(const std::string& path, const UrdfOptions& options = {});

  /// A URDF or an MJCF file, told apart by its first element (<robot> or <mujoco>).
  static RobotModel FromFile(const std::string& path, const UrdfOptions& options = {});

  /// Whether the file's first element is <mujoco> (an MJCF; false for a URDF or a file that cannot be read).
  static bool IsMjcfFile(const std::string& path);

  /// A robot shipped inside the binary: "biped" (data/robots/biped.urdf).
  static RobotModel Builtin(const std::string& name, const UrdfOptions& options = {});

  const std::string& name() const { return name_; }
  const std::string& source() const { return source_; }
  int link_count() const { return static_cast<int>(links_.size()); }
  int joint_count() const { return static_cast<int>(joints_.size()); }
  int root_link() const { return root_link_; }
  const RobotLink& link(int i) const { return links_.at(i); }
  const RobotJoint& joint(int i) const { return joints_.at(i); }
  const std::string& link_name(int i) const { return links_.at(i).name; }
  const std::string& joint_name(int i) const { return joints_.at(i).name; }

  /// Index of the link called `name`, or −1.
  int LinkIndex(const std::string& name) const;
  /// Index of the joint called `name`, or −1.
  int JointIndex(const std::string& name) const;

  /// The joints that move (every one but the fixed ones), in joint order: the
  /// order of a joint vector exchanged with a caller (co-simulation, sim.joint_names).
  std::vector<int> MovingJoints() const;

  /// Total mass of the links, kg.
  double TotalMass_kg() const;

  /// Triangles of the links' meshes (each link counts its own, shared files included).
  std::size_t MeshTriangleCount() const;
  /// Distinct mesh files loaded (a file used by several links counts once).
  std::size_t MeshFileCount() const { return mesh_file_count_; }

  /// The model's named poses (MJCF keyframes; none for a URDF), in file order.
  const std::vector<RobotKeyframe>& keyframes() const { return keyframes_; }
  /// The keyframe called `name`, or null.
  const RobotKeyframe* Keyframe(const std::string& name) const;

  /// The geoms of an MJCF's world body (a scene file that includes the robot),
  /// in file order; none for a URDF or a robot's own MJCF.
  const std::vector<ModelSceneGeom>& scene_geoms() const { return scene_geoms_; }

  /// What the loader's engine was (e.g. "MuJoCo 4.0.0" for an MJCF; empty for a URDF).
  const std::string& loader() const { return loader_; }

  /// Poses of every link in W given the root link's pose X_WRoot and one value
  /// per joint (rad or m, indexed like joint(i); fixed joints ignore theirs).
  /// Both spans are sized joint_count() and link_count().
  void ForwardKinematics(const Pose& X_WRoot, std::span<const double> q_by_joint_index,
                         std::span<Pose> X_WL_out) const;

  /// X_PC of joint j at value q: its child link's frame in its parent link's (X_PJ·M(q)).
  Pose JointTransform(int joint, double q) const;

  /// Convenience: the same returning a vector.
  std::vector<Pose> ForwardKinematics(const Pose& X_WRoot, std::span<const double> q_by_joint_index) const;

 private:
  std::string name_;
  std::string source_;
  std::vector<RobotLink> links_;
  std::vector<RobotJoint> joints_;
  std::unordered_map<std::string, int> link_of_, joint_of_;  ///< names to indices (LinkIndex, JointIndex)
  std::vector<int> joint_order_;  ///< joints parents-first, for forward kinematics
  int root_link_ = -1;
  std::size_t mesh_file_count_ = 0;
  std::vector<RobotKeyframe> keyframes_;
  std::vector<ModelSceneGeom> scene_geoms_;
  std::string loader_;
};

}  // namespace proxsim

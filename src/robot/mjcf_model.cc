// RobotModel::FromMjcfFile: an MJCF file compiled by MuJoCo (mj_loadXML), its
// bodies, joints, geoms and sites mapped into the link and joint tables (the
// mapping: robot/mjcf_model.h).
#include "robot/mjcf_model.h"

#include <mujoco/mujoco.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/input_limits.h"
#include "scene/mesh_prescan.h"
#include "robot/robot_model.h"

namespace proxsim {

std::shared_ptr<const TriangleMesh> EllipsoidMesh(const Vec3& radii) {
  constexpr double kPi = 3.14159265358979323846;
  const int rings = kEllipsoidRings, segments = 2 * kEllipsoidRings;
  auto mesh = std::make_shared<TriangleMesh>();
  // the poles, and (rings − 1) circles of latitude between them
  mesh->vertices_O.emplace_back(0.0f, 0.0f, static_cast<float>(radii.z()));
  for (int i = 1; i < rings; ++i) {
    const double polar = kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double azimuth = 2 * kPi * j / segments;
      mesh->vertices_O.emplace_back(static_cast<float>(radii.x() * std::sin(polar) * std::cos(azimuth)),
                                    static_cast<float>(radii.y() * std::sin(polar) * std::sin(azimuth)),
                                    static_cast<float>(radii.z() * std::cos(polar)));
    }
  }
  mesh->vertices_O.emplace_back(0.0f, 0.0f, static_cast<float>(-radii.z()));
  const auto at = [&](int ring, int j) { return static_cast<std::uint32_t>(1 + (ring - 1) * segments + j % segments); };
  const auto south = static_cast<std::uint32_t>(mesh->vertices_O.size() - 1);
  // caps, then the bands between circles, counter-clockwise seen from outside
  for (int j = 0; j < segments; ++j) {
    mesh->triangles.push_back({0, at(1, j), at(1, j + 1)});
    mesh->triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
  }
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      mesh->triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh->triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

namespace {

// MuJoCo's warnings go to a file in the working folder by default: collected instead, while one load runs
std::vector<std::string>* g_warnings = nullptr;
extern "C" void CollectWarning(const char* text) {
  if (g_warnings != nullptr) g_warnings->push_back(text);
}

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;

// The text of an MJCF file, when it is a regular file within the size limit
std::optional<std::string> MjcfText(const std::filesystem::path& path) {
  if (!RegularFileProblem(path.string(), kMaxUrdfBytes).empty()) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The file an <include> tag starting at `at` names (beside `path`), or none
// when its file="..." cannot be read before the tag's end
std::optional<std::filesystem::path> IncludedFile(const std::filesystem::path& path, const std::string& text,
                                                  std::size_t at) {
  const std::size_t file = text.find("file=", at);
  const std::size_t end_tag = text.find('>', at);
  if (file == std::string::npos || file > end_tag || file + 6 >= text.size()) return std::nullopt;
  const std::size_t close = text.find(text[file + 5], file + 6);
  if (close == std::string::npos) return std::nullopt;
  return path.parent_path() / text.substr(file + 6, close - file - 6);
}

// The <body> elements of an MJCF file and of the files it includes (each
// once), counted before MuJoCo compiles them: its compile time and memory
// grow faster than linearly with the count (20 000 bodies: 105 s and 1.8 GB).
std::size_t CountMjcfBodies(const std::filesystem::path& path, std::set<std::string>& seen) {
  std::error_code error;
  const std::string key = std::filesystem::weakly_canonical(path, error).string();
  if (!seen.insert(key).second) return 0;
  const std::optional<std::string> text = MjcfText(path);
  if (!text) return 0;
  std::size_t bodies = 0;
  for (std::size_t at = text->find("<body"); at != std::string::npos; at = text->find("<body", at + 5)) {
    const char next = at + 5 < text->size() ? (*text)[at + 5] : '\0';
    if (next == ' ' || next == '>' || next == '/' || next == '\t' || next == '\n' || next == '\r') ++bodies;
  }
  for (std::size_t at = text->find("<include"); at != std::string::npos; at = text->find("<include", at + 8)) {
    if (const auto included = IncludedFile(path, *text, at)) bodies += CountMjcfBodies(*included, seen);
  }
  return bodies;
}

// The scan behind MjcfMayHaveWorldGeoms: the file's elements in order, the
// bodies open under <worldbody> counted; `in_world` starts true for a file
// included directly in <worldbody> (its elements are the world body's).
bool ScanWorldGeoms(const std::filesystem::path& path, bool in_world, std::set<std::string>& seen) {
  std::error_code error;
  const std::string key = std::filesystem::weakly_canonical(path, error).string();
  if (!seen.insert(key + (in_world ? "\n1" : "\n0")).second) return false;
  const std::optional<std::string> read = MjcfText(path);
  if (!read) return true;  // unread: it may
  const std::string& text = *read;
  int bodies = 0;  // open under <worldbody>
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    // comments, declarations and processing instructions hold no elements
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) break;
      continue;
    }
    if (text.compare(at, 2, "<?") == 0 || text.compare(at, 2, "<!") == 0) continue;
    const bool closing = text.compare(at, 2, "</") == 0;
    std::size_t name_end = at + (closing ? 2 : 1);
    while (name_end < text.size() && (std::isalnum(static_cast<unsigned char>(text[name_end])) != 0 ||
                                      text[name_end] == '_' || text[name_end] == '-'))
      ++name_end;
    const std::string name = text.substr(at + (closing ? 2 : 1), name_end - at - (closing ? 2 : 1));
    // the tag's end, past quoted attribute values
    std::size_t end = name_end;
    for (char quote = 0; end < text.size() && (quote != 0 || text[end] != '>'); ++end) {
      if (quote == 0 && (text[end] == '"' || text[end] == '\'')) quote = text[end];
      else if (quote != 0 && text[end] == quote) quote = 0;
    }
    const bool empty = end > 0 && end < text.size() && text[end - 1] == '/';
    if (closing) {
      if (name == "worldbody") in_world = false;
      if (name == "body" && bodies > 0) --bodies;
    } else if (name == "worldbody") {
      in_world = !empty;
      bodies = 0;
    } else if (in_world && name == "body") {
      bodies += empty ? 0 : 1;
    } else if (in_world && bodies == 0 && (name == "geom" || name == "attach" || name == "composite" || name == "flexcomp")) {
      return true;
    } else if (name == "compiler" && text.substr(at, end - at).find("fusestatic") != std::string::npos) {
      return true;  // static bodies may be fused into the world body
    } else if (name == "include") {
      // an included file's elements stand where it is included
      const auto included = IncludedFile(path, text, at);
      if (!included || ScanWorldGeoms(*included, in_world && bodies == 0, seen)) return true;
    }
    at = end;
  }
  return false;
}

ModelPtr LoadCompiled(const std::string& path) {
  std::set<std::string> seen;
  if (const std::size_t bodies = CountMjcfBodies(path, seen); bodies > kMaxMjcfBodies) {
    throw InputError(path + ": " + std::to_string(bodies) + " <body> elements (with its includes), beyond the limit of " +
                     std::to_string(kMaxMjcfBodies) + " (MuJoCo's compile time grows faster than the count; "
                     "docs/trust.md)");
  }
  // mj_loadXML and the warning hook are process-global: one load at a time
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  std::vector<std::string> warnings;
  g_warnings = &warnings;
  void (*previous)(const char*) = mju_user_warning;
  mju_user_warning = CollectWarning;
  char error[1024] = "";
  ModelPtr model(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  mju_user_warning = previous;
  g_warnings = nullptr;
  if (!model) {
    throw InputError(path + ": MuJoCo " + mj_versionString() + " could not load the MJCF: " +
                     (error[0] != '\0' ? std::string(error) : "no reason given"));
  }
  return model;
}

Pose PoseOf(const mjtNum* pos, const mjtNum* quat_wxyz) {
  Pose X = Pose::Identity();
  X.linear() = Eigen::Quaterniond(quat_wxyz[0], quat_wxyz[1], quat_wxyz[2], quat_wxyz[3]).normalized().toRotationMatrix();
  X.translation() = Vec3(pos[0], pos[1], pos[2]);
  return X;
}

Pose Translation(const Vec3& p) {
  Pose X = Pose::Identity();
  X.translation() = p;
  return X;
}

// an object's name, or a stand-in for an unnamed one ("body 3")
std::string NameOf(const mjModel* m, int type, int id, const char* kind) {
  const char* name = mj_id2name(m, type, id);
  return name != nullptr && name[0] != '\0' ? std::string(name) : std::string(kind) + " " + std::to_string(id);
}

const char* GeomTypeName(int type) {
  switch (type) {
    case mjGEOM_PLANE: return "plane";
    case mjGEOM_HFIELD: return "hfield";
    case mjGEOM_SPHERE: return "sphere";
    case mjGEOM_CAPSULE: return "capsule";
    case mjGEOM_ELLIPSOID: return "ellipsoid";
    case mjGEOM_CYLINDER: return "cylinder";
    case mjGEOM_BOX: return "box";
    case mjGEOM_MESH: return "mesh";
    case mjGEOM_SDF: return "sdf";
    default: return "unknown";
  }
}

using MeshCache = std::map<int, std::shared_ptr<const TriangleMesh>>;  // by MuJoCo mesh id, shared by its geoms

// A geom's proxsim shapes in its body's frame (a capsule's surface is a
// cylinder's side and a sphere at each end); none for a type proxsim does
// not take on a body (a plane, a height field)
std::vector<LinkShape> GeomShapes(const mjModel* m, int g, MeshCache& meshes) {
  const Pose X_BO = PoseOf(m->geom_pos + 3 * g, m->geom_quat + 4 * g);
  const mjtNum* size = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_BOX: return {{Box{2.0 * Vec3(size[0], size[1], size[2])}, X_BO}};
    case mjGEOM_SPHERE: return {{Sphere{size[0]}, X_BO}};
    case mjGEOM_CYLINDER: return {{Cylinder{size[0], 2.0 * size[1]}, X_BO}};
    case mjGEOM_CAPSULE:
      return {{Cylinder{size[0], 2.0 * size[1]}, X_BO},
              {Sphere{size[0]}, X_BO * Translation(Vec3(0, 0, size[1]))},
              {Sphere{size[0]}, X_BO * Translation(Vec3(0, 0, -size[1]))}};
    case mjGEOM_ELLIPSOID:
      return {{Mesh{.file = "ellipsoid", .data = EllipsoidMesh(Vec3(size[0], size[1], size[2]))}, X_BO}};
    case mjGEOM_MESH: {
      const int id = m->geom_dataid[g];
      auto& data = meshes[id];
      if (!data) {
        auto mesh = std::make_shared<TriangleMesh>();
        for (int v = m->mesh_vertadr[id]; v < m->mesh_vertadr[id] + m->mesh_vertnum[id]; ++v)
          mesh->vertices_O.emplace_back(m->mesh_vert[3 * v], m->mesh_vert[3 * v + 1], m->mesh_vert[3 * v + 2]);
        for (int f = m->mesh_faceadr[id]; f < m->mesh_faceadr[id] + m->mesh_facenum[id]; ++f) {
          mesh->triangles.push_back({static_cast<std::uint32_t>(m->mesh_face[3 * f]),
                                     static_cast<std::uint32_t>(m->mesh_face[3 * f + 1]),
                                     static_cast<std::uint32_t>(m->mesh_face[3 * f + 2])});
        }
        data = std::move(mesh);
      }
      return {{Mesh{.file = NameOf(m, mjOBJ_MESH, id, "mesh"), .data = data}, X_BO}};
    }
    default: return {};
  }
}

// The world body's geoms: the scene a scene file draws around the robot.
// Each becomes scene objects named model:GEOM in the world frame (a
// capsule's ends model:GEOM:top and model:GEOM:bottom, along its own +z and
// −z); the plane z = 0 facing up is the ground; any other plane, and what
// proxsim has no shape for, is named as not taken.
std::vector<ModelSceneGeom> WorldGeoms(const mjModel* m) {
  std::vector<ModelSceneGeom> geoms;
  MeshCache meshes;
  for (int k = 0; k < m->body_geomnum[0]; ++k) {
    const int g = m->body_geomadr[0] + k;
    const char* name = mj_id2name(m, mjOBJ_GEOM, g);
    ModelSceneGeom geom{.geom = name != nullptr && name[0] != '\0' ? std::string(name) : "geom_" + std::to_string(k),
                        .type = GeomTypeName(m->geom_type[g]),
                        .group = m->geom_group[g],
                        .ground_plane = false,
                        .objects = {},
                        .problem = {}};
    const std::string object = "model:" + geom.geom;
    if (m->geom_type[g] == mjGEOM_PLANE) {
      // the ground: the plane through the origin facing +z, whatever its drawn size (MuJoCo's contacts take a plane as unbounded)
      const Pose X_WO = PoseOf(m->geom_pos + 3 * g, m->geom_quat + 4 * g);
      const Vec3 normal_W = X_WO.linear().col(2);
      if ((normal_W - Vec3::UnitZ()).norm() < 1e-9 && std::abs(X_WO.translation().z()) < 1e-9) {
        geom.ground_plane = true;
        geom.objects.push_back(SceneObject{.name = object, .shape = Plane{}, .X_WO = Pose::Identity(), .material = {}, .ground = true});
      } else {
        geom.problem = "a plane that is not the ground (z = 0, facing up): proxsim takes a model's plane only as its "
                       "ground; give it in the scenario's scene (a plane object with its pose, or a box)";
      }
      geoms.push_back(std::move(geom));
      continue;
    }
    const std::vector<LinkShape> shapes = GeomShapes(m, g, meshes);
    if (shapes.empty()) {
      geom.problem = "a " + geom.type + ": not supported in a scene (box, sphere, capsule, cylinder, ellipsoid, mesh "
                     "and the ground plane are)";
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      const char* part = shapes.size() == 1 ? "" : i == 0 ? "" : i == 1 ? ":top" : ":bottom";
      geom.objects.push_back(SceneObject{
          .name = object + part, .shape = shapes[i].shape, .X_WO = shapes[i].X_LO, .material = {}, .ground = false});
    }
    geoms.push_back(std::move(geom));
  }
  return geoms;
}

}  // namespace

bool MjcfMayHaveWorldGeoms(const std::string& path) {
  std::set<std::string> seen;
  return ScanWorldGeoms(path, false, seen);
}

// The tables are filled here, in body order (MuJoCo numbers a body after its
// parent), so that joints come parents first as forward kinematics needs.
RobotModel RobotModel::FromMjcfFile(const std::string& path, const UrdfOptions& options) {
  if (const std::string problem = RegularFileProblem(path, kMaxUrdfBytes); !problem.empty()) throw InputError(problem);
  const ModelPtr owner = LoadCompiled(path);
  const mjModel* m = owner.get();
  std::vector<std::string> problems;
  const std::string where = path + ": ";

  // what proxsim's kinematic tree cannot follow, named. A joint coupling
  // (a gripper's fingers) is kept when the reference pose (every qpos 0, where
  // proxsim holds the joints the gait does not drive) satisfies it: MuJoCo's
  // coupling is q1 − ref1 = Σ c_i (q2 − ref2)^i (without joint2, q1 − ref1 = c0)
  for (int e = 0; e < m->neq; ++e) {
    if (!m->eq_active0[e]) continue;  // off unless a controller turns it on
    const std::string name = NameOf(m, mjOBJ_EQUALITY, e, "equality");
    if (m->eq_type[e] != mjEQ_JOINT) {
      problems.push_back(where + "equality constraint '" + name +
                         "' is not supported: proxsim's robot is a kinematic tree (no closed chains or welds; "
                         "joint couplings are)");
      continue;
    }
    const int j1 = m->eq_obj1id[e], j2 = m->eq_obj2id[e];
    const double d1 = 0.0 - m->qpos0[m->jnt_qposadr[j1]];
    const double d2 = j2 >= 0 ? 0.0 - m->qpos0[m->jnt_qposadr[j2]] : 0.0;
    const mjtNum* c = m->eq_data + mjNEQDATA * e;
    const double residual = d1 - (c[0] + d2 * (c[1] + d2 * (c[2] + d2 * (c[3] + d2 * c[4]))));
    if (std::abs(residual) > 1e-9) {
      problems.push_back(where + "joint coupling '" + name + "' (joint '" + NameOf(m, mjOBJ_JOINT, j1, "joint") +
                         "') does not hold at the reference pose (every joint at 0), off by " +
                         std::to_string(residual) + ": proxsim holds coupled joints there");
    }
  }
  if (m->nskin > 0) problems.push_back(where + "skins are not supported (" + std::to_string(m->nskin) + " skin(s))");
  std::vector<int> roots;
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_parentid[b] == 0) roots.push_back(b);
    if (m->body_mocapid[b] >= 0) {
      problems.push_back(where + "body '" + NameOf(m, mjOBJ_BODY, b, "body") + "' is a mocap body: not supported");
    }
  }
  if (roots.size() != 1) {
    std::string names;
    for (const int b : roots) names += (names.empty() ? "'" : ", '") + NameOf(m, mjOBJ_BODY, b, "body") + "'";
    problems.push_back(where + "expected one body under the world (the robot's root), found " +
                       std::to_string(roots.size()) + (names.empty() ? "" : ": " + names));
    throw InputError(problems);
  }
  if (options.geom_group < -1 || options.geom_group > 5) {
    problems.push_back(where + "geom group " + std::to_string(options.geom_group) + ": expected 0 to 5, or none for every geom");
  }

  RobotModel model;
  model.name_ = m->names != nullptr ? std::string(m->names) : std::string();
  model.source_ = path;
  const auto add_link = [&](const std::string& name, double mass_kg) {
    const int index = static_cast<int>(model.links_.size());
    if (!model.link_of_.try_emplace(name, index).second) {
      problems.push_back(where + "the name '" + name + "' is used by two links (bodies, sites or a body's joint links)");
    }
    model.links_.push_back(RobotLink{.name = name, .child_joints = {}, .shapes = {}, .mass_kg = mass_kg});
    return index;
  };
  const auto add_joint = [&](const std::string& name, JointType type, int parent, int child, const Pose& X_PJ,
                             const Vec3& axis_J) {
    const int index = static_cast<int>(model.joints_.size());
    if (!model.joint_of_.try_emplace(name, index).second) problems.push_back(where + "two joints are named '" + name + "'");
    model.joints_.push_back(RobotJoint{.name = name, .type = type, .parent_link = parent, .child_link = child,
                                       .X_PJ = X_PJ, .axis_J = axis_J});
    model.links_[parent].child_joints.push_back(index);
    model.links_[child].parent_joint = index;
    return index;
  };

  // bodies: each a link; its joints between it and its parent's link
  std::vector<int> link_of_body(m->nbody, -1);
  std::map<int, int> mujoco_joint_of;  // proxsim's moving joint -> MuJoCo's joint id (for keyframes)
  MeshCache meshes;
  for (int b = roots[0]; b < m->nbody; ++b) {
    const std::string body = NameOf(m, mjOBJ_BODY, b, "body");
    const bool root = b == roots[0];
    if (!root && link_of_body[m->body_parentid[b]] < 0) continue;  // under a body already refused
    int parent = root ? -1 : link_of_body[m->body_parentid[b]];
    Pose X_PB = root ? Pose::Identity() : PoseOf(m->body_pos + 3 * b, m->body_quat + 4 * b);

    // the moving joints of this body, in MuJoCo's order
    std::vector<int> moving;
    for (int j = m->body_jntadr[b]; m->body_jntnum[b] > 0 && j < m->body_jntadr[b] + m->body_jntnum[b]; ++j) {
      const std::string joint = NameOf(m, mjOBJ_JOINT, j, "joint");
      switch (m->jnt_type[j]) {
        case mjJNT_FREE:
          if (!root) problems.push_back(where + "free joint '" + joint + "' of body '" + body + "' below the root: not supported");
          break;
        case mjJNT_BALL:
          problems.push_back(where + "ball joint '" + joint + "' of body '" + body +
                             "': not supported (proxsim's joints have one degree of freedom: use hinges)");
          break;
        default:
          if (root) {
            problems.push_back(where + "joint '" + joint + "' attaches the root body '" + body +
                               "' to the world: not supported (proxsim places the root itself: give it a <freejoint/> or none)");
          } else {
            moving.push_back(j);
          }
      }
    }

    // a link per joint between the parent and the body, each on its joint's anchor
    int link = -1;  // the body's own link
    for (std::size_t k = 0; k < moving.size(); ++k) {
      const int j = moving[k];
      const std::string joint = NameOf(m, mjOBJ_JOINT, j, "joint");
      const Vec3 anchor(m->jnt_pos[3 * j], m->jnt_pos[3 * j + 1], m->jnt_pos[3 * j + 2]);
      Vec3 axis(m->jnt_axis[3 * j], m->jnt_axis[3 * j + 1], m->jnt_axis[3 * j + 2]);
      if (axis.norm() < 1e-12) {
        problems.push_back(where + "joint '" + joint + "' has a zero axis");
        axis = Vec3::UnitX();
      }
      const bool last = k + 1 == moving.size();
      const bool on_origin = anchor.norm() == 0.0;
      const int child = add_link(last && on_origin ? body : body + "." + joint, last && on_origin ? m->body_mass[b] : 0.0);
      const bool hinge = m->jnt_type[j] == mjJNT_HINGE;
      const bool limited = m->jnt_limited[j] != 0;
      // proxsim's q is MuJoCo's qpos: MuJoCo turns a joint by qpos − ref from
      // the pose the XML draws (ref = qpos0), so the joint frame is the XML's
      // turned back by ref, and the XML's pose is q = ref
      const double ref = m->qpos0[m->jnt_qposadr[j]];
      Pose X_PJ = X_PB * Translation(anchor);
      if (hinge) {
        X_PJ.linear() = X_PJ.linear() * Eigen::AngleAxisd(-ref, axis.normalized()).toRotationMatrix();
      } else {
        X_PJ = X_PJ * Translation(-ref * axis.normalized());
      }
      const int index = add_joint(joint, hinge ? (limited ? JointType::kRevolute : JointType::kContinuous) : JointType::kPrismatic,
                                  parent, child, X_PJ, axis.normalized());
      mujoco_joint_of[index] = j;
      if (limited) {
        model.joints_[index].has_limits = true;
        model.joints_[index].lower = m->jnt_range[2 * j];
        model.joints_[index].upper = m->jnt_range[2 * j + 1];
      }
      if (last && on_origin) link = child;
      parent = child;
      X_PB = Translation(-anchor);
    }
    // the body itself, unless it is the last joint's child: the root, or fixed to what came before
    if (link < 0) {
      link = add_link(body, m->body_mass[b]);
      if (!root) add_joint("fixed:" + body, JointType::kFixed, parent, link, X_PB, Vec3::UnitX());
    }
    link_of_body[b] = link;

    // its geoms of the group chosen
    for (int g = m->body_geomadr[b]; m->body_geomnum[b] > 0 && g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
      if (options.geom_group >= 0 && m->geom_group[g] != options.geom_group) continue;
      std::vector<LinkShape> shapes = GeomShapes(m, g, meshes);
      if (shapes.empty()) {
        problems.push_back(where + "geom '" + NameOf(m, mjOBJ_GEOM, g, "geom") + "' of body '" + body + "' is a " +
                           GeomTypeName(m->geom_type[g]) +
                           ": not supported on a robot (box, sphere, capsule, cylinder, ellipsoid and mesh are)");
      }
      auto& link_shapes = model.links_[link].shapes;
      link_shapes.insert(link_shapes.end(), std::make_move_iterator(shapes.begin()), std::make_move_iterator(shapes.end()));
    }
  }

  // sites: frames fixed to their bodies, where sensors may mount
  for (int s = 0; s < m->nsite; ++s) {
    const int body_link = link_of_body[m->site_bodyid[s]];
    if (body_link < 0) continue;  // the world's, or under a body refused
    const std::string site = NameOf(m, mjOBJ_SITE, s, "site");
    const int link = add_link(site, 0.0);
    add_joint("site:" + site, JointType::kFixed, body_link, link, PoseOf(m->site_pos + 3 * s, m->site_quat + 4 * s),
              Vec3::UnitX());
  }
  if (!problems.empty()) throw InputError(problems);

  // keyframes: each joint's qpos, and the root's pose when it has a free joint
  int root_free_qpos = -1;
  if (m->body_jntnum[roots[0]] > 0 && m->jnt_type[m->body_jntadr[roots[0]]] == mjJNT_FREE) {
    root_free_qpos = m->jnt_qposadr[m->body_jntadr[roots[0]]];
  }
  for (int k = 0; k < m->nkey; ++k) {
    const mjtNum* qpos = m->key_qpos + k * m->nq;
    RobotKeyframe key{.name = NameOf(m, mjOBJ_KEY, k, "key"), .q_by_joint = std::vector<double>(model.joints_.size(), 0.0)};
    for (const auto& [joint, j] : mujoco_joint_of) key.q_by_joint[joint] = qpos[m->jnt_qposadr[j]];
    if (root_free_qpos >= 0) {
      key.has_root = true;
      key.X_WRoot = PoseOf(qpos + root_free_qpos, qpos + root_free_qpos + 3);
    }
    model.keyframes_.push_back(std::move(key));
  }
  model.loader_ = std::string("MuJoCo ") + mj_versionString();
  model.scene_geoms_ = WorldGeoms(m);

  // forward kinematics in joint order: each joint was added after its parent link was reached
  model.root_link_ = 0;
  model.mesh_file_count_ = meshes.size();
  model.joint_order_.resize(model.joints_.size());
  for (int j = 0; j < model.joint_count(); ++j) model.joint_order_[j] = j;
  return model;
}

}  // namespace proxsim

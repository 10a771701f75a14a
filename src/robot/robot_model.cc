// RobotModel: URDF through urdfdom into flat link/joint tables, and forward
// kinematics over them. urdfdom reports its reasons for refusing a file through
// console_bridge; we capture those lines and put them in the InputError.
#include "robot/robot_model.h"
#include "robot/xacro_expand.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <queue>
#include <sstream>
#include <unordered_map>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "core/embedded_files.h"
#include "core/input_error.h"
#include "core/input_limits.h"
#include "core/nesting_scan.h"
#include "robot/mesh_uri.h"
#include "scene/mesh_loader.h"
#include "scene/mesh_prescan.h"

namespace proxsim {

namespace {

// Collects urdfdom's error and warning lines while one parse runs.
class CaptureHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) lines.push_back(text);
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::vector<std::string> lines;
  std::vector<std::string> errors;  ///< what urdfdom logs as an error and then drops (a <box size="big"/>)
};

urdf::ModelInterfaceSharedPtr ParseCapturingErrors(const std::string& text, std::vector<std::string>* messages,
                                                   std::vector<std::string>* errors) {
  // console_bridge's handler is process-global: one parse at a time.
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  CaptureHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(text);
  } catch (const std::exception& e) {
    handler.lines.push_back(e.what());
  }
  console_bridge::restorePreviousOutputHandler();
  *messages = std::move(handler.lines);
  *errors = std::move(handler.errors);
  return model;
}

Pose PoseFromUrdf(const urdf::Pose& p) {
  Pose X = Pose::Identity();
  X.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  X.translation() = Vec3(p.position.x, p.position.y, p.position.z);
  return X;
}

// The meshes of one URDF: each file found (robot/mesh_uri.h) and read once,
// however many links name it, at whatever scales (a scaled copy is made from
// the file's triangles, not read again).
class UrdfMeshes {
 public:
  UrdfMeshes(const std::string& source, const UrdfOptions& options)
      : options_(options), urdf_dir_(std::filesystem::path(source).parent_path()) {}

  /// The mesh shape for a URDF <mesh>; nullopt after adding a problem.
  std::optional<Mesh> Load(const urdf::Mesh& m, const std::string& where, std::vector<std::string>* problems) {
    const Vec3 scale(m.scale.x, m.scale.y, m.scale.z);
    if (!scale.allFinite() || (scale.array() == 0).any()) {
      problems->push_back(where + ": mesh '" + m.filename + "' has a zero or non-finite scale");
      return std::nullopt;
    }
    const MeshLookup lookup = ResolveMeshUri(m.filename, urdf_dir_, options_.package_paths);
    if (!lookup.path && !lookup.missing_package.empty()) {
      // a package that is nowhere: one line for it, however many meshes name it
      auto [missing, first] = missing_packages_.try_emplace(lookup.missing_package);
      if (first) missing->second.line = where + ": mesh '" + m.filename + "' not found: " + lookup.problem;
      else ++missing->second.more_meshes;
      return std::nullopt;
    }
    if (!lookup.path) {
      problems->push_back(where + ": mesh '" + m.filename + "' not found: " + lookup.problem);
      return std::nullopt;
    }
    // the file, read once
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(*lookup.path, error);
    const std::string file = error ? lookup.path->string() : canonical.string();
    auto raw = read_.find(file);
    if (raw == read_.end()) {
      std::shared_ptr<const TriangleMesh> data;
      std::string why;
      try {
        data = LoadMeshFile(lookup.path->string(), Vec3::Ones());
      } catch (const InputError& e) {
        for (const std::string& line : e.problems()) why += (why.empty() ? "" : "; ") + line;
      }
      raw = read_.emplace(file, FileRead{std::move(data), std::move(why)}).first;
    }
    if (!raw->second.data) {
      problems->push_back(where + ": mesh '" + m.filename + "': " + raw->second.why);
      return std::nullopt;
    }
    if (scale == Vec3::Ones()) return Mesh{.file = m.filename, .scale = scale, .data = raw->second.data};
    // a scale: one scaled copy per file and scale
    const auto key = std::make_pair(file, std::array<double, 3>{scale.x(), scale.y(), scale.z()});
    auto scaled = scaled_.find(key);
    if (scaled == scaled_.end()) {
      auto copy = std::make_shared<TriangleMesh>(*raw->second.data);
      for (Vec3f& v : copy->vertices_O) {
        v = (v.cast<double>().cwiseProduct(scale)).cast<float>();
        if (!v.allFinite()) {
          problems->push_back(where + ": mesh '" + m.filename + "': a vertex is not finite after scaling");
          return std::nullopt;
        }
      }
      scaled = scaled_.emplace(key, std::move(copy)).first;
    }
    return Mesh{.file = m.filename, .scale = scale, .data = scaled->second};
  }

  /// Mesh files read (successfully or not).
  std::size_t file_count() const { return read_.size(); }

  /// One problem per package that was found nowhere: the first mesh naming it,
  /// the folders searched, and how many other meshes name it.
  void AddMissingPackages(std::vector<std::string>* problems) const {
    for (const auto& [name, missing] : missing_packages_) {
      std::string line = missing.line;
      if (missing.more_meshes > 0)
        line += " (and " + std::to_string(missing.more_meshes) + " other mesh" + (missing.more_meshes == 1 ? "" : "es") +
                " of package '" + name + "')";
      problems->push_back(std::move(line));
    }
  }

 private:
  struct FileRead {
    std::shared_ptr<const TriangleMesh> data;  // null when the file could not be read
    std::string why;                           // and why
  };
  const UrdfOptions& options_;
  std::filesystem::path urdf_dir_;
  struct MissingPackage {
    std::string line;     // the first mesh's problem
    int more_meshes = 0;  // other meshes naming the same package
  };
  std::map<std::string, FileRead> read_;
  std::map<std::string, MissingPackage> missing_packages_;
  std::map<std::pair<std::string, std::array<double, 3>>, std::shared_ptr<const TriangleMesh>> scaled_;
};

// A URDF geometry as a proxsim shape; adds a problem and returns false when unsupported.
bool ShapeFromUrdf(const urdf::Geometry& g, const std::string& where, UrdfMeshes& meshes, Shape* out,
                   std::vector<std::string>* problems) {
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(g);
      *out = Box{Vec3(b.dim.x, b.dim.y, b.dim.z)};
      if (b.dim.x <= 0 || b.dim.y <= 0 || b.dim.z <= 0) {
        problems->push_back(where + ": box size must be > 0 on every axis");
        return false;
      }
      return true;
    }
    case urdf::Geometry::SPHERE: {
      const auto& s = static_cast<const urdf::Sphere&>(g);
      if (s.radius <= 0) {
        problems->push_back(where + ": sphere radius must be > 0");
        return false;
      }
      *out = Sphere{s.radius};
      return true;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      if (c.radius <= 0 || c.length <= 0) {
        problems->push_back(where + ": cylinder radius and length must be > 0");
        return false;
      }
      *out = Cylinder{c.radius, c.length};
      return true;
    }
    case urdf::Geometry::MESH: {
      auto mesh = meshes.Load(static_cast<const urdf::Mesh&>(g), where, problems);
      if (!mesh) return false;
      *out = std::move(*mesh);
      return true;
    }
  }
  problems->push_back(where + ": unknown geometry type");
  return false;
}

// A xacro file uses xacro's elements (<xacro:macro>, <xacro:include>...) or,
// declaring its namespace (xmlns:xacro="..."), its substitutions (${...},
// $(...)). The namespace alone is not enough: xacro's own output may keep the
// declaration on a URDF that has nothing left to expand.
bool IsXacro(const std::string& text) {
  if (text.find("<xacro:") != std::string::npos) return true;
  return text.find("xmlns:xacro") != std::string::npos &&
         (text.find("${") != std::string::npos || text.find("$(") != std::string::npos);
}

Pose JointMotion(const RobotJoint& j, double q) {
  Pose M = Pose::Identity();
  switch (j.type) {
    case JointType::kRevolute:
    case JointType::kContinuous:
      M.linear() = Eigen::AngleAxisd(q, j.axis_J).toRotationMatrix();
      break;
    case JointType::kPrismatic:
      M.translation() = q * j.axis_J;
      break;
    case JointType::kFixed:
      break;
  }
  return M;
}

}  // namespace

const char* LinkGeometryKindName(LinkGeometryKind kind) {
  return kind == LinkGeometryKind::kCollision ? "collision" : "visual";
}

RobotModel RobotModel::FromUrdfFile(const std::string& path, const UrdfOptions& options) {
  // a regular file of bounded size: a FIFO or /dev/zero would never end
  if (const std::string problem = RegularFileProblem(path, kMaxUrdfBytes); !problem.empty())
    throw InputError(problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the URDF file (missing or unreadable)");
  std::stringstream text;
  text << in.rdbuf();
  // a xacro file is expanded by xacro itself (robot/xacro_expand.h); the URDF
  // it prints is read as if it were the file (meshes relative to its folder)
  if (IsXacro(text.str())) return FromUrdfText(ExpandXacro(path), path, options);
  return FromUrdfText(text.str(), path, options);
}

bool RobotModel::IsMjcfFile(const std::string& path) {
  // the first element, past the XML declaration, comments and doctype
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::size_t at = 0;
  for (;;) {
    at = head.find('<', at);
    if (at == std::string::npos) break;
    if (head.compare(at, 4, "<!--") == 0) {
      at = head.find("-->", at);
    } else if (head.compare(at, 2, "<?") == 0 || head.compare(at, 2, "<!") == 0) {
      at = head.find('>', at);
    } else {
      break;
    }
    if (at == std::string::npos) break;
  }
  return at != std::string::npos && head.compare(at, 7, "<mujoco") == 0 &&
         (at + 7 == head.size() || !std::isalnum(static_cast<unsigned char>(head[at + 7])));
}

RobotModel RobotModel::FromFile(const std::string& path, const UrdfOptions& options) {
  return IsMjcfFile(path) ? FromMjcfFile(path, options) : FromUrdfFile(path, options);
}

RobotModel RobotModel::Builtin(const std::string& name, const UrdfOptions& options) {
  const std::string key = "data/robots/" + name + ".urdf";
  const auto& files = EmbeddedFiles();
  const auto it = files.find(key);
  if (it == files.end()) throw InputError("builtin:" + name + ": no built-in robot of that name (known: biped)");
  return FromUrdfText(std::string(it->second), "builtin:" + name, options);
}

RobotModel RobotModel::FromUrdfText(const std::string& urdf_text, const std::string& source,
                                    const UrdfOptions& options) {
  // TinyXML (inside urdfdom) recurses once per nested element: bound the
  // nesting, the size and the number of links before it parses anything
  if (urdf_text.size() > kMaxUrdfBytes) {
    throw InputError(source + ": " + std::to_string(urdf_text.size()) + " bytes, beyond the URDF limit of " +
                     std::to_string(kMaxUrdfBytes) + " bytes (docs/trust.md)");
  }
  const NestingScan scan = ScanXmlNesting(urdf_text, kMaxNestingDepth);
  if (const auto problem = NestingProblem(scan, source, "XML elements", kMaxNestingDepth)) throw InputError(*problem);
  if (scan.elements > 8 * kMaxUrdfLinks) {
    throw InputError(source + ": " + std::to_string(scan.elements) + " XML elements, beyond the limit of " +
                     std::to_string(8 * kMaxUrdfLinks) + " (" + std::to_string(kMaxUrdfLinks) +
                     " links with their joints; docs/trust.md)");
  }
  // urdfdom reads a xacro file as a URDF and drops its macros: the robot would
  // then lack links and joints, blamed elsewhere. Recognised by its content
  // (IsXacro), not its name.
  if (IsXacro(urdf_text)) {
    throw InputError(source + ": this is xacro, given as text: expand it first (`xacro in.urdf.xacro > out.urdf`), "
                     "or give its file (proxsim runs xacro on a file)");
  }
  std::vector<std::string> messages;
  std::vector<std::string> errors;
  const urdf::ModelInterfaceSharedPtr urdf = ParseCapturingErrors(urdf_text, &messages, &errors);
  if (urdf && !errors.empty()) {
    // parsed, but with an element urdfdom could not read and left out: the robot would lack it silently
    std::string why = source + ": urdfdom left out what it could not read: ";
    for (std::size_t i = 0; i < errors.size(); ++i) why += (i ? "; " : "") + errors[i];
    throw InputError(why + " (fix the element, e.g. a box size of three numbers in metres)");
  }
  if (!urdf) {
    std::string why = source + ": urdfdom could not parse the URDF (not XML, a missing link or joint field, "
                               "a joint naming an unknown link, a cycle or no single root)";
    if (!messages.empty()) {
      why += ": ";
      for (std::size_t i = 0; i < messages.size(); ++i) why += (i ? "; " : "") + messages[i];
    }
    throw InputError(why);
  }
  // urdfdom links own their children (shared_ptr): links in a cycle keep each
  // other alive after the model is gone. Cut those edges on every way out.
  struct CutChildLinks {
    urdf::ModelInterface& model;
    ~CutChildLinks() {
      for (auto& [name, link] : model.links_)
        if (link) link->child_links.clear();
    }
  } cut_child_links{*urdf};
  const urdf::LinkConstSharedPtr root = urdf->getRoot();
  if (!root) throw InputError(source + ": the URDF has no root link");

  RobotModel model;
  model.name_ = urdf->getName();
  model.source_ = source;
  std::vector<std::string> problems;
  UrdfMeshes meshes(source, options);

  // Breadth-first from the root: link 0 is the root, every joint comes after
  // its parent link, so joint order is a valid forward-kinematics order.
  // names to indices as they are added: linear in links, not quadratic
  std::unordered_map<std::string, int> link_of, joint_of;
  std::queue<urdf::LinkConstSharedPtr> todo;
  todo.push(root);
  while (!todo.empty()) {
    const urdf::LinkConstSharedPtr ul = todo.front();
    todo.pop();
    const int link_index = static_cast<int>(model.links_.size());
    if (!link_of.try_emplace(ul->name, link_index).second) {
      problems.push_back(source + ": link '" + ul->name + "' is reached twice from the root (a cycle)");
      continue;
    }
    RobotLink link;
    link.name = ul->name;
    if (ul->inertial) link.mass_kg = ul->inertial->mass;
    // Geometry: the kind asked for, else the other one.
    std::vector<std::pair<urdf::GeometrySharedPtr, urdf::Pose>> visual, collision;
    for (const auto& v : ul->visual_array)
      if (v && v->geometry) visual.emplace_back(v->geometry, v->origin);
    for (const auto& c : ul->collision_array)
      if (c && c->geometry) collision.emplace_back(c->geometry, c->origin);
    const bool want_visual = options.geometry == LinkGeometryKind::kVisual;
    const bool use_visual = want_visual ? !visual.empty() : collision.empty();
    link.shapes_kind = use_visual ? LinkGeometryKind::kVisual : LinkGeometryKind::kCollision;
    for (const auto& [g, origin] : use_visual ? visual : collision) {
      Shape shape;
      const std::string where =
          source + ": link '" + ul->name + "' (" + LinkGeometryKindName(link.shapes_kind) + ")";
      if (ShapeFromUrdf(*g, where, meshes, &shape, &problems)) link.shapes.push_back({shape, PoseFromUrdf(origin)});
    }
    if (ul->parent_joint) {
      const auto joint = joint_of.find(ul->parent_joint->name);
      link.parent_joint = joint == joint_of.end() ? -1 : joint->second;
    }
    model.links_.push_back(std::move(link));

    for (const auto& uj : ul->child_joints) {
      const urdf::LinkConstSharedPtr child = urdf->getLink(uj->child_link_name);
      if (!child) {
        problems.push_back(source + ": joint '" + uj->name + "' names a missing child link '" +
                           uj->child_link_name + "'");
        continue;
      }
      RobotJoint joint;
      joint.name = uj->name;
      joint.parent_link = link_index;
      joint.X_PJ = PoseFromUrdf(uj->parent_to_joint_origin_transform);
      const Vec3 axis(uj->axis.x, uj->axis.y, uj->axis.z);
      switch (uj->type) {
        case urdf::Joint::REVOLUTE: joint.type = JointType::kRevolute; break;
        case urdf::Joint::CONTINUOUS: joint.type = JointType::kContinuous; break;
        case urdf::Joint::PRISMATIC: joint.type = JointType::kPrismatic; break;
        case urdf::Joint::FIXED: joint.type = JointType::kFixed; break;
        default:
          problems.push_back(source + ": joint '" + uj->name +
                             "' has an unsupported type (use revolute, continuous, prismatic or fixed)");
          joint.type = JointType::kFixed;
      }
      if (joint.type != JointType::kFixed) {
        if (axis.norm() < 1e-12) {
          problems.push_back(source + ": joint '" + uj->name + "' has a zero axis");
        } else {
          joint.axis_J = axis.normalized();
        }
      }
      if (uj->limits) {
        joint.has_limits = true;
        joint.lower = uj->limits->lower;
        joint.upper = uj->limits->upper;
        joint.velocity = uj->limits->velocity;
        joint.effort = uj->limits->effort;
      }
      model.links_[link_index].child_joints.push_back(static_cast<int>(model.joints_.size()));
      joint_of.try_emplace(joint.name, static_cast<int>(model.joints_.size()));
      model.joints_.push_back(std::move(joint));
      todo.push(child);
    }
  }
  // Child link indices: links were appended in the same breadth-first order.
  // the child of joint j is the link whose parent_joint is j
  for (int l = 0; l < model.link_count(); ++l)
    if (model.links_[l].parent_joint >= 0) model.joints_[model.links_[l].parent_joint].child_link = l;
  // Every link must hang from the root: urdfdom accepts a separate cycle of
  // links (each has a parent, none reaches the root).
  for (const auto& [name, ul] : urdf->links_) {
    if (!link_of.contains(name))
      problems.push_back(source + ": link '" + name +
                         "' is not connected to the root link '" + root->name + "' (a cycle or a second tree)");
  }
  meshes.AddMissingPackages(&problems);
  if (!problems.empty()) throw InputError(problems);
  model.root_link_ = 0;
  model.mesh_file_count_ = meshes.file_count();
  model.link_of_ = std::move(link_of);
  model.joint_of_ = std::move(joint_of);
  model.joint_order_.resize(model.joints_.size());
  for (int j = 0; j < model.joint_count(); ++j) model.joint_order_[j] = j;
  return model;
}

const RobotKeyframe* RobotModel::Keyframe(const std::string& name) const {
  for (const RobotKeyframe& key : keyframes_) {
    if (key.name == name) return &key;
  }
  return nullptr;
}

int RobotModel::LinkIndex(const std::string& name) const {
  const auto it = link_of_.find(name);
  return it == link_of_.end() ? -1 : it->second;
}

int RobotModel::JointIndex(const std::string& name) const {
  const auto it = joint_of_.find(name);
  return it == joint_of_.end() ? -1 : it->second;
}

std::size_t RobotModel::MeshTriangleCount() const {
  std::size_t triangles = 0;
  for (const RobotLink& link : links_)
    for (const LinkShape& shape : link.shapes)
      if (const auto* mesh = std::get_if<Mesh>(&shape.shape)) triangles += mesh->data->triangles.size();
  return triangles;
}

std::vector<int> RobotModel::MovingJoints() const {
  std::vector<int> moving;
  for (int j = 0; j < joint_count(); ++j)
    if (joints_[j].type != JointType::kFixed) moving.push_back(j);
  return moving;
}

double RobotModel::TotalMass_kg() const {
  double m = 0;
  for (const auto& l : links_) m += l.mass_kg;
  return m;
}

void RobotModel::ForwardKinematics(const Pose& X_WRoot, std::span<const double> q_by_joint_index,
                                   std::span<Pose> X_WL_out) const {
  // Sizes are our callers' responsibility (a bug, not bad input).
  if (q_by_joint_index.size() != joints_.size() || X_WL_out.size() != links_.size())
    throw std::logic_error("RobotModel::ForwardKinematics: span sizes do not match the model");
  X_WL_out[root_link_] = X_WRoot;
  for (const int j : joint_order_) {
    const RobotJoint& joint = joints_[j];
    X_WL_out[joint.child_link] = X_WL_out[joint.parent_link] * joint.X_PJ * JointMotion(joint, q_by_joint_index[j]);
  }
}

Pose RobotModel::JointTransform(int joint, double q) const {
  const RobotJoint& j = joints_.at(joint);
  return j.X_PJ * JointMotion(j, q);
}

std::vector<Pose> RobotModel::ForwardKinematics(const Pose& X_WRoot, std::span<const double> q_by_joint_index) const {
  std::vector<Pose> X_WL(links_.size(), Pose::Identity());
  ForwardKinematics(X_WRoot, q_by_joint_index, X_WL);
  return X_WL;
}

}  // namespace proxsim

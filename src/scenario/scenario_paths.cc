#include "scenario/scenario_paths.h"

namespace proxsim {

namespace fs = std::filesystem;

namespace {

// A folder as an absolute path without symbolic links (it need not exist).
fs::path Canonical(const fs::path& dir) {
  std::error_code error;
  const fs::path absolute = fs::absolute(dir.empty() ? fs::path(".") : dir, error);
  const fs::path canonical = fs::weakly_canonical(absolute, error);
  return error ? absolute.lexically_normal() : canonical;
}

// The scalar at `key` of a map, rebased; anything else left as it is.
void RebaseKey(YAML::Node map, const char* key, const fs::path& from_dir, const fs::path& to_dir) {
  if (!map.IsMap()) return;
  YAML::Node value = map[key];
  if (!value.IsDefined() || !value.IsScalar()) return;
  value = RebasedPath(value.Scalar(), from_dir, to_dir);
}

}  // namespace

std::string RebasedPath(const std::string& path, const fs::path& from_dir, const fs::path& to_dir) {
  const fs::path given(path);
  if (path.empty() || given.is_absolute()) return path;
  const fs::path from = Canonical(from_dir), to = Canonical(to_dir);
  if (from == to) return path;
  const fs::path target = (from / given).lexically_normal();
  const fs::path relative = target.lexically_relative(to);
  return relative.empty() ? target.string() : relative.string();
}

void RebaseScenarioPaths(YAML::Node document, const fs::path& from_dir, const fs::path& to_dir) {
  if (!document.IsMap()) return;
  if (YAML::Node scene = document["scene"]; scene.IsMap()) {
    if (YAML::Node objects = scene["objects"]; objects.IsSequence()) {
      for (YAML::Node object : objects) {
        if (!object.IsMap()) continue;
        RebaseKey(object["mesh"], "file", from_dir, to_dir);
        RebaseKey(object["motion"], "trajectory", from_dir, to_dir);
      }
    }
  }
  YAML::Node robot = document["robot"];
  if (!robot.IsMap()) return;
  if (const YAML::Node model = robot["model"]; model.IsScalar() && !model.Scalar().starts_with("builtin:"))
    RebaseKey(robot, "model", from_dir, to_dir);
  RebaseKey(robot, "trajectory", from_dir, to_dir);
  if (YAML::Node folders = robot["package_paths"]; folders.IsSequence()) {
    for (YAML::Node folder : folders)
      if (folder.IsScalar()) folder = RebasedPath(folder.Scalar(), from_dir, to_dir);
  }
}

}  // namespace proxsim

#include "robot/mesh_uri.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

namespace proxsim {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kPackageScheme = "package://";
constexpr std::string_view kFileScheme = "file://";

bool IsRegularFile(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

bool IsDirectory(const fs::path& path) {
  std::error_code error;
  return fs::is_directory(path, error);
}

// `dir` is the package NAME: it is called NAME, or its package.xml says so
bool IsPackage(const fs::path& dir, const std::string& name) {
  const fs::path clean = dir.lexically_normal();
  const std::string base = clean.has_filename() ? clean.filename().string() : clean.parent_path().filename().string();
  return base == name || PackageXmlName(dir) == name;
}

// `dir` itself, then dir/NAME, then any subfolder whose package.xml names
// NAME (sorted): the package roots a search folder offers
std::vector<fs::path> PackagesIn(const fs::path& dir, const std::string& name) {
  std::vector<fs::path> roots;
  if (!IsDirectory(dir)) return roots;
  if (IsPackage(dir, name)) roots.push_back(dir);
  if (IsDirectory(dir / name)) roots.push_back(dir / name);
  std::vector<fs::path> children;
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (IsDirectory(it->path()) && it->path().filename() != name) children.push_back(it->path());
  }
  std::sort(children.begin(), children.end());
  for (const fs::path& child : children)
    if (PackageXmlName(child) == name) roots.push_back(child);
  return roots;
}

std::vector<std::string> SplitColonList(const char* text) {
  std::vector<std::string> parts;
  if (text == nullptr) return parts;
  std::stringstream in{std::string(text)};
  std::string part;
  while (std::getline(in, part, ':'))
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string Join(const std::vector<std::string>& items) {
  std::string all;
  for (const std::string& item : items) all += (all.empty() ? "" : ", ") + item;
  return all.empty() ? "none" : all;
}

MeshLookup FileOrProblem(const fs::path& path, const std::string& form) {
  if (IsRegularFile(path)) return {path, "", ""};
  std::error_code error;
  const bool exists = fs::exists(path, error);
  return {std::nullopt, form + " '" + path.string() + (exists ? "' is not a regular file" : "' does not exist"), ""};
}

// package://NAME/rest through the three places, in order
MeshLookup ResolvePackageUri(const std::string& uri, const fs::path& urdf_dir,
                             std::span<const std::string> package_paths) {
  const std::string body = uri.substr(kPackageScheme.size());
  const std::size_t slash = body.find('/');
  const std::string name = body.substr(0, slash);
  const std::string rest = slash == std::string::npos ? "" : body.substr(slash + 1);
  if (name.empty() || rest.empty()) return {std::nullopt, "expected package://PACKAGE/path/to/file", ""};

  std::vector<std::string> searched, without_file;
  // a candidate package root: the file is there, or it is noted as lacking it
  const auto try_root = [&](const fs::path& root) -> std::optional<fs::path> {
    if (IsRegularFile(root / rest)) return root / rest;
    without_file.push_back(root.string());
    return std::nullopt;
  };
  // 1. robot.package_paths, 2. ROS_PACKAGE_PATH: each folder is the package or holds it
  const std::vector<std::string> ros_paths = SplitColonList(std::getenv("ROS_PACKAGE_PATH"));
  for (const auto& [list, label] : {std::pair{std::vector<std::string>(package_paths.begin(), package_paths.end()),
                                              std::string("robot.package_paths")},
                                    std::pair{ros_paths, std::string("ROS_PACKAGE_PATH")}}) {
    std::vector<std::string> folders;
    for (const std::string& folder : list) {
      folders.push_back(folder);
      for (const fs::path& root : PackagesIn(folder, name))
        if (const auto file = try_root(root)) return {*file, "", ""};
    }
    searched.push_back(label + ": " + Join(folders));
  }
  // 3. the URDF's ancestors, its own folder first
  std::vector<std::string> ancestors;
  std::error_code error;
  fs::path dir = fs::absolute(urdf_dir.empty() ? fs::path(".") : urdf_dir, error).lexically_normal();
  if (!dir.empty() && !dir.has_filename()) dir = dir.parent_path();  // drop a trailing separator
  for (int depth = 0; depth < 256 && !dir.empty(); ++depth) {
    ancestors.push_back(dir.string());
    if (IsPackage(dir, name))
      if (const auto file = try_root(dir)) return {*file, "", ""};
    if (dir == dir.root_path() || dir.parent_path() == dir) break;
    dir = dir.parent_path();
  }
  searched.push_back("the URDF's folder and its ancestors: " + Join(ancestors));

  std::string problem = "package '" + name + "' ";
  problem += without_file.empty() ? "not found" : "found at " + Join(without_file) + " but without '" + rest + "'";
  problem += "; searched " + searched[0] + "; " + searched[1] + "; " + searched[2];
  return {std::nullopt, problem, without_file.empty() ? name : ""};
}

}  // namespace

std::optional<std::string> PackageXmlName(const fs::path& dir) {
  const fs::path xml = dir / "package.xml";
  if (!IsRegularFile(xml)) return std::nullopt;
  std::ifstream in(xml, std::ios::binary);
  // a package.xml is small; read at most 1 MB of it
  std::string text(1 << 20, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t open = text.find("<name>");
  if (open == std::string::npos) return std::nullopt;
  const std::size_t begin = open + 6;
  const std::size_t close = text.find("</name>", begin);
  if (close == std::string::npos) return std::nullopt;
  std::string name = text.substr(begin, close - begin);
  const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
  name.erase(name.begin(), std::find_if_not(name.begin(), name.end(), space));
  name.erase(std::find_if_not(name.rbegin(), name.rend(), space).base(), name.end());
  if (name.empty()) return std::nullopt;
  return name;
}

MeshLookup ResolveMeshUri(const std::string& uri, const fs::path& urdf_dir, std::span<const std::string> package_paths) {
  if (uri.starts_with(kPackageScheme)) return ResolvePackageUri(uri, urdf_dir, package_paths);
  std::string rest = uri;
  std::string form = "the file";
  if (uri.starts_with(kFileScheme)) {
    rest = uri.substr(kFileScheme.size());
    form = "the file:// path";
  } else if (const std::size_t colon = uri.find("://"); colon != std::string::npos) {
    return {std::nullopt, "unsupported URI scheme '" + uri.substr(0, colon) +
                              "://' (expected a path, file:// or package://)", ""};
  }
  if (rest.empty()) return {std::nullopt, "an empty file name", ""};
  const fs::path path(rest);
  return FileOrProblem(path.is_absolute() ? path : urdf_dir / path, form);
}

}  // namespace proxsim

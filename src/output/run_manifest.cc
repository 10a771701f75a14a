#include "output/run_manifest.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"

namespace proxsim {

namespace {

namespace fs = std::filesystem;
constexpr const char* kManifest = "manifest.json";

// The standard FNV-1a 64 offset basis, and the mistyped one manifests were
// once written with (so that a standard FNV-1a check of them failed): a
// manifest written before still proves its files (DigestMatches).
constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;
constexpr std::uint64_t kLegacyFnvOffsetBasis = 1469598103934665603ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

std::string Hex(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

// FNV-1a 64 of what `fd` reads from both bases, hex; closes fd; empty when it cannot be read
std::pair<std::string, std::string> DigestsOfFd(int fd) {
  if (fd < 0) return {};
  std::uint64_t hash = kFnvOffsetBasis, legacy = kLegacyFnvOffsetBasis;
  char buffer[65536];
  ssize_t n;
  while ((n = ::read(fd, buffer, sizeof buffer)) > 0) {
    for (ssize_t i = 0; i < n; ++i) {
      hash = (hash ^ static_cast<unsigned char>(buffer[i])) * kFnvPrime;
      legacy = (legacy ^ static_cast<unsigned char>(buffer[i])) * kFnvPrime;
    }
  }
  ::close(fd);
  if (n < 0) return {};
  return {Hex(hash), Hex(legacy)};
}

std::string Digest(const fs::path& file) {
  return DigestsOfFd(::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC)).first;
}

// whether what `fd` reads has `digest`, from either basis; closes fd
bool DigestMatches(int fd, const std::string& digest) {
  const auto [standard, legacy] = DigestsOfFd(fd);
  return !digest.empty() && (digest == standard || digest == legacy);
}

// A manifest path split into its folders and its name; empty when it could
// leave the folder ("..", ".", an absolute path, an empty part).
std::vector<std::string> SafeParts(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    const std::string part = path.substr(start, slash - start);
    if (part.empty() || part == "." || part == "..") return {};
    parts.push_back(part);
    start = slash + 1;
  }
  return parts;
}

// Removes dir/path only if it is a regular file of `bytes` bytes and `digest`,
// reached through real folders (never a link), then the folders that leaves
// empty; every step relative to a descriptor opened with O_NOFOLLOW.
void RemoveListedFile(const fs::path& dir, const ManifestFile& file) {
  const std::vector<std::string> parts = SafeParts(file.path);
  if (parts.empty() || file.digest.empty()) return;  // unsafe, or no digest to prove it ours
  std::vector<int> fds{::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  for (std::size_t i = 0; i + 1 < parts.size() && fds.back() >= 0; ++i)
    fds.push_back(::openat(fds.back(), parts[i].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
  if (fds.back() >= 0) {
    const int parent = fds.back();
    const char* name = parts.back().c_str();
    struct stat info {};
    if (::fstatat(parent, name, &info, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(info.st_mode) &&
        static_cast<std::uintmax_t>(info.st_size) == file.bytes &&
        DigestMatches(::openat(parent, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC), file.digest)) {
      ::unlinkat(parent, name, 0);
      // the folders it leaves empty (rmdir refuses a non-empty one)
      for (std::size_t i = fds.size() - 1; i >= 1; --i) {
        if (fds[i] < 0 || ::unlinkat(fds[i - 1], parts[i - 1].c_str(), AT_REMOVEDIR) != 0) break;
      }
    }
  }
  for (const int fd : fds)
    if (fd >= 0) ::close(fd);
}

// "readings/" → the files this process committed under it (a user's own files
// there are not the run's); a file → itself; missing → nothing
std::vector<ManifestFile> Expand(const fs::path& dir, const std::string& path) {
  std::vector<ManifestFile> files;
  std::error_code ec;
  const auto add = [&](const std::string& relative) {
    const fs::path full = dir / relative;
    if (fs::is_regular_file(fs::symlink_status(full, ec)))
      files.push_back({relative, fs::file_size(full, ec), Digest(full)});
  };
  if (path.ends_with('/')) {
    for (const std::string& relative : CommittedUnder(dir.string()))
      if (relative.starts_with(path)) add(relative);
  } else {
    add(fs::path(path).generic_string());
  }
  return files;
}

void Write(const fs::path& dir, RunManifest manifest) {
  std::sort(manifest.files.begin(), manifest.files.end(),
            [](const ManifestFile& a, const ManifestFile& b) { return a.path < b.path; });
  manifest.files.erase(std::unique(manifest.files.begin(), manifest.files.end(),
                                   [](const ManifestFile& a, const ManifestFile& b) { return a.path == b.path; }),
                       manifest.files.end());
  nlohmann::json files = nlohmann::json::array();
  for (const ManifestFile& f : manifest.files)
    files.push_back({{"path", f.path}, {"bytes", f.bytes}, {"fnv1a64", f.digest}});
  const nlohmann::json json = {{"proxsim_run_manifest", 1},
                               {"about", "the files one proxsim run wrote here; the next run into this folder "
                                         "removes exactly these, when they are still these bytes"},
                               {"summary_fnv1a64", manifest.summary_digest},
                               {"files", files}};
  WriteFileAtomically((dir / kManifest).string(), json.dump(2) + "\n");
}

}  // namespace

const std::vector<std::string>& RunOutputNames() {
  static const std::vector<std::string> names = {"readings.csv", "readings", "profile.ply", "poses.csv",
                                                  "joints.csv",   "scene.json",   "summary.json", "timings.json", "terrain",
                                                  "report"};
  return names;
}

const std::vector<std::string>& RunFileNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = RunOutputNames();
    all.insert(all.end(), {"columns.json", "zones", "echoes", "objects_poses.csv", "manifest.json", ".proxsim.lock"});
    return all;
  }();
  return names;
}

std::optional<RunManifest> ReadRunManifest(const std::string& dir) {
  std::ifstream in(fs::path(dir) / kManifest);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
  if (json.is_discarded() || !json.is_object() || !json.contains("files") || !json["files"].is_array())
    return std::nullopt;
  RunManifest manifest;
  if (json.contains("summary_fnv1a64") && json["summary_fnv1a64"].is_string())
    manifest.summary_digest = json["summary_fnv1a64"];
  for (const auto& f : json["files"]) {
    if (!f.is_object() || !f.contains("path") || !f["path"].is_string()) continue;
    const std::string path = f["path"];
    // never outside the folder, whatever the file says
    if (SafeParts(path).empty()) continue;
    const auto bytes = f.find("bytes");
    const auto digest = f.find("fnv1a64");
    manifest.files.push_back({path, bytes != f.end() && bytes->is_number_unsigned() ? bytes->get<std::uintmax_t>() : 0,
                              digest != f.end() && digest->is_string() ? digest->get<std::string>() : ""});
  }
  return manifest;
}

void RemovePreviousRun(const std::string& dir) {
  const auto manifest = ReadRunManifest(dir);
  if (!manifest) return;
  for (const ManifestFile& f : manifest->files) RemoveListedFile(dir, f);
  // the manifest itself, when it is a regular file (never a link's target)
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  struct stat info {};
  if (fd >= 0 && ::fstatat(fd, kManifest, &info, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(info.st_mode))
    ::unlinkat(fd, kManifest, 0);
  if (fd >= 0) ::close(fd);
}

void WriteRunManifest(const std::string& dir, const std::vector<std::string>& paths) {
  RunManifest manifest;
  for (const std::string& path : paths) {
    const auto files = Expand(dir, path);
    manifest.files.insert(manifest.files.end(), files.begin(), files.end());
  }
  manifest.summary_digest = Digest(fs::path(dir) / "summary.json");
  Write(dir, manifest);
}

void AddToRunManifest(const std::string& dir, const std::vector<std::string>& paths) {
  RunManifest manifest = ReadRunManifest(dir).value_or(RunManifest{});
  for (const std::string& path : paths) {
    std::erase_if(manifest.files, [&](const ManifestFile& f) { return f.path == path; });
    const auto files = Expand(dir, path);
    manifest.files.insert(manifest.files.end(), files.begin(), files.end());
  }
  Write(dir, manifest);
}

void RemoveFromRunManifest(const std::string& dir, const std::string& subdir) {
  auto manifest = ReadRunManifest(dir);
  if (!manifest) return;
  std::erase_if(manifest->files, [&](const ManifestFile& f) {
    if (!f.path.starts_with(subdir)) return false;
    RemoveListedFile(dir, f);
    return true;
  });
  Write(dir, *manifest);
}

std::vector<std::string> RunFolderProblems(const std::string& dir) {
  std::vector<std::string> problems;
  const auto manifest = ReadRunManifest(dir);
  std::error_code exists_error;
  if (!manifest && fs::exists(fs::path(dir) / kManifest, exists_error)) {
    // there but unreadable: the files cannot be checked against it
    problems.push_back(std::string(kManifest) + ": not a manifest proxsim wrote (not JSON with a \"files\" list)");
  }
  if (!manifest) return problems;
  const fs::path root(dir);
  std::error_code ec;
  std::set<std::string> listed_tops;
  for (const ManifestFile& f : manifest->files) {
    listed_tops.insert(fs::path(f.path).begin()->string());
    if (f.path.starts_with("report/")) continue;  // drawn from the rest: plot replaces them
    const fs::path full = root / f.path;
    if (!fs::is_regular_file(full, ec)) {
      problems.push_back(f.path + ": listed in manifest.json but missing");
    } else if (fs::file_size(full, ec) != f.bytes) {
      problems.push_back(f.path + ": " + std::to_string(fs::file_size(full, ec)) + " bytes, manifest.json says " +
                         std::to_string(f.bytes) + " (rewritten by another run?)");
    }
  }
  if (!manifest->summary_digest.empty() &&
      !DigestMatches(::open((root / "summary.json").c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC), manifest->summary_digest)) {
    problems.push_back("summary.json: not the summary of the run manifest.json describes (rewritten by another run?)");
  }
  for (const std::string& name : RunOutputNames()) {
    if (name == "report") continue;  // plot replaces it
    if (fs::exists(root / name, ec) && !listed_tops.contains(name)) {
      problems.push_back(name + ": a run output that is not this run's (left by another run?)");
    }
  }
  return problems;
}

}  // namespace proxsim

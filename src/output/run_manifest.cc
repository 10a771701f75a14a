#include "output/run_manifest.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"

namespace proxsim {

namespace {

namespace fs = std::filesystem;
constexpr const char* kManifest = "manifest.json";

std::string Digest(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a 64
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ull;
    }
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

// "readings/" → every file under it; a file → itself; missing → nothing
std::vector<ManifestFile> Expand(const fs::path& dir, const std::string& path) {
  std::vector<ManifestFile> files;
  std::error_code ec;
  const fs::path full = dir / path;
  if (fs::is_directory(full, ec)) {
    for (const auto& entry : fs::recursive_directory_iterator(full, ec)) {
      if (entry.is_regular_file(ec)) {
        files.push_back({fs::relative(entry.path(), dir, ec).generic_string(), entry.file_size(ec)});
      }
    }
  } else if (fs::is_regular_file(full, ec)) {
    files.push_back({fs::path(path).generic_string(), fs::file_size(full, ec)});
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
  for (const ManifestFile& f : manifest.files) files.push_back({{"path", f.path}, {"bytes", f.bytes}});
  const nlohmann::json json = {{"proxsim_run_manifest", 1},
                               {"about", "the files one proxsim run wrote here; the next run into this folder "
                                         "removes exactly these"},
                               {"summary_fnv1a64", manifest.summary_digest},
                               {"files", files}};
  WriteFileAtomically((dir / kManifest).string(), json.dump(2) + "\n");
}

// removes dir/path's parents up to dir while they are empty
void RemoveEmptyParents(const fs::path& dir, fs::path path) {
  std::error_code ec;
  for (path = path.parent_path(); !path.empty() && path != "." && path != dir; path = path.parent_path()) {
    if (!fs::is_directory(dir / path, ec) || !fs::is_empty(dir / path, ec)) break;
    fs::remove(dir / path, ec);
  }
}

}  // namespace

const std::vector<std::string>& RunOutputNames() {
  static const std::vector<std::string> names = {"readings.csv", "readings", "profile.ply", "poses.csv",
                                                  "scene.json",   "summary.json", "timings.json", "terrain",
                                                  "report"};
  return names;
}

std::optional<RunManifest> ReadRunManifest(const std::string& dir) {
  std::ifstream in(fs::path(dir) / kManifest);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
  if (json.is_discarded() || !json.contains("files")) return std::nullopt;
  RunManifest manifest;
  manifest.summary_digest = json.value("summary_fnv1a64", "");
  for (const auto& f : json["files"]) {
    if (!f.contains("path") || !f["path"].is_string()) continue;
    const std::string path = f["path"];
    // never outside the folder, whatever the file says
    if (path.empty() || path.front() == '/' || fs::path(path).lexically_normal().string().starts_with("..")) continue;
    manifest.files.push_back({path, f.value("bytes", std::uintmax_t{0})});
  }
  return manifest;
}

void RemovePreviousRun(const std::string& dir) {
  const auto manifest = ReadRunManifest(dir);
  if (!manifest) return;
  std::error_code ec;
  for (const ManifestFile& f : manifest->files) {
    fs::remove(fs::path(dir) / f.path, ec);
    RemoveEmptyParents(dir, f.path);
  }
  fs::remove(fs::path(dir) / kManifest, ec);
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
  std::error_code ec;
  std::erase_if(manifest->files, [&](const ManifestFile& f) {
    if (!f.path.starts_with(subdir)) return false;
    fs::remove(fs::path(dir) / f.path, ec);
    RemoveEmptyParents(dir, f.path);
    return true;
  });
  Write(dir, *manifest);
}

std::vector<std::string> RunFolderProblems(const std::string& dir) {
  std::vector<std::string> problems;
  const auto manifest = ReadRunManifest(dir);
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
  if (!manifest->summary_digest.empty() && Digest(root / "summary.json") != manifest->summary_digest) {
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

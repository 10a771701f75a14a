#include "scene/mesh_prescan.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "core/input_limits.h"
#include "core/nesting_scan.h"

namespace proxsim {

namespace {

using nlohmann::json;

std::string ReadWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The first byte that is not a byte order mark or white space, however far in
// (a glTF behind megabytes of spaces is still JSON to Assimp); 0 when none.
char FirstSignificantByte(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char chunk[65536];
  bool first = true;
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    std::string_view text(chunk, static_cast<std::size_t>(in.gcount()));
    if (first && text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    first = false;
    for (const char c : text)
      if (!std::isspace(static_cast<unsigned char>(c))) return c;
  }
  return 0;
}

// The first bytes only: enough to tell the format (a large OBJ is not read twice)
std::string ReadHead(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

std::string_view TrimStart(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  return text;
}

std::uint32_t LittleEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
  return value;
}

// An unsigned count at `key` of `object`, or `fallback` when absent; refuses anything else.
std::uint64_t CountAt(const json& object, const char* key, std::uint64_t fallback, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned()) throw InputError(where + "." + key + ": expected a count >= 0, got " + it->dump());
  return it->get<std::uint64_t>();
}

// glTF: the node tree's depth from every root, without recursion; a cycle or a
// node with two parents is refused (Assimp would recurse for ever or twice).
void CheckGltfNodes(const json& gltf, const std::string& path) {
  const auto nodes = gltf.find("nodes");
  if (nodes == gltf.end()) return;
  if (!nodes->is_array()) throw InputError(path + ": glTF 'nodes' is not an array");
  const std::size_t n = nodes->size();
  std::vector<std::vector<std::size_t>> children(n);
  std::vector<int> parents(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const json& node = (*nodes)[i];
    if (!node.is_object()) throw InputError(path + ": glTF node " + std::to_string(i) + " is not an object");
    const auto list = node.find("children");
    if (list == node.end()) continue;
    if (!list->is_array()) throw InputError(path + ": glTF node " + std::to_string(i) + ": 'children' is not an array");
    for (const json& c : *list) {
      if (!c.is_number_unsigned() || c.get<std::uint64_t>() >= n)
        throw InputError(path + ": glTF node " + std::to_string(i) + " names a missing child " + c.dump());
      const auto child = c.get<std::size_t>();
      if (++parents[child] > 1 || child == i)
        throw InputError(path + ": glTF node " + std::to_string(child) + " has two parents or is its own (not a tree)");
      children[i].push_back(child);
    }
  }
  std::vector<std::pair<std::size_t, int>> stack;  // (node, depth)
  std::size_t reached = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (parents[i] == 0) stack.emplace_back(i, 1);
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    ++reached;
    if (depth > kMaxNestingDepth) {
      throw InputError(path + ": glTF node tree deeper than " + std::to_string(kMaxNestingDepth) +
                       " levels (limit, docs/trust.md)");
    }
    for (const std::size_t c : children[node]) stack.emplace_back(c, depth + 1);
  }
  if (reached != n) throw InputError(path + ": glTF nodes form a cycle (not a tree)");
}

// glTF: every buffer, view and accessor within the bytes that exist.
// `glb_bin_bytes`: the GLB's BIN chunk, the buffer without a uri.
void CheckGltfSizes(const json& gltf, const std::string& path, std::uint64_t glb_bin_bytes) {
  std::vector<std::uint64_t> buffer_bytes, view_bytes;
  const json empty = json::array();
  const auto array = [&](const char* key) -> const json& {
    const auto it = gltf.find(key);
    if (it == gltf.end()) return empty;
    if (!it->is_array()) throw InputError(path + ": glTF '" + key + "' is not an array");
    if (it->size() > kMaxDeclaredElements) throw InputError(path + ": glTF '" + key + "': too many entries");
    return *it;
  };
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const json& buffer : array("buffers")) {
    const std::string where = path + ": glTF buffers[" + std::to_string(buffer_bytes.size()) + "]";
    if (!buffer.is_object()) throw InputError(where + ": not an object");
    const std::uint64_t declared = CountAt(buffer, "byteLength", 0, where);
    if (declared > kMaxMeshFileBytes)
      throw InputError(where + ": byteLength " + std::to_string(declared) + " beyond the limit of " +
                       std::to_string(kMaxMeshFileBytes) + " bytes");
    std::uint64_t available = glb_bin_bytes;
    if (const auto uri = buffer.find("uri"); uri != buffer.end()) {
      if (!uri->is_string()) throw InputError(where + ": uri is not a string");
      const std::string text = *uri;
      if (text.starts_with("data:")) {
        const auto comma = text.find(',');
        available = comma == std::string::npos ? 0 : (text.size() - comma - 1) * 3 / 4;
      } else {
        const std::string file = (folder / text).string();
        const std::string problem = RegularFileProblem(file, kMaxMeshFileBytes);
        if (!problem.empty()) throw InputError(where + ": " + problem);
        available = std::filesystem::file_size(file);
      }
    }
    if (declared > available)
      throw InputError(where + ": byteLength " + std::to_string(declared) + " but only " + std::to_string(available) +
                       " bytes are there");
    buffer_bytes.push_back(declared);
  }
  for (const json& view : array("bufferViews")) {
    const std::string where = path + ": glTF bufferViews[" + std::to_string(view_bytes.size()) + "]";
    if (!view.is_object()) throw InputError(where + ": not an object");
    const std::uint64_t buffer = CountAt(view, "buffer", buffer_bytes.size(), where);
    const std::uint64_t offset = CountAt(view, "byteOffset", 0, where), length = CountAt(view, "byteLength", 0, where);
    if (buffer >= buffer_bytes.size() || offset > buffer_bytes[buffer] || length > buffer_bytes[buffer] - offset)
      throw InputError(where + ": beyond the bytes of its buffer");
    view_bytes.push_back(length);
  }
  static const std::map<std::uint64_t, std::uint64_t> kComponentBytes = {
      {5120, 1}, {5121, 1}, {5122, 2}, {5123, 2}, {5125, 4}, {5126, 4}};
  static const std::map<std::string, std::uint64_t> kComponents = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                                   {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
  std::size_t index = 0;
  for (const json& accessor : array("accessors")) {
    const std::string where = path + ": glTF accessors[" + std::to_string(index++) + "]";
    if (!accessor.is_object()) throw InputError(where + ": not an object");
    const std::uint64_t count = CountAt(accessor, "count", 0, where);
    if (count > kMaxDeclaredElements)
      throw InputError(where + ": count " + std::to_string(count) + " beyond the limit of " +
                       std::to_string(kMaxDeclaredElements));
    if (!accessor.contains("bufferView")) continue;  // zeros (or sparse): nothing read
    const std::uint64_t view = CountAt(accessor, "bufferView", 0, where);
    const auto component = kComponentBytes.find(CountAt(accessor, "componentType", 5126, where));
    const auto type = accessor.contains("type") && accessor["type"].is_string()
                          ? kComponents.find(accessor["type"].get<std::string>())
                          : kComponents.end();
    if (view >= view_bytes.size() || component == kComponentBytes.end() || type == kComponents.end())
      throw InputError(where + ": names a missing buffer view, or an unknown componentType or type");
    const std::uint64_t element = component->second * type->second;
    const std::uint64_t stride = std::max(element, CountAt((*gltf.find("bufferViews"))[view], "byteStride", 0, where));
    const std::uint64_t offset = CountAt(accessor, "byteOffset", 0, where);
    if (count > 0 && (offset > view_bytes[view] || (count - 1) * stride + element > view_bytes[view] - offset))
      throw InputError(where + ": " + std::to_string(count) + " elements do not fit in buffer view " +
                       std::to_string(view) + " (" + std::to_string(view_bytes[view]) + " bytes)");
  }
}

void CheckGltfJson(std::string_view text, const std::string& path, std::uint64_t glb_bin_bytes) {
  if (const auto problem = NestingProblem(ScanJsonNesting(text, kMaxNestingDepth), path, "JSON", kMaxNestingDepth))
    throw InputError(*problem);
  const json gltf = json::parse(text, nullptr, false);
  if (gltf.is_discarded() || !gltf.is_object()) return;  // not glTF JSON: Assimp decides (and refuses)
  CheckGltfNodes(gltf, path);
  CheckGltfSizes(gltf, path, glb_bin_bytes);
}

// GLB: a 12-byte header, then chunks (length, type, bytes): JSON first, BIN maybe
void CheckGlb(std::string_view bytes, const std::string& path) {
  if (bytes.size() < 20) throw InputError(path + ": GLB file shorter than its header");
  const std::uint32_t json_bytes = LittleEndian32(bytes, 12);
  if (json_bytes > bytes.size() - 20) throw InputError(path + ": GLB JSON chunk longer than the file");
  std::uint64_t bin_bytes = 0;
  const std::size_t bin_at = 20 + json_bytes;
  if (bytes.size() >= bin_at + 8) {
    bin_bytes = LittleEndian32(bytes, bin_at);
    if (bin_bytes > bytes.size() - bin_at - 8) throw InputError(path + ": GLB BIN chunk longer than the file");
  }
  CheckGltfJson(bytes.substr(20, json_bytes), path, bin_bytes);
}

// OFF: "[ST][C][N][4][n]OFF", then "vertices faces edges"; each vertex takes at
// least 6 bytes ("0 0 0\n"), each face 8 ("3 0 1 2\n")
void CheckOff(std::string_view text, std::uintmax_t file_bytes, const std::string& path) {
  std::istringstream words{std::string(text.substr(0, 4096))};
  std::string magic;
  words >> magic;
  if (magic.size() < 3 || magic.substr(magic.size() - 3) != "OFF") return;
  std::string line;
  std::getline(words, line);
  std::string counts_line;
  while (std::getline(words, counts_line)) {
    const auto first = counts_line.find_first_not_of(" \t\r");
    if (first != std::string::npos && counts_line[first] != '#') break;
  }
  std::istringstream counts(counts_line);
  double vertices = 0, faces = 0;
  counts >> vertices >> faces;
  const double room = static_cast<double>(file_bytes);
  if (!(vertices >= 0) || !(faces >= 0) || vertices > kMaxDeclaredElements || faces > kMaxDeclaredElements ||
      vertices * 6 + faces * 8 > room) {
    throw InputError(path + ": OFF header declares " + counts_line + " (vertices faces) but the file holds " +
                     std::to_string(file_bytes) + " bytes (at least 6 per vertex and 8 per face; limit " +
                     std::to_string(kMaxDeclaredElements) + " of each)");
  }
}

}  // namespace

void PrescanMeshFile(const std::string& path) {
  if (const std::string problem = RegularFileProblem(path, kMaxMeshFileBytes); !problem.empty())
    throw InputError(problem);
  // by content, not by extension: Assimp also picks its reader by content
  const std::string head = ReadHead(path, 4096);
  const std::string_view start = TrimStart(head);
  if (head.starts_with("glTF")) return CheckGlb(ReadWhole(path), path);
  const char first = FirstSignificantByte(path);
  if (first == '{') {
    const std::string bytes = ReadWhole(path);
    return CheckGltfJson(TrimStart(bytes), path, 0);
  }
  if (first == '<') {
    const std::string bytes = ReadWhole(path);
    if (const auto problem = NestingProblem(ScanXmlNesting(bytes, kMaxNestingDepth), path, "XML elements", kMaxNestingDepth))
      throw InputError(*problem);
    return;
  }
  CheckOff(start, std::filesystem::file_size(path), path);
}

bool MeshIOSystem::Exists(const char* path) const { return RegularFileProblem(path, kMaxMeshFileBytes).empty(); }

Assimp::IOStream* MeshIOSystem::Open(const char* path, const char* mode) {
  // only reading, only regular files of bounded size
  if (std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr) {
    refusal_ = std::string(path) + ": Assimp asked to write it; mesh files are only read";
    return nullptr;
  }
  if (std::string problem = RegularFileProblem(path, kMaxMeshFileBytes); !problem.empty()) {
    refusal_ = std::move(problem);
    return nullptr;
  }
  return DefaultIOSystem::Open(path, mode);
}

}  // namespace proxsim

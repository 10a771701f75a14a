#include "output/npy_files.h"

#include <algorithm>

namespace proxsim {

std::string NpyFolderFor(const std::string& name, std::size_t index) {
  const bool plain = !name.empty() && name != "." && name != ".." &&
                     std::all_of(name.begin(), name.end(), [](char c) {
                       return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                              c == '-' || c == '.';
                     });
  return plain ? name : "sensor_" + std::to_string(index);
}

std::string NpyArrayHeader(const char* descr, const std::vector<std::int64_t>& shape) {
  std::string dims;
  for (const std::int64_t n : shape) dims += std::to_string(n) + ",";
  if (shape.size() > 1) dims.pop_back();  // (n,) for one dimension, (a,b,c) for more
  std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" + dims + "), }";
  // magic 6 + version 2 + length 2 + dict + '\n', padded to a multiple of 64
  const std::size_t total = (10 + dict.size() + 1 + 63) / 64 * 64;
  const std::size_t length = total - 10;
  dict.resize(length - 1, ' ');
  std::string header = "\x93NUMPY";
  header += '\x01';
  header += '\x00';
  header += static_cast<char>(length & 0xFF);
  header += static_cast<char>(length >> 8);
  header += dict;
  header += '\n';
  return header;
}

}  // namespace proxsim

#include "output/npy_files.h"

#include <sys/stat.h>

#include <stdexcept>

namespace proxsim {

void RefuseLinkedFolders(const std::string& dir, const std::vector<std::string>& folders) {
  std::vector<std::string> paths{dir};
  for (const std::string& folder : folders) paths.push_back(dir + "/" + folder);
  for (const std::string& path : paths) {
    struct stat info {};
    if (::lstat(path.c_str(), &info) != 0) continue;  // made by the run itself
    if (!S_ISDIR(info.st_mode)) {
      throw std::runtime_error("cannot write " + path + ": it is a symbolic link or not a folder; proxsim never "
                               "writes through a link (remove it, or give another --out)");
    }
  }
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

// Reading back the .npy arrays a run writes (zones/, echoes/) in the tests.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.h"

namespace proxsim::testing {

// An .npy array's shape and values (float64 or uint8, C order), read back.
struct NpyArray {
  std::vector<long> shape;
  std::vector<double> values;
};

inline NpyArray LoadNpy(const std::filesystem::path& path) {
  const std::string bytes = ReadFile(path);
  NpyArray array;
  EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
  const std::size_t header_length =
      static_cast<unsigned char>(bytes[8]) | (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
  const std::string header = bytes.substr(10, header_length);
  EXPECT_EQ((10 + header_length) % 64, 0u) << "the header is padded to 64 bytes";
  const bool f8 = header.find("'<f8'") != std::string::npos;
  const std::size_t open = header.find("'shape': (") + 10, close = header.find(')', open);
  std::stringstream dims(header.substr(open, close - open));
  std::string dim;
  long count = 1;
  while (std::getline(dims, dim, ',')) {
    if (dim.find_first_not_of(' ') == std::string::npos) continue;
    array.shape.push_back(std::stol(dim));
    count *= array.shape.back();
  }
  const char* data = bytes.data() + 10 + header_length;
  EXPECT_EQ(bytes.size() - 10 - header_length, static_cast<std::size_t>(count) * (f8 ? 8 : 1)) << path;
  for (long i = 0; i < count; ++i) {
    if (f8) {
      double value;
      std::memcpy(&value, data + 8 * i, 8);
      array.values.push_back(value);
    } else {
      array.values.push_back(static_cast<unsigned char>(data[i]));
    }
  }
  return array;
}

}  // namespace proxsim::testing

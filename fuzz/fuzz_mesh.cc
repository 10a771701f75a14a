// libFuzzer target: the mesh loader (LoadMeshFile, Assimp inside). Assimp
// picks the format from the file extension, so the first byte of the input
// chooses one and the rest is written to a temporary file of that name.
// Any input must either load or throw InputError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "scene/mesh_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kExtensions[] = {"obj", "stl", "ply", "gltf", "dae", "off", "glb"};
  constexpr std::size_t kCount = sizeof(kExtensions) / sizeof(kExtensions[0]);
  if (size == 0) return 0;
  const std::string path = "/tmp/proxsim-fuzz-mesh-" + std::to_string(getpid()) + "." + kExtensions[data[0] % kCount];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    proxsim::LoadMeshFile(path, proxsim::Vec3(1, 1, 1));
  } catch (const proxsim::InputError&) {
  }
  unlink(path.c_str());
  return 0;
}

#include "raycast/embree_version.h"

#include <cstdlib>

#include <embree3/rtcore_config.h>

namespace proxsim {

std::string EmbreeVersion() { return RTC_VERSION_STRING; }

std::string EmbreeDeviceConfig() {
  const char* config = std::getenv(kEmbreeConfigVariable);
  return config ? config : "";
}

}  // namespace proxsim

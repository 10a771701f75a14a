#include "raycast/embree_version.h"

#include <embree3/rtcore_config.h>

namespace proxsim {

std::string EmbreeVersion() { return RTC_VERSION_STRING; }

}  // namespace proxsim

#include "sim/sample_frame.h"

namespace proxsim {

const char* SupportLegName(SupportLeg leg) {
  switch (leg) {
    case SupportLeg::kNone: return "";
    case SupportLeg::kLeft: return "left";
    case SupportLeg::kRight: return "right";
    case SupportLeg::kDouble: return "double";
  }
  return "";
}

}  // namespace proxsim

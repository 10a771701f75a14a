#include "scene/shape.h"

namespace proxsim {

const char* ShapeKindName(const Shape& shape) {
  static constexpr const char* kNames[] = {"box", "sphere", "cylinder", "plane", "mesh"};
  return kNames[shape.index()];
}

}  // namespace proxsim

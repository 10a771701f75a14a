#include "sensors/echo.h"

namespace proxsim {

Echo EchoOfHit(double distance_m, const Vec3& dir_W, const Vec3& normal_W) {
  Echo echo;
  echo.distance_m = distance_m;
  echo.incidence_deg = IncidenceDeg(dir_W.x(), dir_W.y(), dir_W.z(), normal_W.x(), normal_W.y(), normal_W.z());
  return echo;
}

}  // namespace proxsim

#include "sensors/echo_groups.h"

#include <algorithm>

namespace proxsim {

void SplitEchoes(std::vector<RangedRay>& rays, double separation_m, int max_groups, std::vector<EchoGroup>& groups) {
  groups.clear();
  std::sort(rays.begin(), rays.end(), [](const RangedRay& a, const RangedRay& b) {
    return a.d_m < b.d_m || (a.d_m == b.d_m && a.ray < b.ray);
  });
  std::size_t begin = 0;
  while (begin < rays.size() && static_cast<int>(groups.size()) < max_groups) {
    std::size_t end = begin + 1;
    while (end < rays.size() && rays[end].d_m - rays[end - 1].d_m < separation_m) ++end;
    groups.push_back({begin, end});
    begin = end;
  }
}

}  // namespace proxsim

#include "sensors/echo_groups.h"

#include <algorithm>
#include <cmath>

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

void ResolveTargets(std::vector<RangedRay>& rays, double separation_m, int max_targets,
                    std::vector<ResolvedTarget>& targets) {
  thread_local std::vector<EchoGroup> groups;
  SplitEchoes(rays, separation_m, max_targets, groups);
  targets.clear();
  for (const EchoGroup& group : groups) {
    // the centre of the returns, each weighed by its signal (the histogram's
    // peak leans to the nearer, brighter surface); the plain mean when no
    // return carries signal, or of those whose signal is unbounded (a
    // surface at the emitter, d = 0)
    double sum_m = 0.0, sum_weighted_m = 0.0, sum_weight = 0.0, unbounded_m = 0.0;
    int unbounded = 0;
    for (std::size_t k = group.begin; k < group.end; ++k) {
      sum_m += rays[k].d_m;
      if (std::isinf(rays[k].signal)) {
        unbounded_m += rays[k].d_m;
        ++unbounded;
        continue;
      }
      sum_weighted_m += rays[k].signal * rays[k].d_m;
      sum_weight += rays[k].signal;
    }
    const double centre_m = unbounded > 0    ? unbounded_m / unbounded
                            : sum_weight > 0 ? sum_weighted_m / sum_weight
                                             : sum_m / static_cast<double>(group.end - group.begin);
    targets.push_back({group, centre_m});
  }
}

}  // namespace proxsim

#include "gait/locomotion.h"

#include <array>
#include <utility>

namespace proxsim {

namespace {
// in code order: a support leg's code in the output files is its index here
constexpr std::array<std::pair<SupportLeg, const char*>, 3> kSupportLegNames = {{
    {SupportLeg::kLeft, "left"},
    {SupportLeg::kRight, "right"},
    {SupportLeg::kDouble, "double"},
}};
static_assert([] {
  for (std::size_t i = 0; i < kSupportLegNames.size(); ++i)
    if (static_cast<std::size_t>(kSupportLegNames[i].first) != i) return false;
  return true;
}());
}  // namespace

const char* SupportLegName(SupportLeg s) { return kSupportLegNames[static_cast<std::size_t>(s)].second; }

const std::vector<std::string>& SupportLegNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const auto& [leg, name] : kSupportLegNames) all.emplace_back(name);
    return all;
  }();
  return names;
}

}  // namespace proxsim

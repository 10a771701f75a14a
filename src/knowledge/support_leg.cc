#include "knowledge/support_leg.h"

#include "core/enum_names.h"

namespace proxsim {

namespace {
constexpr EnumNameTable<SupportLeg, 3> kSupportLegNames = {{
    {SupportLeg::kLeft, "left"},
    {SupportLeg::kRight, "right"},
    {SupportLeg::kDouble, "double"},
}};
static_assert(InCodeOrder(kSupportLegNames));
}  // namespace

const char* SupportLegName(SupportLeg s) { return NameIn(kSupportLegNames, s); }

const std::vector<std::string>& SupportLegNames() {
  static const std::vector<std::string> names = NamesIn(kSupportLegNames);
  return names;
}

}  // namespace proxsim

// What a datasheet part costs and weighs, for the outcome studies' answers
// (the cheapest set that reaches a success rate; docs/studies.md). One row per
// part of SensorSpec::PartPreset, with where the figures come from
// (docs/sensors.md "Price and mass"). The paper's models (laser, ultrasonic,
// reflectance, ideal) are not parts and have none: a study gives them one.
#pragma once

#include <optional>
#include <string_view>

namespace proxsim {

struct PartPrice {
  double price_usd = 0;  ///< one unit, on a breakout board where the part is sold so
  double mass_g = 0;     ///< the same unit
};

/// The catalogue's price and mass of a part ("hc_sr04", "vl53l0x", ...), or nullopt.
std::optional<PartPrice> PartPriceOf(std::string_view part);

}  // namespace proxsim

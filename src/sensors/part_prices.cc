#include "sensors/part_prices.h"

namespace proxsim {

namespace {

struct Row {
  std::string_view part;
  PartPrice price;
};

// Approximate list prices of one unit on the usual hobby breakout boards, and
// their masses; the sources and their dates are in docs/sensors.md ("Price and
// mass"). A study overrides any of them (`prices:` in the study file).
constexpr Row kRows[] = {
    {"hc_sr04", {3.95, 8.5}},
    {"sharp_gp2y0a21", {12.95, 3.5}},
    {"vl53l0x", {14.95, 1.0}},
    {"vl53l1x", {14.95, 1.0}},
    // no distributor price was found for a VL53L4CX board: taken as the VL53L1X
    // board's (an estimate, docs/sensors.md says so)
    {"vl53l4cx", {14.95, 1.0}},
    {"vl53l5cx", {24.95, 1.5}},
    {"vl53l7cx", {24.95, 1.5}},
    {"vl53l8cx", {24.95, 1.5}},
};

}  // namespace

std::optional<PartPrice> PartPriceOf(std::string_view part) {
  for (const Row& row : kRows)
    if (row.part == part) return row.price;
  return std::nullopt;
}

}  // namespace proxsim

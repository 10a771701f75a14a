// An outcome study's strategies (docs/studies.md "Each set at its best
// settings"): the `strategies:` list, each a scenario's `robot.strategy` map
// or `none`, and the `tune:` map that makes variants of them —
//
//   strategies: [{name: stop, perception: map}, {name: circumvent}]
//   tune: {stop.min_height_m: [0.03, 0.05, 0.08], circumvent.margin_m: [0.1, 0.2]}
//
// gives stop[min_height_m=0.03], stop[min_height_m=0.05], … (group `stop`)
// and circumvent[margin_m=0.1], circumvent[margin_m=0.2] (group
// `circumvent`). Every set runs every variant on the training seeds; its
// best variant of each group is the one its answer reports, on the test
// seeds (outcome_answers.cc). A name given twice is told apart by its
// parameters (stop[min_height_m=0.03]), never by a number.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scenario/yaml_reader.h"
#include "study/outcome_config.h"

namespace proxsim {

/// At most this many variants of all strategies together (each runs in every world with every set).
inline constexpr std::size_t kMaxStrategyVariants = 1000;

/// Reads `strategies` (absent: one `{name: stop}`) and `tune` (absent: nothing
/// tuned) into the study's strategy variants, groups in the order given, each
/// group's variants in the order of the tuned values (the first key's slowest).
/// Problems go to `reader`.
std::vector<StrategyChoice> ReadOutcomeStrategies(YamlReader& reader, const Field& strategies, const Field& tune);

/// A YAML node as one line of flow-style text (sets and strategies are small).
std::string FlowText(const YAML::Node& node);

}  // namespace proxsim

// The built-in strategy a scenario names (`robot.strategy`), as a free function.
#pragma once

#include <memory>

#include "strategy/strategy.h"
#include "strategy/strategy_config.h"

namespace proxsim {

std::unique_ptr<Strategy> MakeStrategy(const StrategyConfig& config);

}  // namespace proxsim

#include "strategy/make_strategy.h"

#include "strategy/circumvent_strategy.h"
#include "strategy/stop_strategy.h"

namespace proxsim {

std::unique_ptr<Strategy> MakeStrategy(const StrategyConfig& config) {
  if (const auto* stop = std::get_if<StopConfig>(&config)) return std::make_unique<StopStrategy>(*stop);
  return std::make_unique<CircumventStrategy>(std::get<CircumventConfig>(config));
}

}  // namespace proxsim

#include "scenario/config.hpp"

#include <cmath>

namespace entourage {

std::uint64_t ScenarioConfig::steps() const {
  return static_cast<std::uint64_t>(std::llround(duration_s / step_s));
}

}  // namespace entourage

#pragma once
// The one place that maps model names (as written in scenarios) to models.

#include <optional>
#include <string_view>
#include <vector>

#include "behaviour/car_following.hpp"

namespace entourage {

enum class LaneChangeModel : std::uint8_t {
  kNone = 0,   // never changes lane
  kMobil = 1,  // Kesting et al. 2007
  kOvertaking = 2,  // two-lane roads: passes in the oncoming lane (behaviour/overtaking.hpp)
};

struct ModelInfo {
  std::string_view name;
  std::string_view kind;  // "car_following", "lane_change" or "wrapper"
  std::string_view description;
};

std::optional<CarFollowingModel> car_following_model_by_name(std::string_view name);
std::optional<LaneChangeModel> lane_change_model_by_name(std::string_view name);
std::string_view name_of(CarFollowingModel m);
std::string_view name_of(LaneChangeModel m);
const std::vector<ModelInfo>& all_models();

}  // namespace entourage

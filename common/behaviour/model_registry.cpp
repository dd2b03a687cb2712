#include "behaviour/model_registry.hpp"

namespace entourage {

namespace {
struct CfEntry {
  CarFollowingModel model;
  ModelInfo info;
};
struct LcEntry {
  LaneChangeModel model;
  ModelInfo info;
};

const std::vector<CfEntry>& cf_entries() {
  static const std::vector<CfEntry> entries{
      {CarFollowingModel::kIdm, {"idm", "car_following", "Intelligent Driver Model (Treiber et al. 2000)"}},
      {CarFollowingModel::kModifiedIdm,
       {"modified_idm", "car_following", "IDM without interaction beyond beta s* (paper V of the thesis)"}},
      {CarFollowingModel::kGipps, {"gipps", "car_following", "Gipps' safe-speed model (Gipps 1981)"}},
  };
  return entries;
}

const std::vector<LcEntry>& lc_entries() {
  static const std::vector<LcEntry> entries{
      {LaneChangeModel::kNone, {"none", "lane_change", "never changes lane"}},
      {LaneChangeModel::kMobil, {"mobil", "lane_change", "MOBIL with a right-lane bias (Kesting et al. 2007)"}},
      {LaneChangeModel::kOvertaking,
       {"overtaking", "lane_change",
        "overtaking in the oncoming lane of a two-lane road (VTISim, Brodin & Carlsson 1986; paper I/II)"}},
  };
  return entries;
}
}  // namespace

std::optional<CarFollowingModel> car_following_model_by_name(std::string_view name) {
  for (const auto& e : cf_entries()) {
    if (e.info.name == name) return e.model;
  }
  return std::nullopt;
}

std::optional<LaneChangeModel> lane_change_model_by_name(std::string_view name) {
  for (const auto& e : lc_entries()) {
    if (e.info.name == name) return e.model;
  }
  return std::nullopt;
}

std::string_view name_of(CarFollowingModel m) {
  for (const auto& e : cf_entries()) {
    if (e.model == m) return e.info.name;
  }
  return "unknown";
}

std::string_view name_of(LaneChangeModel m) {
  for (const auto& e : lc_entries()) {
    if (e.model == m) return e.info.name;
  }
  return "unknown";
}

const std::vector<ModelInfo>& all_models() {
  static const std::vector<ModelInfo> all = [] {
    std::vector<ModelInfo> v;
    for (const auto& e : cf_entries()) v.push_back(e.info);
    for (const auto& e : lc_entries()) v.push_back(e.info);
    v.push_back({"human_driver", "wrapper",
                 "Human Driver Model around idm or modified_idm: reaction time, estimation errors, several "
                 "leaders (Treiber et al. 2006); a driver's human_driver block turns it on"});
    return v;
  }();
  return all;
}

}  // namespace entourage

#include "director/core/director_core.hpp"

#include <cmath>

namespace entourage::director {

namespace {
// A new start-time estimate is published when it moves by more than this.
constexpr double kEstimateReportThreshold_s = 0.5;
// Below this speed the ego is considered stopped and the start time unknown.
constexpr double kStoppedSpeed_mps = 0.1;
}  // namespace

const char* to_string(PlayPhase p) {
  switch (p) {
    case PlayPhase::kWaiting: return "waiting";
    case PlayPhase::kPreparing: return "preparing";
    case PlayPhase::kCast: return "cast";
    case PlayPhase::kTransporting: return "transporting";
    case PlayPhase::kHandedOver: return "handed_over";
    case PlayPhase::kRunning: return "running";
    case PlayPhase::kDone: return "done";
    case PlayPhase::kFailed: return "failed";
  }
  return "unknown";
}

DirectorCore::DirectorCore(const ScenarioConfig& scenario) : scenario_(scenario) {
  for (const auto& p : scenario.plays) plays_.push_back({p, PlayPhase::kWaiting, -1.0});
}

std::vector<PlayReport> DirectorCore::step(const EgoObservation& ego) {
  std::vector<PlayReport> reports;
  for (Play& play : plays_) {
    const PlayPhase before = play.phase;
    std::string detail;
    if (play.phase == PlayPhase::kWaiting && ego.s_m >= play.config.trigger1_s_m) {
      play.phase = PlayPhase::kPreparing;
      detail = "trigger point 1 passed";
    }
    if (play.phase == PlayPhase::kPreparing && ego.s_m >= play.config.trigger2_s_m) {
      play.phase = PlayPhase::kFailed;
      detail = "trigger point 2 passed; no actors: casting and transport are not built yet";
    }
    double estimate = -1.0;
    if (play.phase == PlayPhase::kPreparing && ego.speed_mps > kStoppedSpeed_mps) {
      estimate = ego.time_s + (play.config.trigger2_s_m - ego.s_m) / ego.speed_mps;
    }
    const bool estimate_moved = std::abs(estimate - play.reported_estimate_s) > kEstimateReportThreshold_s;
    if (!first_ && before == play.phase && !estimate_moved) continue;
    play.reported_estimate_s = estimate;
    reports.push_back({play.config.id, play.config.name, play.phase, ego.s_m, play.config.trigger1_s_m,
                       play.config.trigger2_s_m, estimate, detail});
  }
  first_ = false;
  return reports;
}

}  // namespace entourage::director

#pragma once
// The event director (thesis ch. 3.1, papers III-IV): turns autonomous traffic into a scripted
// play at a given place. This core follows each play's trigger points as the ego drives:
//   waiting    -> preparing   when the ego passes trigger point 1
//   preparing  -> failed      when the ego passes trigger point 2: casting, transporting and
//                             handing over actors are not built yet, and the status says so.
// It estimates, while preparing, when the ego will reach trigger point 2 from its current speed.

#include <cstdint>
#include <string>
#include <vector>

#include "scenario/config.hpp"
#include "traffic/world.hpp"

namespace entourage::director {

enum class PlayPhase : std::uint8_t {
  kWaiting = 0,
  kPreparing = 1,
  kCast = 2,
  kTransporting = 3,
  kHandedOver = 4,
  kRunning = 5,
  kDone = 6,
  kFailed = 7,
};

const char* to_string(PlayPhase p);

struct PlayReport {
  std::uint32_t play_id = 0;
  std::string name;
  PlayPhase phase = PlayPhase::kWaiting;
  double ego_s_m = 0.0;
  double trigger1_s_m = 0.0;
  double trigger2_s_m = 0.0;
  double estimated_start_time_s = -1.0;
  std::string detail;
};

class DirectorCore {
 public:
  explicit DirectorCore(const ScenarioConfig& scenario);

  // The reports to publish at this step: every play at step 0, afterwards those whose phase
  // changed or whose start-time estimate moved by more than the reporting threshold.
  std::vector<PlayReport> step(const EgoObservation& ego);

 private:
  struct Play {
    PlayConfig config;
    PlayPhase phase = PlayPhase::kWaiting;
    double reported_estimate_s = -1.0;
  };

  ScenarioConfig scenario_;
  std::vector<Play> plays_;
  bool first_ = true;
};

}  // namespace entourage::director

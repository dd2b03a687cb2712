#pragma once
// Everything about the road and the rules that a driver's decision needs besides the other
// vehicles: lane-change timing, speed adaptation along the road, what lies ahead (sight distance,
// overtaking restrictions, lane closures), the overtaking model's parameters and the step.
// Built once per service from the scenario; read-only afterwards.

#include "behaviour/overtaking.hpp"
#include "scenario/config.hpp"
#include "traffic/road_ahead.hpp"
#include "traffic/speed_sections.hpp"

namespace entourage {

// Oncoming traffic shares the road (a rural road with lanes both ways, no barrier): overtakings
// use the oncoming lane.
inline bool two_way_road(const RoadConfig& road) {
  return road.kind == RoadKind::kRural && road.lanes_backward > 0 && road.lanes_forward > 0;
}

// Timing of lane changes (thesis ch. 3.2: lane changes must take time to look real) and the
// thresholds of the situations that override the models.
struct DrivingRules {
  double signal_s = 1.5;           // indicator on before the lateral movement starts
  double max_signal_wait_s = 4.0;  // a change that has not become safe by then is given up
  double min_interval_s = 5.0;     // from the end of one change to the decision on the next
  // A driver weighs a discretionary change (MOBIL) this often, not at every simulation step: a
  // decision rate of the driver, independent of the step, and well above the rate of mirror
  // glances in free driving. Mandatory changes and the safety check of a signalled change are
  // evaluated every step.
  double decision_interval_s = 0.5;
  // A closed lane this close ahead makes leaving it mandatory (and keeps others out of it).
  double mandatory_lookahead_m = 600.0;
  // A driver brakes for an opposite-direction vehicle in its own lane (an overtaker that has not
  // made it back) once the time to meet it is below this.
  double oncoming_reaction_s = 4.0;
  // ... and always once it is this close, whatever the speeds (both may stand).
  double oncoming_near_m = 30.0;

  // Do two vehicles meeting head-on in one lane, `gap_m` apart and closing at `closing_mps`, react?
  bool oncoming_too_close(double gap_m, double closing_mps) const {
    return gap_m < oncoming_reaction_s * closing_mps + oncoming_near_m;
  }
};

class DrivingEnvironment {
 public:
  explicit DrivingEnvironment(const ScenarioConfig& scenario, DrivingRules rules = {});

  const DrivingRules& rules() const { return rules_; }
  const SpeedSections& speeds() const { return speeds_; }
  const RoadAhead& ahead() const { return ahead_; }
  const OvertakingParams& overtaking() const { return overtaking_; }
  double dt_s() const { return dt_s_; }
  // Oncoming traffic shares the road (no barrier): overtakings use the oncoming lane.
  bool two_way() const { return two_way_; }
  int lanes(Direction d) const { return d == Direction::kForward ? lanes_forward_ : lanes_backward_; }

 private:
  DrivingRules rules_;
  SpeedSections speeds_;
  RoadAhead ahead_;
  OvertakingParams overtaking_;
  double dt_s_;
  bool two_way_;
  int lanes_forward_;
  int lanes_backward_;
};

}  // namespace entourage

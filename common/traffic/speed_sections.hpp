#pragma once
// The road cut into sections of constant conditions (speed limit, curvature, lane width) for
// speed adaptation (behaviour/speed_adaptation.hpp), and each driver's desired speed along it,
// including slowing down in time for a slower section ahead. Built once from the scenario; queried
// per vehicle and step (a binary search plus the few sections within braking reach).

#include <vector>

#include "behaviour/speed_adaptation.hpp"
#include "core/ids.hpp"
#include "scenario/config.hpp"

namespace entourage {

struct SpeedSection {
  double start_m = 0.0;  // along s; sections are contiguous, sorted, and cover [0, road length]
  double end_m = 0.0;
  SectionConditions conditions;
};

class SpeedSections {
 public:
  SpeedSections(const RoadConfig& road, const SpeedAdaptationParams& params);

  const std::vector<SpeedSection>& sections() const { return sections_; }
  const SpeedAdaptationParams& params() const { return params_; }

  // The section containing s (the first or last one outside the road).
  const SpeedSection& at(double s_m) const;

  // The driver's desired speed at s on the section there, without looking ahead.
  double local_desired_speed_mps(double s_m, double basic_desired_mps, double basic_median_mps) const;

  // The driver's desired speed at s travelling in `dir`: the local one, lowered where a section
  // ahead (in the direction of travel) asks for less, to approach_speed_mps(section speed,
  // distance to it, approach_decel). Sections are scanned only as far as they can matter.
  double desired_speed_mps(Direction dir, double s_m, double basic_desired_mps, double basic_median_mps) const;

  // The deceleration a driver at `speed_mps` needs now to be down to the desired speed of every
  // slower section ahead when it reaches it: the largest (v^2 - v_section^2) / (2 distance); 0 if
  // none. The driver brakes by it once it reaches approach_decel (traffic/driving.cpp), so that it
  // arrives at a lower limit or a curve at the speed it drives there, however it approached.
  double approach_decel_needed_mps2(Direction dir, double s_m, double speed_mps, double basic_desired_mps,
                                    double basic_median_mps) const;

  // True when every section has the reference conditions (a straight road at its base limit and
  // reference width): every driver's desired speed is its basic one everywhere.
  bool uniform() const { return uniform_; }

 private:
  // Calls visit(section, distance) for the sections ahead in the direction of travel, nearest
  // first, until it returns false.
  template <typename Visit>
  void for_each_ahead(Direction dir, double s_m, Visit visit) const;

  SpeedAdaptationParams params_;
  std::vector<SpeedSection> sections_;
  bool uniform_ = true;
};

}  // namespace entourage

#pragma once
// The micro-meso transitions of a run, measured from its rows (a recording or its CSV export), for
// the design's seamless borders:
//   into micro  every vehicle handed from meso to micro at a border: the largest deceleration it
//               drives over its first kIntoMicroWindow_s in micro (or until micro hands it on). A
//               vehicle that meso brought to the border with a gap and a speed micro's model
//               accepts does not brake hard there.
//   into meso   every vehicle handed from micro to meso at a border: its lane, and its speed
//               against what its last acceleration in micro gave, across the handoff (micro's last
//               row of it, meso's first). Its identity is the handoff's own: the id carries over.
// Vehicles under a director's command at the handoff are left out (a script may brake them).

#include <cstdint>

#include "recording/tables.hpp"

namespace entourage::recording {

// How long after a handoff into micro its decelerations count.
inline constexpr double kIntoMicroWindow_s = 3.0;
// A deceleration above this counts as hard braking at a border (the comfortable decelerations of
// the shipped drivers' types are 1.3-3 m/s^2).
inline constexpr double kHardBorderDecel_mps2 = 3.0;

struct IntoMicro {
  std::uint64_t handoffs = 0;       // counted (autonomous, seen in micro afterwards)
  double median_decel_mps2 = 0.0;   // of the per-vehicle largest decelerations
  double p95_decel_mps2 = 0.0;
  double max_decel_mps2 = 0.0;
  std::uint64_t hard = 0;           // vehicles above kHardBorderDecel_mps2
};

struct IntoMeso {
  std::uint64_t handoffs = 0;          // counted (autonomous, seen on both sides)
  std::uint64_t lane_kept = 0;         // meso's first row in micro's last lane (or the lane it was moving to)
  double max_speed_jump_mps = 0.0;     // |v_meso - (v_micro + a_micro dt)|, the largest
  double mean_speed_jump_mps = 0.0;
};

struct Transitions {
  IntoMicro into_micro;
  IntoMeso into_meso;
};

// `step_s`: the run's step.
Transitions measure_transitions(const Tables& t, double step_s);

}  // namespace entourage::recording

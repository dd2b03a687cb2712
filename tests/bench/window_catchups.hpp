#pragma once
// Catch-ups counted in drives of the window (every core in one process, window_cores.hpp), against
// the moving-observer prediction: shared by entourage-bench-catchups and the tests that assert a
// transparent probe's catch-ups (tests/unit/probe_catchups_test.cpp).
//
// A drive counts as the recording's summary counts (recording/summary.hpp): a vehicle of the ego's
// direction whose position relative to the ego changes sign between two steps passes it or is
// passed by it; an oncoming one is met when its position does. The prediction integrates the
// moving-observer rates of the streams the drive's generator observed over the ego's speeds.

#include <cstdint>

#include "core/ids.hpp"
#include "road/window.hpp"
#include "scenario/config.hpp"
#include "traffic/observed_stream.hpp"

namespace entourage::bench {

// What one observer (a vehicle of the whole road, or the ego of a window drive) met.
struct Tally {
  double passive = 0.0;  // crossings: vehicles passing the observer
  double active = 0.0;   // vehicles the observer passes
  double predicted_passive = 0.0;
  double predicted_active = 0.0;
  double observed_s = 0.0;
  double distance_m = 0.0;
  // Of observed_s, the time the catch-ups (observed and predicted) were counted: while the window
  // around the observer was like the reference road (traffic/road_sim.hpp: like_reference_road).
  double counted_s = 0.0;
  // Vehicles of its direction crossing the points where its window's edges are: in and out at
  // the rear, in and out at the front (a vehicle born or retired inside counts as crossing).
  double rear_in = 0.0;
  double rear_out = 0.0;
  double front_in = 0.0;
  double front_out = 0.0;
  double vehicle_seconds = 0.0;      // vehicles of its direction in the window, over time
  double rear_outer_seconds = 0.0;   // of those, in the outer region behind
  double front_outer_seconds = 0.0;  // and ahead
  double vehicle_metres = 0.0;       // the distance they drove (Edie's flow: over length and time)
  double rear_outer_metres = 0.0;    // of that, in the outer region behind
  double front_outer_metres = 0.0;   // and ahead
  // Window drives: the oncoming vehicles met, against the prediction, and their distance driven in
  // the window.
  double met = 0.0;
  double predicted_met = 0.0;
  double oncoming_metres = 0.0;

  void add(const Tally& t) {
    passive += t.passive;
    active += t.active;
    predicted_passive += t.predicted_passive;
    predicted_active += t.predicted_active;
    observed_s += t.observed_s;
    distance_m += t.distance_m;
    counted_s += t.counted_s;
    rear_in += t.rear_in;
    rear_out += t.rear_out;
    front_in += t.front_in;
    front_out += t.front_out;
    vehicle_seconds += t.vehicle_seconds;
    rear_outer_seconds += t.rear_outer_seconds;
    front_outer_seconds += t.front_outer_seconds;
    vehicle_metres += t.vehicle_metres;
    rear_outer_metres += t.rear_outer_metres;
    front_outer_metres += t.front_outer_metres;
    met += t.met;
    predicted_met += t.predicted_met;
    oncoming_metres += t.oncoming_metres;
  }
};

// The scenario with its ego a probe (scenario `ego.transparent`): an observer at a set speed (its
// road's curves and limits allowed) that the traffic drives through and that sees nobody, as the
// moving-observer relations assume.
ScenarioConfig with_probe(ScenarioConfig sc, double speed_kph);

// The window's edges and regions relative to the observer (its position 0).
WindowBounds relative_window(const WindowConfig& w);
double window_length_m(const WindowConfig& w);
bool in_window(double rel_m, const WindowBounds& b);

// The observer's own step: its speed against the stream's moving-observer rates, these only if
// the step's catch-ups are `counted`.
void observe_step(Tally& t, double speed_mps, const ObservedStream& stream, double dt, bool counted = true);

// Another vehicle of its direction in the observer's window, `rel_m` ahead of it now (behind if
// negative) and `before_m` the step before (NaN: not there then).
void observe_in_window(Tally& t, double before_m, double rel_m, double speed_mps, const WindowBounds& w, double dt);

// A vehicle gone (retired, or off the road's end) whose last position was `before_m`.
void observe_gone(Tally& t, double before_m, const WindowBounds& w);

// The initial fill reaches the regions a step after the generator placed it: counting starts after
// it has settled, or its vehicles would count as born inside the window.
inline constexpr Step kFillSteps = 10;

// One drive of the window: the ego stand-in counted as the recording's summary counts it (a vehicle
// of its direction whose position relative to the ego changes sign between two steps; an oncoming
// one is met when its position does), the same prediction, from the streams the drive's generator
// observed; both only at the steps when the whole window is on a stretch like the reference road.
Tally window_drive(const ScenarioConfig& sc, std::uint64_t seed, double duration_s);

}  // namespace entourage::bench

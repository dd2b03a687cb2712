#pragma once
// Vehicle generation for a window that moves with the ego (thesis ch. 3.2, papers I-II).
//
// Per direction the demand is a stationary stream (common/traffic/stream.hpp). Seen from the
// window moving at the ego's speed u, vehicles faster than u enter at the rear edge, slower ones at
// the front edge, and oncoming vehicles at the front edge, each as a Poisson process whose rate
// follows u (so that the flow past any fixed road point equals the demand), with the entering
// speeds drawn from the matching conditional distribution. At the start, and whenever the ego
// jumps, the whole window is filled at the stream's density with space-mean speeds.
//
// Phases of a step:
//   fill      at the first step or after a jump: vehicles across the whole window
//   arrive    Poisson arrivals at each edge join that edge's queue (type and speed drawn now)
//   place     queued vehicles enter where their lane has room; the others wait (counted)
// New vehicles are handed to micro (inner region) or meso (outer regions) at once.

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "core/random.hpp"
#include "road/road.hpp"
#include "road/window.hpp"
#include "scenario/config.hpp"
#include "traffic/handoff.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/step_io.hpp"
#include "traffic/stream.hpp"

namespace entourage::generator {

enum class Edge : std::uint8_t { kRear = 0, kFront = 1 };

struct Counters {
  std::uint64_t filled = 0;        // vehicles placed by initial fills
  std::uint64_t fill_dropped = 0;  // fill points with no room left in the window
  std::uint64_t arrivals = 0;      // arrivals drawn at the edges
  std::uint64_t placed = 0;        // arrivals that entered
  std::uint64_t waited_steps = 0;  // vehicle-steps spent queued at an edge for lack of room
  std::uint64_t fills = 0;         // number of initial fills (1 + jumps)
};

struct GeneratorConfig {
  double jump_threshold_m = 100.0;  // an ego moving further than this in a step has jumped
  std::size_t max_queue = 200;      // arrivals waiting at one edge before the oldest is dropped
};

class GeneratorCore {
 public:
  GeneratorCore(const ScenarioConfig& scenario, std::uint64_t seed, GeneratorConfig config = {});

  StepOutput step(const StepInput& in);

  const Counters& counters() const { return counters_; }
  std::size_t queued() const;

 private:
  struct Pending {
    std::uint8_t type_index;
    double speed_mps;
  };
  struct Stream {
    Direction dir;
    Edge edge;
    double accumulated = 0.0;  // integrated rate since the last arrival
    double next = 1.0;         // unit-exponential threshold of the next arrival
    std::deque<Pending> queue;
  };

  struct Spot {
    int lane;
    double progress_m;
    double speed_mps;  // the speed it starts with there
  };

  bool needs_fill(const StepInput& in) const;
  std::optional<Spot> fill_spot(Direction dir, double progress_m, double speed_mps, std::uint8_t type_index) const;
  double room_behind(Direction dir, int lane, double progress_m, double speed_mps, const VehicleTypeConfig& type) const;
  void perceive(const StepInput& in);
  void fill(const StepInput& in, StepOutput& out);
  void arrive(const StepInput& in);
  void place(const StepInput& in, StepOutput& out);
  // The lane (and the speed it allows) where a vehicle can enter at s_m, preferring the lane that
  // lets it drive fastest; nullopt if no lane has room.
  std::optional<std::pair<int, double>> find_room(Direction dir, double s_m, double speed_mps,
                                                  std::uint8_t type_index) const;
  Handoff birth(Direction dir, int lane, double s_m, double speed_mps, double desired_speed_mps,
                std::uint8_t type_index, const WindowBounds& w, Step step, HandoffReason reason);
  double rate(const Stream& s, double u) const;
  SpeedDraw draw(const Stream& s, double u);
  const StreamModel& model(Direction d) const { return d == Direction::kForward ? forward_ : backward_; }

  ScenarioConfig scenario_;
  GeneratorConfig config_;
  Road road_;
  StreamModel forward_;
  StreamModel backward_;
  Random rng_;
  std::uint64_t seed_;
  VehicleId next_id_ = 1;
  std::vector<Stream> streams_;
  std::optional<EgoObservation> last_ego_;
  LaneIndex index_;                   // world at step-1 moved to this step, plus recent births
  std::vector<Handoff> recent_births_;  // not yet visible in the world state
  Counters counters_;
};

}  // namespace entourage::generator

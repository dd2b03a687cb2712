#pragma once
// Vehicle generation for a window that moves with the ego (thesis ch. 3.2, papers I-II).
//
// Per direction, the demand's stream is observed once at startup as the model itself produces it
// (common/traffic/observed_stream.hpp: a road simulation of the demand, cut into platoons), so
// that speeds, densities and platoons are those of interacting traffic, not of drivers at their
// desired speeds. Seen from the window moving at the ego's speed u (Wardrop's moving-observer
// relations, for platoons): platoons faster than u enter at the rear edge, slower ones at the
// front edge and oncoming ones at the front edge, each edge a Poisson process whose rate follows
// u, the platoon drawn with the matching weight.
//
// Phases of a step:
//   adopt     vehicles that left the window ahead join the front zone (adopt_left_ahead)
//   perceive  the world at step-1 moved on to this step, births not yet visible, and the front zone
//   ahead     the front zone's vehicles move (front_zone.hpp: the traffic just beyond the front edge)
//   fill      at the first step or after a jump: a stretch of the observed stream fills the window
//             and the front zone
//   arrive    platoon arrivals at each edge join that edge's queue; the rates follow the ego's speed
//             and are scaled towards the stream's density in the window (regulation: the ego's
//             direction counted in the outer regions, where the ego gathers nobody)
//   place     from behind and oncoming, a platoon's vehicles enter one by one at the edge, each
//             when its lane has room there; from ahead, a slow platoon joins the front zone whole,
//             its last vehicle just beyond the edge, and enters the window as the edge reaches it.
//             Every waiting platoon gets its turn, in arrival order: one that cannot enter yet does
//             not hold up the others
//   hand over front-zone vehicles the edge has reached go to meso; those far ahead retire
// New vehicles are handed at once to micro (inner region) or meso (outer regions).

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "core/random.hpp"
#include "generator/core/front_zone.hpp"
#include "road/road.hpp"
#include "road/window.hpp"
#include "scenario/config.hpp"
#include "traffic/handoff.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/observed_stream.hpp"
#include "traffic/step_io.hpp"

namespace entourage::generator {

enum class Edge : std::uint8_t { kRear = 0, kFront = 1 };

// The three entrances of the window: the ego's direction from behind and from ahead, and the
// oncoming direction from ahead.
enum class Entrance : std::uint8_t { kRear = 0, kFront = 1, kOncoming = 2 };
inline constexpr std::size_t kEntrances = 3;

struct Counters {
  std::array<std::uint64_t, kEntrances> arrivals_at{};  // platoons, per entrance
  std::array<std::uint64_t, kEntrances> members_at{};   // vehicles in the arrived platoons
  std::array<std::uint64_t, kEntrances> placed_at{};    // vehicles, per entrance
  std::uint64_t filled = 0;         // vehicles placed by initial fills
  std::uint64_t fill_skipped = 0;   // fill vehicles that would have overlapped the ego or others
  std::uint64_t fill_overlapping = 0;  // fill vehicles left out: they overlapped another of the stretch
  std::uint64_t arrivals = 0;       // platoons arrived at the edges
  std::uint64_t placed = 0;         // vehicles that entered at the edges
  std::uint64_t waited_steps = 0;   // platoon-steps spent queued at an edge for lack of room
  std::uint64_t dropped = 0;        // platoons dropped from an overfull edge queue
  std::uint64_t at_leader_speed = 0;  // members from behind caught slower than the window, entered at their leader's speed
  std::uint64_t ahead = 0;          // vehicles that joined the front zone
  std::uint64_t left_ahead = 0;     // front-zone vehicles that left far ahead without entering
  std::uint64_t made_way = 0;       // faster front-zone vehicles taken to have passed a slow platoon
  std::uint64_t fills = 0;          // number of initial fills (1 + jumps)
  std::uint64_t commands_applied = 0;  // director commands to front-zone vehicles (FrontZone::apply)
  // Platoons expected per entrance at the moving-observer rates over the ego's speeds, plain and
  // as the regulation scaled them: their ratio is what the regulation did to the arrivals.
  std::array<double, kEntrances> expected_plain_at{};
  std::array<double, kEntrances> expected_regulated_at{};
};

struct GeneratorConfig {
  double jump_threshold_m = 100.0;  // an ego moving further than this in a step has jumped
  double front_zone_m = 300.0;      // the front zone's reach beyond the front edge at a fill
  double front_entry_margin_m = 2.0;  // a slow platoon's last vehicle joins the zone this far ahead of the edge
  int fill_candidates = 8;          // stretches drawn for a fill; the closest to the mean density wins
  double front_zone_limit_m = 1500.0;  // vehicles further ahead than this leave the front zone
  std::size_t max_queue = 100;      // platoons waiting at one edge before the oldest is dropped
  StreamObservation observation;
};

class GeneratorCore {
 public:
  GeneratorCore(const ScenarioConfig& scenario, std::uint64_t seed, GeneratorConfig config = {});

  StepOutput step(const StepInput& in);

  const Counters& counters() const { return counters_; }
  std::size_t queued() const;
  const Fleet& front_zone() const { return zone_.vehicles(); }
  const ObservedStream& stream(Direction d) const { return d == Direction::kForward ? forward_ : backward_; }

 private:
  struct Pending {
    Platoon platoon;
    std::size_t next_member = 0;  // from behind and oncoming: members placed, leader first
  };
  struct EdgeStream {
    Direction dir;
    Edge edge;
    Entrance entrance;
    double accumulated = 0.0;  // integrated rate since the last arrival
    double next = 1.0;         // unit-exponential threshold of the next arrival
    std::deque<Pending> queue;
  };

  void perceive(const StepInput& in);
  void index_world(const StepInput& in);
  void hand_over(const StepInput& in, StepOutput& out);
  Vehicle make(const Vehicle& model, Direction dir, int lane, double progress_m, double speed_mps);
  bool needs_fill(const StepInput& in) const;
  void fill(const StepInput& in, StepOutput& out);
  void arrive(const StepInput& in);
  void place(const StepInput& in, StepOutput& out);
  bool place_one_by_one(const EdgeStream& s, Pending& pending, double u, const WindowBounds& w, Step step,
                        StepOutput& out);
  bool place_from_ahead(const EdgeStream& s, const Pending& pending, const WindowBounds& w);
  bool platoon_fits(const Platoon& platoon, Direction dir, int lane, double leader_p,
                    std::vector<VehicleId>& in_the_way) const;
  void add_to_zone(const Vehicle& v);
  // A vehicle that left the window ahead goes on in the front zone towards the speed a driver
  // like it has in the stream (ObservedStream::typical_speed_mps), never below its exit speed.
  // Kept at its exit speed, a car leaving held up stayed slow beyond the edge and held up the
  // window's front vehicles for minutes (front_zone.hpp); set to its typical speed even when that
  // is below its exit speed, it fell back into the window: at a probe speed of 100 km/h the outer
  // region ahead held 14.4 vehicles for the stream's 10.6.
  void adopt_left_ahead(const Vehicle& v);
  // Room for `v` at `progress_m`: the gap its driver wants to the vehicle ahead, and the gap the
  // vehicle behind wants to it (crowding_follower: that vehicle if it lacks it, else nullptr).
  bool room_ahead(Direction dir, int lane, double progress_m, const Vehicle& v) const;
  const Occupant* crowding_follower(Direction dir, int lane, double progress_m, const Vehicle& v) const;
  bool fits(Direction dir, int lane, double progress_m, const Vehicle& v) const;
  Handoff birth(const Vehicle& model, Direction dir, int lane, double progress_m, double speed_mps,
                const WindowBounds& w, Step step, HandoffReason reason);
  double rate(const EdgeStream& s, double u) const;
  // The factor on the arrivals of the ego's direction (the oncoming direction is not regulated):
  // how far its vehicles counted (in the outer regions, or the whole window; scenario
  // demand.regulation_counts) are from the stream's density times the length counted (scenario
  // demand.regulation_gain).
  double regulation(const StepInput& in) const;

  ScenarioConfig scenario_;
  GeneratorConfig config_;
  Road road_;
  Random rng_;
  std::uint64_t seed_;
  ObservedStream forward_;
  ObservedStream backward_;
  VehicleId next_id_ = 1;
  std::vector<EdgeStream> edges_;
  std::optional<EgoObservation> last_ego_;
  LaneIndex index_;                     // world at step-1 moved on to this step, plus births
  std::vector<Handoff> recent_births_;  // not yet visible in the world state
  FrontZone zone_;
  std::vector<Vehicle> passed_;  // zone vehicles that made way for a slow platoon: they leave
  HandoffInbox inbox_{Role::kGenerator, {Region::kOutside}};  // vehicles leaving the window ahead
  Counters counters_;
};

}  // namespace entourage::generator

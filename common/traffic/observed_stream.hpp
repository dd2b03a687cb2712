#pragma once
// The stationary stream of a demand as the model itself produces it, observed in a road
// simulation (road_sim.hpp): snapshots of a stretch of road where the stream has settled, cut
// into platoons. Interacting traffic is not a set of independent vehicles at their desired
// speeds: drivers are slower than they wish, and slow ones are often held up behind a slower
// leader. The generator fills the window with a stretch of such a snapshot and feeds its edges
// with such platoons, so that both the speeds and the structure of the stream are right.
//
// A platoon is a leader and the vehicles following it in its lane that keep up with it (PlatoonRule).
// The moving-observer relations (../shared/notes/traffic-theory.md) hold for platoons as for
// vehicles: with platoon density k_p and the space-mean distribution f_p of platoon speeds (the
// snapshots are space samples), a window moving at u is entered from behind at k_p E[(v - u)+],
// from ahead at k_p E[(u - v)+] and by oncoming platoons at k_p E[v + u], each platoon chosen with
// that weight. The platoon density is scaled so that the platoons carry exactly the demanded flow
// (sum of size x speed over the sampled length = q): the sample gives the stream's structure, the
// demand its flow. The vehicle density is scaled alike, so that the vehicles at their own speeds
// carry it (the generator's regulation aims at it, and a fill takes the stretch closest to it): a
// sample of 20 snapshots carries a flow some percent off the demand (3-13 % below it on the rural
// road, within 2 % on the freeway), and a target from the unscaled density disagreed with the
// arrivals by as much.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "scenario/config.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

// Which vehicles of a snapshot drive in one platoon. A vehicle joins the platoon ahead of it in its
// lane when it is closer than `headway_s` behind that platoon's last vehicle and not slower than
// the platoon's speed by more than `speed_tolerance_mps`. A platoon enters the window at its
// leader's speed and is weighted with it in the moving-observer rates, so a member must drive at
// that speed: a vehicle falling back from a faster one it happens to be near (a truck a second
// behind a car that passed it at 110 km/h) is no follower. Counted at its leader's speed, a tenth
// of the freeway's trucks entered a window at 100 km/h from behind instead of ahead, and the window
// held 22 % fewer trucks than the stream (stop 27). Followers faster than their leader are held up
// by it and belong to it.
struct PlatoonRule {
  double headway_s = 3.0;
  double speed_tolerance_mps = 2.0;
};

// Snapshots of 10 km of settled road every 120 s. A vehicle takes 350-450 s to cross those 10 km,
// so consecutive snapshots share most of their vehicles: the 20 are some five independent samples,
// and what they carry is off the demand by several percent (on the rural road 3-13 % below it; one
// snapshot's flow moves between 300 and 550 veh/h at a demand of 450). The densities are scaled to
// the demand (below); more or sparser snapshots would cost startup time in proportion.
struct StreamObservation {
  double road_length_m = 12000.0;
  double settled_from_m = 2000.0;  // the stream is sampled beyond this distance from the source
  double warmup_s = 450.0;         // before the first snapshot: the stream reaches the road's end
  double snapshot_every_s = 120.0;
  int snapshots = 20;
  PlatoonRule platoon;
};

// A vehicle of a snapshot or of a platoon: the position along its direction of travel from the
// stretch's rear end (snapshots), or the distance behind its platoon's leader (platoons).
struct StreamVehicle {
  double offset_m = 0.0;
  Vehicle vehicle;  // lane, speed, type, size and driver; id and position are set on entry
};

struct Platoon {
  double speed_mps = 0.0;             // the leader's
  std::vector<StreamVehicle> members;  // leader first (offset 0), then backwards
};

// Cuts one snapshot (sorted by offset) into platoons, lane by lane, from the front of the stretch
// backwards, appending them to `out`. A platoon cut by the stretch's ends is kept as it is.
void cut_into_platoons(const std::vector<StreamVehicle>& snap, int lanes, const PlatoonRule& rule,
                       std::vector<Platoon>* out);

// The seeds a run's generator observes its streams with: its own seed from the run's (its
// service's derived stream) and, from that, one per direction. A recording's reader (the catch-up
// prediction, recording/summary.hpp) observes with the same seeds, so it predicts from the very
// stream the generator fed the window with, not from another sample of it (the rural oncoming
// stream's density differs by 7 % between two samples of 20 snapshots).
std::uint64_t generator_seed(std::uint64_t run_seed);
std::uint64_t observation_seed(std::uint64_t generator_seed, Direction dir);

// Speeds in ascending order with running sums, for the moving-observer sums at any window speed
// u in O(log n): the generator asks for its edges' rates at every step, and a pass over the
// observed platoons was a third of its cost.
class SortedSpeeds {
 public:
  void add(double speed_mps);
  void finish();  // sorts; call after the last add
  std::size_t size() const { return sorted_mps_.size(); }
  double sum_mps() const;                   // of all the speeds
  double sum_faster_by(double u) const;     // sum of max(0, v - u)
  double sum_slower_by(double u) const;     // sum of max(0, u - v)
  double sum_closing_with(double u) const;  // sum of v + u

 private:
  struct Sums {
    double count = 0.0;
    double speed = 0.0;
  };
  Sums below(double u) const;  // over the speeds below u
  Sums all() const;
  std::vector<double> sorted_mps_;
  std::vector<double> running_sum_mps_;  // from the slowest up to each one, inclusive
};

class ObservedStream {
 public:
  ObservedStream() = default;
  // Observes the stream of `dir`'s demand. A direction without flow gives an empty stream.
  ObservedStream(const ScenarioConfig& scenario, Direction dir, const StreamObservation& how, std::uint64_t seed);

  bool empty() const { return platoons_.empty(); }
  double flow_veh_per_s() const { return flow_; }
  double density_per_m() const { return vehicle_density_; }  // of the stream carrying the demand
  double sample_flow_per_s() const { return sample_flow_; }  // what the snapshots themselves carried
  double platoon_density_per_m() const { return platoon_density_; }
  double mean_speed_mps() const;  // space mean over vehicles
  // The speed a driver like `v` (its type and basic desired speed) has in the stream, on average:
  // its desired speed times the mean ratio of speed to desired speed of the observed vehicles of
  // its type closest to it in desired speed (kTypicalNeighbours of them). A driver drives below
  // the speed it wishes in interacting traffic, fast ones more so. Its desired speed when the
  // stream has no vehicle of its type.
  double typical_speed_mps(const Vehicle& v) const;
  const std::vector<Platoon>& platoons() const { return platoons_; }

  double rate_rear_per_s(double window_speed_mps) const;  // platoons per second
  double rate_front_per_s(double window_speed_mps) const;
  double rate_oncoming_per_s(double window_speed_mps) const;
  // The same in vehicles per second, each vehicle at its own speed: the catch-ups of a driver at a
  // steady speed u, passive (overtaken by the stream) and active (overtaking it), and the oncoming
  // vehicles met. These count every crossing (a vehicle that drops back behind the driver and
  // passes it again crosses twice), the rate at which vehicles cross a point moving at u in a
  // stationary stream (k E[(v - u)+] over the space-mean distribution of the vehicles' own speeds),
  // not the platoons' leaders' speeds the arrivals are drawn with: on the freeway a platoon's
  // followers mostly close in on their leader, and at 100 km/h the leaders' speeds gave 1.23 times
  // the active and 0.90 times the passive rate of the vehicles' own (stop 27). Vehicles in the
  // middle of an overtaking are counted here (they are left out of the snapshots the window is
  // filled from, not out of the stream): a probe at 85 km/h on a straight rural road is passed by
  // them a quarter of the times it is passed (stop 40, entourage-bench-catchups on a whole road).
  double vehicles_rear_per_s(double window_speed_mps) const;
  double vehicles_front_per_s(double window_speed_mps) const;
  double vehicles_oncoming_per_s(double window_speed_mps) const;
  // The share of the stream's vehicles that were in the middle of an overtaking when observed.
  double passing_share() const;
  const Platoon& draw_rear(Random& rng, double window_speed_mps) const;
  const Platoon& draw_front(Random& rng, double window_speed_mps) const;
  const Platoon& draw_oncoming(Random& rng, double window_speed_mps) const;

  // A stretch of `length_m` of the settled stream (offsets in [0, length_m) from its rear end).
  // Of `candidates` stretches drawn, the one whose number of vehicles is closest to the stream's
  // mean density times the length (every run starts at the demanded density, with the stream's
  // structure; a single draw would vary by a quarter in a window of a kilometre or two).
  std::vector<StreamVehicle> stretch(Random& rng, double length_m, int candidates = 1) const;

 private:
  std::vector<StreamVehicle> one_stretch(Random& rng, double length_m) const;
  // A sum over the observed platoons as a rate of the stream that carries the demand: its mean per
  // platoon times the platoons per metre.
  double as_rate_per_s(double sum_over_platoons) const;
  // A sum over the observed vehicles as a rate: its mean per vehicle times the vehicles per metre.
  double per_vehicle_rate_per_s(double sum_over_vehicles) const;
  void note_speed_ratio(const Vehicle& v);
  static constexpr std::ptrdiff_t kTypicalNeighbours = 50;
  template <typename Weight>
  const Platoon& draw(Random& rng, Weight w) const;

  double flow_ = 0.0;
  double sampled_length_m_ = 0.0;
  double vehicle_density_ = 0.0;
  double sample_flow_ = 0.0;
  double platoon_density_ = 0.0;  // scaled to the demanded flow
  std::vector<std::vector<StreamVehicle>> snapshots_;  // sorted by offset
  std::vector<Platoon> platoons_;
  SortedSpeeds platoon_speeds_;  // the platoons' (their leaders')
  SortedSpeeds vehicle_speeds_;  // every observed vehicle's own
  // Every vehicle's own speed, those in the middle of an overtaking too (the catch-up rates), and
  // their density scaled like vehicle_density_.
  SortedSpeeds crossing_speeds_;
  double crossing_density_ = 0.0;
  // Per vehicle type (index): (basic desired speed, speed / desired speed) of every observed
  // vehicle, sorted by desired speed.
  std::vector<std::vector<std::pair<double, double>>> speed_ratio_by_desired_;
};

// A stretch must not place two vehicles on top of each other: where one overlaps the vehicle ahead
// of it in its lane (the road simulation the stream was observed in had a collision, and the
// snapshot caught it), the one behind is removed. Returns how many were removed.
std::size_t remove_overlapping(std::vector<StreamVehicle>& stretch);

}  // namespace entourage

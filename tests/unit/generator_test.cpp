// The generator core: the window filled at the stream's density, arrivals at the edges at the
// moving-observer rates, never a vehicle on top of another.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>

#include "core_test_util.hpp"
#include "generator/core/generator_core.hpp"
#include "road/window.hpp"
#include "traffic/driver_draw.hpp"
#include "traffic/handoff.hpp"
#include "traffic/observed_stream.hpp"
#include "traffic/stream.hpp"

namespace entourage::generator {
namespace {

using entourage::testing::ego_at;
using entourage::testing::freeway_scenario;

// Positions of all births of one direction and lane, to check spacing.
void expect_no_overlap(const std::vector<Handoff>& births, const EgoObservation& ego) {
  std::map<std::pair<int, int>, std::vector<std::pair<double, double>>> lanes;  // (dir, lane) -> (s, length)
  for (const auto& h : births) lanes[{sign(h.vehicle.direction), h.vehicle.lane}].push_back({h.vehicle.s_m, h.vehicle.length_m});
  lanes[{1, ego.lane}].push_back({ego.s_m, ego.length_m});
  for (auto& [key, v] : lanes) {
    std::sort(v.begin(), v.end());
    for (std::size_t i = 1; i < v.size(); ++i) {
      EXPECT_GT(v[i].first - v[i - 1].first, 0.5 * (v[i].second + v[i - 1].second))
          << "overlap in direction " << key.first << " lane " << key.second << " at s " << v[i].first;
    }
  }
}

TEST(Generator, AStretchNeverPlacesTwoVehiclesOnTopOfEachOther) {
  // An observed stream whose road simulation had a collision: in lane 0 a car 3 m behind another's
  // centre (they overlap), a truck behind them with room; in lane 1 a car beside the pair.
  auto at = [](double offset_m, int lane, double length_m) {
    StreamVehicle sv;
    sv.offset_m = offset_m;
    sv.vehicle.lane = lane;
    sv.vehicle.length_m = length_m;
    return sv;
  };
  std::vector<StreamVehicle> stretch{at(100.0, 0, 4.5), at(97.0, 0, 4.5), at(60.0, 0, 16.5), at(98.0, 1, 4.5),
                                     at(120.0, 0, 4.5)};
  EXPECT_EQ(remove_overlapping(stretch), 1U);
  ASSERT_EQ(stretch.size(), 4U);
  // The one behind went; the others keep their order; touching bumpers (4.5 m apart) is no overlap.
  EXPECT_DOUBLE_EQ(stretch[0].offset_m, 100.0);
  EXPECT_DOUBLE_EQ(stretch[1].offset_m, 60.0);
  EXPECT_DOUBLE_EQ(stretch[2].offset_m, 98.0);
  std::vector<StreamVehicle> touching{at(100.0, 0, 4.5), at(95.5, 0, 4.5)};
  EXPECT_EQ(remove_overlapping(touching), 0U);
  // A chain of three on top of each other: only the front one stays.
  std::vector<StreamVehicle> chain{at(50.0, 0, 4.5), at(48.0, 0, 4.5), at(46.0, 0, 4.5)};
  EXPECT_EQ(remove_overlapping(chain), 2U);
  EXPECT_DOUBLE_EQ(chain.front().offset_m, 50.0);
}

TEST(Generator, InitialFillHasTheStreamsDensityAndNoOverlap) {
  const ScenarioConfig sc = freeway_scenario();
  for (std::uint64_t seed : {1ULL, 2ULL, 61ULL}) {
    GeneratorCore g(sc, seed);
    StepInput in;
    in.ego = ego_at(0, 5000.0, 30.5);
    const StepOutput out = g.step(in);
    const WindowBounds w = WindowBounds::around(5000.0, sc.window);
    for (Direction d : {Direction::kForward, Direction::kBackward}) {
      const bool ahead = d == Direction::kForward;
      const double length = w.front_edge_m - w.rear_edge_m + (ahead ? GeneratorConfig{}.front_zone_m : 0.0);
      const double expected = g.stream(d).density_per_m() * length;
      auto n = std::count_if(out.handoffs.begin(), out.handoffs.end(),
                             [&](const Handoff& h) { return h.vehicle.direction == d; });
      if (ahead) n += static_cast<decltype(n)>(g.front_zone().size());
      EXPECT_NEAR(static_cast<double>(n), expected, 0.1 * expected) << "seed " << seed << " direction " << sign(d);
    }
    expect_no_overlap(out.handoffs, in.ego);
    for (const auto& h : out.handoffs) {
      EXPECT_EQ(h.reason, HandoffReason::kInitialFill);
      EXPECT_EQ(h.to_role, w.in_inner(h.vehicle.s_m) ? Role::kMicro : Role::kMeso);
      EXPECT_GE(h.vehicle.s_m, w.rear_edge_m);
      EXPECT_LE(h.vehicle.s_m, w.front_edge_m);
    }
    // the generator keeps what lies just ahead of the window, and publishes it
    for (const auto& r : out.states) EXPECT_GT(r.s_m, w.front_edge_m);
    EXPECT_EQ(out.states.size(), g.front_zone().size());
  }
}

TEST(Generator, TheObservedStreamIsSlowerThanItsDriversWishAndCarriesTheDemand) {
  const ScenarioConfig sc = freeway_scenario();
  const ObservedStream s(sc, Direction::kForward, StreamObservation{}, 3);
  const StreamModel free = make_stream(sc, Direction::kForward);
  EXPECT_LT(s.mean_speed_mps(), free.mean_space_speed_mps());        // interacting drivers are held up
  EXPECT_GT(s.density_per_m(), free.density_per_m());                // so there are more of them per km
  EXPECT_NEAR(s.density_per_m() * s.mean_speed_mps(), sc.forward.flow_veh_per_s, 0.1 * sc.forward.flow_veh_per_s);
  double trucks_behind = 0.0;
  for (const auto& p : s.platoons()) trucks_behind += p.members.size() > 1 ? 1.0 : 0.0;
  EXPECT_GT(trucks_behind, 0.0);  // platoons exist
}

TEST(Generator, ADriverIsSlowerInTheStreamThanItWishesAFastOneMoreSo) {
  const ScenarioConfig sc = freeway_scenario();
  const ObservedStream s(sc, Direction::kForward, StreamObservation{}, 3);
  const auto typical = [&](std::uint8_t type, double desired_mps) {
    Vehicle v;
    v.type_index = type;
    v.driver.car_following.idm.desired_speed_mps = desired_mps;
    return s.typical_speed_mps(v);
  };
  const double slow = typical(0, 27.0);  // cars: 97 and 144 km/h
  const double fast = typical(0, 40.0);
  EXPECT_LT(slow, 27.0);
  EXPECT_LT(fast, 40.0);
  EXPECT_GT(fast, slow + 3.0);                // a fast driver is still faster
  EXPECT_LT(fast / 40.0, slow / 27.0);        // but held up more
  const double truck = typical(1, 24.5);      // trucks keep near their 88 km/h
  EXPECT_GT(truck, 0.9 * 24.5);
  EXPECT_LE(truck, 24.5);
}

TEST(Generator, ObservesItsStreamsWithTheSeedsARecordingsReaderDerives) {
  const ScenarioConfig sc = freeway_scenario();
  const std::uint64_t run_seed = 7;
  const GeneratorCore g(sc, generator_seed(run_seed));
  for (Direction d : {Direction::kForward, Direction::kBackward}) {
    const ObservedStream same(sc, d, StreamObservation{}, observation_seed(generator_seed(run_seed), d));
    EXPECT_EQ(g.stream(d).platoons().size(), same.platoons().size());
    EXPECT_EQ(g.stream(d).density_per_m(), same.density_per_m());
    EXPECT_EQ(g.stream(d).mean_speed_mps(), same.mean_speed_mps());
  }
}

// Without regulation (nothing else moves here, so the window would look empty to it).
ScenarioConfig unregulated() {
  ScenarioConfig sc = freeway_scenario();
  sc.demand_regulation_gain = 0.0;
  return sc;
}

TEST(Generator, ACarThatLeavesTheWindowHeldUpGoesOnAheadAtItsStreamSpeed) {
  const ScenarioConfig sc = unregulated();
  const double u = 20.0;
  double s = 5000.0;
  const WindowBounds w = WindowBounds::around(s, sc.window);
  StepInput in;
  in.ego = ego_at(0, s, u);
  // A fill without a front zone, so that nothing there holds either car up (with the zone's 300 m
  // the result hung on the observed stream: a slower zone vehicle 150 m ahead braked the fast car
  // once a change of the models redrew the stream).
  GeneratorConfig no_zone;
  no_zone.front_zone_m = 0.0;
  GeneratorCore g(sc, 3, no_zone);
  g.step(in);  // the fill
  ASSERT_TRUE(g.front_zone().vehicles().empty());
  const int lane = 0;
  const auto left_ahead = [&](VehicleId id, int in_lane, double s_m, double speed_mps, double desired_mps) {
    Random rng(id);
    const DriverParams d = draw_driver(sc.vehicle_types[0], desired_mps, id, rng);
    const Vehicle v = make_vehicle(id, 0, sc.vehicle_types[0], Direction::kForward, in_lane, s_m, speed_mps, d);
    return make_handoff(v, 0, ServiceId{Role::kMeso, 0}, Role::kGenerator, Region::kOutside, HandoffReason::kLeftWindow);
  };
  const VehicleId held_up = 9000001;  // left at 21 m/s, wishes 38
  const VehicleId fast = 9000002;     // left at 34 m/s, wishes 30: faster than it usually is
  in.handoffs = {left_ahead(held_up, lane, w.front_edge_m + 5.0, 21.0, 38.0),
                 left_ahead(fast, 1 - lane, w.front_edge_m + 5.0, 34.0, 30.0)};
  Vehicle probe;
  probe.type_index = 0;
  probe.driver.car_following.idm.desired_speed_mps = 38.0;
  const double typical = g.stream(Direction::kForward).typical_speed_mps(probe);
  ASSERT_GT(typical, 21.0 + 5.0);
  for (int k = 1; k <= 150; ++k) {  // 15 s
    s += u * sc.step_s;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, s, u);
    g.step(in);
    in.handoffs.clear();
  }
  const auto speed_of = [&](VehicleId id) {
    for (const Vehicle& v : g.front_zone().vehicles()) {
      if (v.id == id) return v.speed_mps;
    }
    ADD_FAILURE() << "vehicle " << id << " not in the front zone";
    return 0.0;
  };
  EXPECT_NEAR(speed_of(held_up), typical, 0.1) << "kept the speed it left the window with";
  EXPECT_NEAR(speed_of(fast), 34.0, 0.1) << "slowed below its exit speed: it would fall back into the window";
}

// A vehicle the director released (or cleared) that left the window ahead is the generator's
// until the front edge reaches it: the director's commands to it apply there and go on with it
// into the window. (They were dropped: an actor released in the front zone stayed "releasing" for
// good, and a later play could not cast it.)
TEST(Generator, TheDirectorsCommandsToAFrontZoneVehicleGoOnWithItIntoTheWindow) {
  const ScenarioConfig sc = unregulated();
  double s = 5000.0;
  const WindowBounds w = WindowBounds::around(s, sc.window);
  GeneratorConfig no_zone;
  no_zone.front_zone_m = 0.0;
  GeneratorCore g(sc, 3, no_zone);
  StepInput in;
  in.ego = ego_at(0, s, 20.0);
  g.step(in);  // the fill
  const VehicleId id = 9000001;
  Random rng(id);
  Vehicle v = make_vehicle(id, 0, sc.vehicle_types[0], Direction::kForward, 0, w.front_edge_m + 5.0, 20.0,
                           draw_driver(sc.vehicle_types[0], 20.0, id, rng));
  v.control.mode = ControlMode::kReleasing;  // released by the director just before it left ahead
  in.handoffs = {make_handoff(v, 0, ServiceId{Role::kMeso, 0}, Role::kGenerator, Region::kOutside, HandoffReason::kLeftWindow)};
  ActorCommand released;
  released.vehicle = id;
  released.step = 0;
  released.control.mode = ControlMode::kAutonomous;
  std::optional<Handoff> into_window;
  for (int k = 1; k <= 100 && !into_window; ++k) {  // the ego at 30 m/s catches up with it
    s += 30.0 * sc.step_s;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, s, 30.0);
    in.commands.clear();
    if (k == 3) {
      const Vehicle* here = g.front_zone().find(id);
      ASSERT_NE(here, nullptr);
      EXPECT_EQ(here->control.mode, ControlMode::kReleasing);
      in.commands = {released};
    }
    for (const Handoff& h : g.step(in).handoffs) {
      if (h.vehicle.id == id) into_window = h;
    }
    in.handoffs.clear();
  }
  ASSERT_TRUE(into_window.has_value());
  EXPECT_EQ(into_window->to_role, Role::kMeso);
  EXPECT_EQ(into_window->vehicle.control.mode, ControlMode::kAutonomous);
  EXPECT_EQ(g.counters().commands_applied, 1U);
}

TEST(Generator, ArrivalsMatchTheMovingObserverRates) {
  const ScenarioConfig sc = unregulated();
  GeneratorCore g(sc, 11);
  const double u = 29.0;
  const int steps = 36000;  // an hour
  double s = 5000.0;
  bool fast_from_behind = true;
  bool slow_from_ahead = true;
  for (int k = 0; k < steps; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, s, u);
    const StepOutput out = g.step(in);  // nothing else moves: only the arrivals are counted
    for (const auto& h : out.handoffs) {
      if (h.reason != HandoffReason::kBirth) continue;
      EXPECT_NE(h.to_role, Role::kMicro) << "born inside the inner region";
      if (h.vehicle.direction != Direction::kForward) continue;
      if (h.vehicle.s_m < s) fast_from_behind = fast_from_behind && h.vehicle.speed_mps > u;
      if (h.vehicle.s_m > s) slow_from_ahead = slow_from_ahead && h.vehicle.speed_mps < u;
    }
    s += u * sc.step_s;
  }
  EXPECT_TRUE(fast_from_behind);
  EXPECT_TRUE(slow_from_ahead);
  const double hours = steps * sc.step_s;
  const auto within = [](std::uint64_t count, double expected) {
    return std::abs(static_cast<double>(count) - expected) < 4.0 * std::sqrt(expected) + 2.0;  // Poisson, 4 sigma
  };
  const Counters& c = g.counters();
  const ObservedStream& fwd = g.stream(Direction::kForward);
  const ObservedStream& bwd = g.stream(Direction::kBackward);
  EXPECT_TRUE(within(c.arrivals_at[0], fwd.rate_rear_per_s(u) * hours)) << c.arrivals_at[0];
  // Every vehicle of a platoon from behind enters, also one the stream's snapshot caught slower
  // than the window (at its leader's speed, rare since a platoon's members keep up with it within
  // 2 m/s); only those still queued at the end are missing.
  EXPECT_LE(c.members_at[0] - c.placed_at[0], 10U) << c.members_at[0] << " " << c.placed_at[0];
  EXPECT_TRUE(within(c.arrivals_at[1], fwd.rate_front_per_s(u) * hours)) << c.arrivals_at[1];
  EXPECT_TRUE(within(c.arrivals_at[2], bwd.rate_oncoming_per_s(u) * hours)) << c.arrivals_at[2];
}

TEST(Generator, AStandingEgoGetsTheWholeFlowFromBehind) {
  const ScenarioConfig sc = unregulated();
  GeneratorCore g(sc, 5);
  const int steps = 18000;
  for (int k = 0; k < steps; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, 5000.0, 0.0);
    g.step(in);
  }
  const Counters& c = g.counters();
  const double expected = sc.forward.flow_veh_per_s * steps * sc.step_s;
  // vehicles come in platoons of about two: a count of platoons is Poisson, of vehicles twice as wide
  EXPECT_NEAR(static_cast<double>(c.placed_at[0]), expected, 6.0 * std::sqrt(expected)) << c.placed_at[0];
  EXPECT_EQ(c.arrivals_at[1], 0U);
}

// A slow vehicle crawling over the rear edge holds its lane for a minute; trucks keep to that
// lane and must wait, but the cars that arrive after them pass it in the other lane (as on the
// road, before the edge reached either). Served strictly in their order of arrival, the first
// waiting truck stopped every entry from behind (the window's rear arrivals came at 0.87 of the
// moving-observer rate, entourage-bench-catchups --probe-kph 80).
TEST(Generator, APlatoonThatCannotEnterYetDoesNotHoldUpThoseArrivingAfterIt) {
  const ScenarioConfig sc = unregulated();
  GeneratorCore g(sc, 7);
  const double u = 22.0;
  const int steps = 18000;  // half an hour
  const double blocker_ahead_m = 5.0;  // its rear this far inside the rear edge, in the right lane
  double s = 5000.0;
  std::uint64_t late_births = 0;  // from behind, in the last ten minutes
  for (int k = 0; k < steps; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, s, u);
    ObservedVehicle blocker;  // published at the previous step, moving with the window
    blocker.id = 1000000;
    blocker.direction = Direction::kForward;
    blocker.lane = blocker.target_lane = 0;
    blocker.length_m = 16.5;
    blocker.speed_mps = u;
    blocker.s_m = WindowBounds::around(s, sc.window).rear_edge_m + blocker_ahead_m + 0.5 * blocker.length_m -
                  u * sc.step_s;
    in.world_prev.push_back(blocker);
    const StepOutput out = g.step(in);
    for (const auto& h : out.handoffs) {
      if (h.reason != HandoffReason::kBirth || h.vehicle.direction != Direction::kForward || h.vehicle.s_m > s) continue;
      EXPECT_EQ(h.vehicle.lane, 1) << "entered the lane the blocker holds";
      if (k >= steps - 6000) ++late_births;
    }
    s += u * sc.step_s;
  }
  const Counters& c = g.counters();
  EXPECT_GT(c.members_at[0], c.placed_at[0] + 3) << "no truck waiting: the test blocks nothing";
  // The cars' share of the arrivals from behind, at the moving-observer rate, with Poisson room.
  const double expected = 0.5 * g.stream(Direction::kForward).vehicles_rear_per_s(u) * 600.0;
  EXPECT_GT(static_cast<double>(late_births), expected - 3.0 * std::sqrt(expected)) << late_births;
}

// Regulation: the ego's direction's arrivals scaled by 1 + gain (expected - present) / expected,
// within [0, 1 + gain], counted over the outer regions; the oncoming direction is not regulated. A direction's arrivals are counted with the window held at a standing world of that
// direction's vehicles: at the stream's density times `density_factor`, and `inner_factor` times
// that in the inner region. The oncoming entrance (the busiest) over ten minutes, the ego's
// direction (both its entrances) over an hour.
std::uint64_t arrivals(Direction dir, double gain, double density_factor, double inner_factor = 1.0) {
  ScenarioConfig sc = freeway_scenario();
  sc.demand_regulation_gain = gain;
  GeneratorCore g(sc, 21);
  const double u = dir == Direction::kBackward ? 29.0 : 25.0;
  const int steps = dir == Direction::kBackward ? 6000 : 36000;
  const WindowBounds w0 = WindowBounds::around(0.0, sc.window);
  const double length = w0.front_edge_m - w0.rear_edge_m;
  const auto n = static_cast<std::size_t>(std::lround(density_factor * g.stream(dir).density_per_m() * length));
  double s = 5000.0;
  for (int k = 0; k < steps; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, s, u);
    const WindowBounds w = WindowBounds::around(s, sc.window);
    VehicleId id = 1000000;
    const auto stand = [&](double s_m) {
      ObservedVehicle o;
      o.id = id++;
      o.direction = dir;
      o.s_m = s_m;
      o.speed_mps = 0.0;
      o.length_m = 0.1;
      in.world_prev.push_back(o);
    };
    for (std::size_t i = 0; i < n; ++i) {  // a standing world of vehicles spread over the window
      const double s_m = w.rear_edge_m + (static_cast<double>(i) + 0.5) * length / static_cast<double>(n);
      stand(s_m);
      if (w.in_inner(s_m) && inner_factor > 1.0) stand(s_m + 1.0);  // twice as dense there
    }
    g.step(in);
    s += u * sc.step_s;
  }
  const Counters& c = g.counters();
  return dir == Direction::kBackward ? c.arrivals_at[2] : c.arrivals_at[0] + c.arrivals_at[1];
}
std::uint64_t oncoming_arrivals(double gain, double density_factor, double inner_factor = 1.0) {
  return arrivals(Direction::kBackward, gain, density_factor, inner_factor);
}

TEST(Generator, RegulationPullsTheEgosDirectionTowardsTheStreamsDensity) {
  const double plain = static_cast<double>(arrivals(Direction::kForward, 0.0, 1.0));
  EXPECT_NEAR(static_cast<double>(arrivals(Direction::kForward, 4.0, 1.0)), plain, 5.0 * std::sqrt(plain));
  // held empty, only the births of the last steps count as present: close to the full boost of 5
  const double boosted = static_cast<double>(arrivals(Direction::kForward, 4.0, 0.0));
  EXPECT_GT(boosted, 3.0 * plain);
  EXPECT_LT(boosted, 5.0 * plain + 5.0 * std::sqrt(5.0 * plain));
  EXPECT_EQ(arrivals(Direction::kForward, 4.0, 2.0), 0U);
}

// The oncoming vehicles cross the window in well under a minute: regulating their count raised the
// oncoming flow 4 % above the demand (services/generator/README.md, *Regulation*). They enter at
// the moving-observer rate whatever the window holds.
TEST(Generator, TheOncomingDirectionEntersAtThePlainMovingObserverRate) {
  const double plain = static_cast<double>(oncoming_arrivals(0.0, 1.0));
  EXPECT_GT(plain, 100.0);
  for (double density_factor : {0.0, 1.0, 2.0}) {
    EXPECT_NEAR(static_cast<double>(oncoming_arrivals(4.0, density_factor)), plain, 5.0 * std::sqrt(plain))
        << "window held at " << density_factor << " times the stream's density";
  }
}

// Drivers the ego holds up, or that it follows, gather around it: a whole road of traffic holds
// more vehicles in the inner region than the stream's density says and the stream's density in the
// outer regions (entourage-bench-catchups). Counting the inner region too cut the arrivals from
// behind, and with them the catch-ups.
TEST(Generator, VehiclesGatheredInTheInnerRegionDoNotCutTheArrivals) {
  const double plain = static_cast<double>(arrivals(Direction::kForward, 0.0, 1.0));
  EXPECT_NEAR(static_cast<double>(arrivals(Direction::kForward, 4.0, 1.0, 2.0)), plain, 5.0 * std::sqrt(plain));
  // the outer regions still count: held at twice the density everywhere, nothing arrives
  EXPECT_EQ(arrivals(Direction::kForward, 4.0, 2.0), 0U);
}

TEST(Generator, AJumpOfTheEgoRefillsTheWindow) {
  const ScenarioConfig sc = freeway_scenario();
  GeneratorCore g(sc, 9);
  StepInput in;
  in.ego = ego_at(0, 2000.0, 30.0);
  g.step(in);
  in.step = 1;
  in.ego = ego_at(1, 9000.0, 30.0);  // a simulator reset far down the road
  const StepOutput out = g.step(in);
  const auto fills = std::count_if(out.handoffs.begin(), out.handoffs.end(),
                                   [](const Handoff& h) { return h.reason == HandoffReason::kInitialFill; });
  EXPECT_GT(fills, 20);
  EXPECT_EQ(g.counters().fills, 2U);
}

TEST(Generator, SameSeedSameVehicles) {
  const ScenarioConfig sc = freeway_scenario();
  GeneratorCore a(sc, 77);
  GeneratorCore b(sc, 77);
  for (int k = 0; k < 300; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, 3000.0 + 30.0 * 0.1 * k, 30.0);
    const auto oa = a.step(in);
    const auto ob = b.step(in);
    ASSERT_EQ(oa.handoffs.size(), ob.handoffs.size());
    for (std::size_t i = 0; i < oa.handoffs.size(); ++i) {
      EXPECT_EQ(oa.handoffs[i].vehicle.id, ob.handoffs[i].vehicle.id);
      EXPECT_DOUBLE_EQ(oa.handoffs[i].vehicle.s_m, ob.handoffs[i].vehicle.s_m);
      EXPECT_DOUBLE_EQ(oa.handoffs[i].vehicle.driver.desired_speed_mps(), ob.handoffs[i].vehicle.driver.desired_speed_mps());
    }
  }
}

}  // namespace
}  // namespace entourage::generator

// The observed stream (traffic/observed_stream.hpp): how a snapshot is cut into platoons, and the
// catch-up rates of a driver at a steady speed from the vehicles' own speeds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/random.hpp"
#include "core_test_util.hpp"
#include "traffic/observed_stream.hpp"

namespace entourage {
namespace {

using testing::freeway_scenario;

StreamVehicle at(double offset_m, double speed_mps, double length_m = 4.5) {
  StreamVehicle v;
  v.offset_m = offset_m;
  v.vehicle.lane = 0;
  v.vehicle.speed_mps = speed_mps;
  v.vehicle.length_m = length_m;
  return v;
}

std::vector<Platoon> platoons_of(const std::vector<StreamVehicle>& snap, const PlatoonRule& rule = {}) {
  std::vector<Platoon> out;
  cut_into_platoons(snap, 1, rule, &out);
  return out;
}

// A car that has just passed a truck and cut in 1.5 s ahead of it at 31 m/s: the truck at 24 m/s
// falls back; the car behind the truck is held up by it.
std::vector<StreamVehicle> truck_just_passed() {
  return {at(120.0, 24.5), at(150.0, 24.0, 16.5), at(200.0, 31.0)};  // sorted by offset
}

TEST(ObservedStream, AVehicleFallingBackFromTheOneAheadIsNoFollower) {
  const std::vector<Platoon> p = platoons_of(truck_just_passed());
  ASSERT_EQ(p.size(), 2U);
  EXPECT_DOUBLE_EQ(p[0].speed_mps, 31.0);
  EXPECT_EQ(p[0].members.size(), 1U);
  EXPECT_DOUBLE_EQ(p[1].speed_mps, 24.0);  // the truck leads its own platoon
  ASSERT_EQ(p[1].members.size(), 2U);
  EXPECT_DOUBLE_EQ(p[1].members[1].offset_m, 30.0);  // the car behind it, 30 m behind its centre
  // By the headway alone all three were one platoon at the car's 31 m/s.
  EXPECT_EQ(platoons_of(truck_just_passed(), {3.0, 1e9}).size(), 1U);
}

TEST(ObservedStream, AFollowerClosingInOnItsLeaderDrivesInItsPlatoon) {
  // 1.9 m/s slower than its leader (within the tolerance), and 5 m/s faster: both follow.
  const std::vector<Platoon> p = platoons_of({at(120.0, 30.0), at(160.0, 23.1), at(200.0, 25.0)});
  ASSERT_EQ(p.size(), 1U);
  EXPECT_EQ(p[0].members.size(), 3U);
  // Further than the headway behind: a platoon of its own whatever its speed.
  EXPECT_EQ(platoons_of({at(100.0, 25.0), at(200.0, 25.0)}).size(), 2U);  // 95.5 m at 25 m/s > 3 s
}

TEST(ObservedStream, EveryPlatoonMemberKeepsUpWithItsLeader) {
  const ObservedStream s(freeway_scenario(), Direction::kForward, StreamObservation{}, 3);
  const double tolerance = StreamObservation{}.platoon.speed_tolerance_mps;
  std::size_t followers = 0;
  for (const Platoon& p : s.platoons()) {
    for (std::size_t i = 1; i < p.members.size(); ++i, ++followers) {
      EXPECT_GE(p.members[i].vehicle.speed_mps, p.speed_mps - tolerance);
    }
  }
  EXPECT_GT(followers, 100U);  // the freeway has platoons
}

// Gross crossings of a point moving at u in a stationary stream: k E[(v - u)+] from behind and
// k E[(u - v)+] from ahead over the vehicles' own speeds, whose difference is the flow relative to
// the point, k (mean speed - u). With the platoons' speeds (a follower counted at its leader's) it
// is not.
TEST(ObservedStream, CatchUpRatesAreThoseOfTheVehiclesOwnSpeeds) {
  const ObservedStream s(freeway_scenario(), Direction::kForward, StreamObservation{}, 3);
  const double k = s.density_per_m();
  for (double u : {0.0, 22.0, 27.8, 36.1, 60.0}) {
    EXPECT_NEAR(s.vehicles_rear_per_s(u) - s.vehicles_front_per_s(u), k * (s.mean_speed_mps() - u), 1e-9) << u;
    EXPECT_NEAR(s.vehicles_oncoming_per_s(u), k * (s.mean_speed_mps() + u), 1e-9) << u;
  }
  EXPECT_DOUBLE_EQ(s.vehicles_front_per_s(0.0), 0.0);
  EXPECT_DOUBLE_EQ(s.vehicles_rear_per_s(60.0), 0.0);
}

// On a two-way road some vehicles are in the middle of an overtaking at any time; they are left out
// of the snapshots the window is filled from but not out of the catch-up rates: a standing observer
// is still passed by the whole flow, and the rates' difference is the flow relative to it.
TEST(ObservedStream, CatchUpRatesCountTheVehiclesInTheMiddleOfAPass) {
  const ScenarioConfig sc = testing::shipped_scenario("rural");
  const ObservedStream s(sc, Direction::kForward, StreamObservation{}, 3);
  EXPECT_GT(s.passing_share(), 0.005);
  EXPECT_LT(s.passing_share(), 0.2);
  EXPECT_NEAR(s.vehicles_rear_per_s(0.0), sc.forward.flow_veh_per_s, 1e-9);
  // The rates' density is that of every vehicle: oncoming k (v + u) minus passive k (v - u)+ plus
  // active k (u - v)+ is 2 k u, with k above the snapshots' own density times the share they are.
  const double u = 22.0;
  const double k = (s.vehicles_oncoming_per_s(u) - s.vehicles_rear_per_s(u) + s.vehicles_front_per_s(u)) / (2.0 * u);
  EXPECT_GT(k, s.density_per_m() * (1.0 - s.passing_share()));
  EXPECT_GT(std::abs(k - s.density_per_m()), 1e-3 * s.density_per_m());  // not the snapshots' vehicles alone
  EXPECT_NEAR(s.vehicles_oncoming_per_s(0.0), sc.forward.flow_veh_per_s, 1e-9);
  const ObservedStream freeway(testing::freeway_scenario(), Direction::kForward, StreamObservation{}, 3);
  EXPECT_EQ(freeway.passing_share(), 0.0);
}

TEST(SortedSpeeds, SumsMatchADirectPassAtAnySpeed) {
  Random rng(5);
  SortedSpeeds sorted;
  std::vector<double> speeds;
  for (int i = 0; i < 200; ++i) {
    speeds.push_back(rng.uniform(15.0, 40.0));
    sorted.add(speeds.back());
  }
  sorted.finish();
  for (double u : {0.0, 14.0, 20.0, 27.5, 33.3, 41.0}) {
    double faster = 0.0;
    double slower = 0.0;
    double closing = 0.0;
    for (double v : speeds) {
      faster += std::max(0.0, v - u);
      slower += std::max(0.0, u - v);
      closing += v + u;
    }
    EXPECT_NEAR(sorted.sum_faster_by(u), faster, 1e-9 * closing) << u;
    EXPECT_NEAR(sorted.sum_slower_by(u), slower, 1e-9 * closing) << u;
    EXPECT_NEAR(sorted.sum_closing_with(u), closing, 1e-9 * closing) << u;
  }
}

}  // namespace
}  // namespace entourage

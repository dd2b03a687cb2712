// The road-simulation experiment (entourage-roadsim): detector statistics against hand-computed
// values, the capacity estimate, the overrides and their refusals, and a whole short run.
#include <gtest/gtest.h>

#include <string>

#include "core/units.hpp"
#include "roadsim/core/road_experiment.hpp"
#include "scenario/loader.hpp"
#include "traffic/detector_stats.hpp"

namespace entourage {
namespace {

Crossing crossing(double t, double speed, Direction dir = Direction::kForward) {
  Crossing c;
  c.time_s = t;
  c.speed_mps = speed;
  c.direction = dir;
  return c;
}

TEST(DetectorStats, FlowSpeedsAndDensityOfAnInterval) {
  // Two vehicles in the first minute at 20 and 30 m/s, none in the second; one backward vehicle.
  const std::vector<Crossing> cs{crossing(10.0, 20.0), crossing(50.0, 30.0), crossing(20.0, 25.0, Direction::kBackward),
                                 crossing(130.0, 10.0)};
  const auto iv = aggregate_crossings(cs, 500.0, Direction::kForward, 2, 0.0, 125.0, 60.0);
  ASSERT_EQ(iv.size(), 2u);  // the last partial interval is dropped, with the crossing at 130 s
  EXPECT_EQ(iv[0].vehicles, 2u);
  EXPECT_DOUBLE_EQ(iv[0].flow_veh_per_h, 120.0);
  EXPECT_DOUBLE_EQ(iv[0].flow_per_lane_veh_per_h(), 60.0);
  EXPECT_DOUBLE_EQ(iv[0].time_mean_speed_mps, 25.0);
  EXPECT_DOUBLE_EQ(iv[0].space_mean_speed_mps, 24.0);  // harmonic mean 2 / (1/20 + 1/30)
  EXPECT_NEAR(iv[0].density_veh_per_km, 120.0 / 86.4, 1e-12);
  EXPECT_EQ(iv[1].vehicles, 0u);
  EXPECT_DOUBLE_EQ(iv[1].flow_veh_per_h, 0.0);
  EXPECT_DOUBLE_EQ(iv[1].start_s, 60.0);
}

TEST(DetectorStats, CapacityIsTheBestSustainedWindow) {
  std::vector<DetectorInterval> iv(5);
  const double flows[] = {1000.0, 3000.0, 3400.0, 3200.0, 1000.0};
  for (std::size_t i = 0; i < iv.size(); ++i) {
    iv[i].detector_m = 100.0;
    iv[i].lanes = 2;
    iv[i].flow_veh_per_h = flows[i];
  }
  EXPECT_DOUBLE_EQ(roadsim::max_sustained_flow_per_lane(iv, Direction::kForward, 100.0, 1), 1700.0);
  EXPECT_DOUBLE_EQ(roadsim::max_sustained_flow_per_lane(iv, Direction::kForward, 100.0, 3), 1600.0);
  EXPECT_DOUBLE_EQ(roadsim::max_sustained_flow_per_lane(iv, Direction::kBackward, 100.0, 1), 0.0);
}

ScenarioConfig freeway() {
  const auto loaded = scenario::load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/freeway.pbtxt");
  EXPECT_TRUE(loaded.ok());
  return loaded.config;
}

TEST(RoadExperiment, OverridesApplyToEveryVehicleType) {
  roadsim::ExperimentConfig c;
  c.car_following = "idm";
  c.human_driver = 1;
  c.lane_change = "none";
  c.forward_flow_veh_per_h = 2000.0;
  c.backward_flow_veh_per_h = 0.0;
  c.decision_interval_s = 0.0;
  const roadsim::Prepared p = roadsim::prepare(freeway(), c);
  ASSERT_TRUE(p.ok()) << p.error;
  for (const auto& t : p.scenario.vehicle_types) {
    EXPECT_EQ(t.driver.car_following, "idm");
    EXPECT_TRUE(t.driver.human_driver);
    EXPECT_EQ(t.driver.lane_change, "none");
  }
  EXPECT_TRUE(p.road.forward);
  EXPECT_FALSE(p.road.backward);
  EXPECT_DOUBLE_EQ(p.road.rules.decision_interval_s, 0.0);
  ASSERT_EQ(p.road.detectors_m.size(), 1u);
  EXPECT_DOUBLE_EQ(p.road.detectors_m[0], 6000.0);
}

TEST(RoadExperiment, BothDirectionsGetADetectorEach) {
  const roadsim::Prepared p = roadsim::prepare(freeway(), roadsim::ExperimentConfig{});
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_TRUE(p.road.backward);
  EXPECT_EQ(p.road.detectors_m, (std::vector<double>{2000.0, 6000.0}));
}

TEST(RoadExperiment, BadOverridesAreRefusedWithTheReason) {
  const ScenarioConfig sc = freeway();
  auto error = [&](auto tweak) {
    roadsim::ExperimentConfig c;
    tweak(c);
    return roadsim::prepare(sc, c).error;
  };
  EXPECT_NE(error([](auto& c) { c.car_following = "krauss"; }).find("unknown car-following model"), std::string::npos);
  EXPECT_NE(error([](auto& c) { c.lane_change = "lc2013"; }).find("unknown lane-change model"), std::string::npos);
  EXPECT_NE(error([](auto& c) {
              c.car_following = "gipps";
              c.human_driver = 1;
            }).find("not gipps"),
            std::string::npos);
  EXPECT_NE(error([](auto& c) { c.warmup_s = 5000.0; }).find("warm-up"), std::string::npos);
  EXPECT_NE(error([](auto& c) { c.detectors_m = {9000.0}; }).find("not on the road"), std::string::npos);
  EXPECT_NE(error([](auto& c) {
              c.forward_flow_veh_per_h = 0.0;
              c.backward_flow_veh_per_h = 0.0;
            }).find("no demand"),
            std::string::npos);
}

TEST(RoadExperiment, AShortRunCarriesTheDemandPastTheDetector) {
  roadsim::ExperimentConfig c;
  c.forward_flow_veh_per_h = 1800.0;
  c.backward_flow_veh_per_h = 0.0;
  c.length_m = 3000.0;
  c.duration_s = 900.0;
  c.warmup_s = 180.0;
  const roadsim::Prepared p = roadsim::prepare(freeway(), c);
  ASSERT_TRUE(p.ok()) << p.error;
  const roadsim::ExperimentResult r = roadsim::run_experiment(p, c);
  std::size_t vehicles = 0;
  for (const auto& i : r.intervals) vehicles += i.vehicles;
  const double flow = per_second_to_per_hour(static_cast<double>(vehicles) / (c.duration_s - c.warmup_s));
  EXPECT_NEAR(flow, 1800.0, 0.15 * 1800.0);  // Poisson arrivals over 12 minutes
  EXPECT_EQ(r.steps, 9000u);
  EXPECT_GT(r.vehicle_updates, 0u);
  EXPECT_GT(r.counters.trips, 0u);
  EXPECT_GT(mps_to_kph(r.mean_trip_speed_mps), 80.0);
  EXPECT_LT(mps_to_kph(r.mean_trip_speed_mps), 140.0);
  EXPECT_EQ(r.counters.emergency_decisions, 0u);
}

}  // namespace
}  // namespace entourage

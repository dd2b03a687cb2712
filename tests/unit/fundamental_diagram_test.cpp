// Paper V's finding on a short run of the road simulation: on a two-lane freeway loaded above
// capacity, the modified IDM carries more traffic at a higher mean speed than IDM, and its speed
// advantage is larger when both are wrapped in the Human Driver Model. (The full sweep and the
// diagrams: entourage-bench-fd.)
#include <gtest/gtest.h>

#include <string>

#include "core/units.hpp"
#include "roadsim/core/road_experiment.hpp"
#include "scenario/loader.hpp"

namespace entourage {
namespace {

struct Outcome {
  double flow_per_lane_veh_per_h = 0.0;  // at the detector, after the warm-up
  double mean_speed_kph = 0.0;           // on the road, after the warm-up
};

Outcome run(const std::string& model, bool hdm, std::uint64_t seed) {
  const auto loaded = scenario::load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/freeway.pbtxt");
  EXPECT_TRUE(loaded.ok());
  roadsim::ExperimentConfig c;
  c.car_following = model;
  c.human_driver = hdm ? 1 : 0;
  c.forward_flow_veh_per_h = 4200.0;  // above either model's capacity: the entrance queues
  c.backward_flow_veh_per_h = 0.0;
  c.lanes = 2;
  c.length_m = 4000.0;
  c.duration_s = 600.0;
  c.warmup_s = 200.0;
  c.seed = seed;
  const roadsim::Prepared p = roadsim::prepare(loaded.config, c);
  EXPECT_TRUE(p.ok()) << p.error;
  const roadsim::ExperimentResult r = roadsim::run_experiment(p, c);
  std::size_t vehicles = 0;
  double seconds = 0.0;
  for (const auto& i : r.intervals) {
    vehicles += i.vehicles;
    seconds += i.end_s - i.start_s;
  }
  EXPECT_GT(r.max_queue, 0u) << "the demand should exceed the capacity";
  return {per_second_to_per_hour(static_cast<double>(vehicles) / seconds) / 2.0, mps_to_kph(r.mean_speed_mps)};
}

TEST(FundamentalDiagram, ModifiedIdmHasTheHigherCapacityAndSpeed) {
  for (bool hdm : {false, true}) {
    const Outcome idm = run("idm", hdm, 1);
    const Outcome modified = run("modified_idm", hdm, 1);
    EXPECT_GT(modified.flow_per_lane_veh_per_h, 1.05 * idm.flow_per_lane_veh_per_h) << "HDM " << hdm;
    EXPECT_GT(modified.mean_speed_kph, idm.mean_speed_kph + 3.0) << "HDM " << hdm;
  }
}

TEST(FundamentalDiagram, TheSpeedAdvantageIsLargerWithTheHumanDriverModel) {
  double gain_plain = 0.0;
  double gain_hdm = 0.0;
  for (std::uint64_t seed : {1, 2}) {
    gain_plain += run("modified_idm", false, seed).mean_speed_kph - run("idm", false, seed).mean_speed_kph;
    gain_hdm += run("modified_idm", true, seed).mean_speed_kph - run("idm", true, seed).mean_speed_kph;
  }
  EXPECT_GT(gain_hdm, gain_plain);
}

}  // namespace
}  // namespace entourage

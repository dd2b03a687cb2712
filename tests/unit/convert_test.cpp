// Topic samples to and from the model, and the checks that refuse bad samples.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dds/convert.hpp"

namespace entourage::dds {
namespace {

RoadConfig road_config() {
  RoadConfig c;
  c.length_m = 10000.0;
  c.lanes_forward = 2;
  c.lanes_backward = 1;
  c.speed_limit_mps = 30.0;
  return c;
}

SampleLimits limits() {
  SampleLimits l;
  l.lanes_forward = 2;
  l.lanes_backward = 1;
  l.vehicle_types = 2;
  return l;
}

Vehicle sample_vehicle() {
  Vehicle v;
  v.id = 42;
  v.type_index = 1;
  v.direction = Direction::kBackward;
  v.lane = 0;
  v.s_m = 1234.5;
  v.speed_mps = 27.0;
  v.accel_mps2 = -0.4;
  v.length_m = 12.0;
  v.width_m = 2.5;
  v.handoff_sequence = 6;
  v.lane_change = {0, 0, LaneChangePhase::kNone, 0.0, 4.5, 12.0, 0.3};
  v.driver.car_following.idm = {25.0, 1.7, 0.8, 1.6, 3.0, 4.0};
  v.driver.car_following.beta = 1.4;
  v.driver.lane_change = LaneChangeModel::kNone;
  v.driver.mobil = {0.4, 0.15, 0.25, 3.5};
  v.driver.max_decel_mps2 = 6.0;
  v.driver.lane_change_duration_s = 4.5;
  v.driver.desired_speed_median_mps = 27.5;
  v.driver.car_following.gipps = {0.7, 3.2, 2.9};
  v.driver.car_following.human_driver = true;
  v.driver.car_following.hdm = {0.5, 4, 0.12, 0.02, 15.0};
  v.hdm_errors = {0.3, -1.2};
  v.requested_lane = 1;
  v.driver.keep_right = true;
  v.driver.rng_state = 0xDEADBEEFULL;
  return v;
}

TEST(Convert, HandoffRoundTripKeepsTheWholeVehicle) {
  const Road road(road_config());
  const Handoff h =
      make_handoff(sample_vehicle(), 77, ServiceId{Role::kMicro, 0}, Role::kMeso, Region::kOuterFront, HandoffReason::kBorder);
  const msg::Handoff m = to_msg(h, 7.7, road);
  EXPECT_FALSE(check(m, limits()).has_value());
  const Handoff back = from_msg(m);
  const Vehicle& a = h.vehicle;
  const Vehicle& b = back.vehicle;
  EXPECT_EQ(b.id, a.id);
  EXPECT_EQ(b.handoff_sequence, 7U);
  EXPECT_EQ(b.direction, a.direction);
  EXPECT_DOUBLE_EQ(b.s_m, a.s_m);
  EXPECT_DOUBLE_EQ(b.speed_mps, a.speed_mps);
  EXPECT_DOUBLE_EQ(b.driver.car_following.idm.time_gap_s, 1.7);
  EXPECT_DOUBLE_EQ(b.driver.car_following.beta, 1.4);
  EXPECT_EQ(b.driver.lane_change, LaneChangeModel::kNone);
  EXPECT_DOUBLE_EQ(b.driver.mobil.politeness, 0.4);
  EXPECT_TRUE(b.driver.keep_right);
  EXPECT_EQ(b.driver.rng_state, 0xDEADBEEFULL);
  EXPECT_DOUBLE_EQ(b.lane_change.since_last_change_s, 12.0);
  EXPECT_DOUBLE_EQ(b.lane_change.decision_wait_s, 0.3);
  EXPECT_DOUBLE_EQ(b.driver.desired_speed_median_mps, 27.5);
  EXPECT_DOUBLE_EQ(b.driver.car_following.gipps.max_decel_mps2, 3.2);
  EXPECT_DOUBLE_EQ(b.driver.car_following.gipps.leader_decel_estimate_mps2, 2.9);
  EXPECT_TRUE(b.driver.car_following.human_driver);
  EXPECT_EQ(b.driver.car_following.hdm.anticipated_leaders, 4);
  EXPECT_DOUBLE_EQ(b.driver.car_following.hdm.error_persistence_s, 15.0);
  EXPECT_DOUBLE_EQ(b.hdm_errors.w_approach, -1.2);
  EXPECT_EQ(b.requested_lane, 1);
  EXPECT_EQ(back.step, 77U);
  EXPECT_EQ(back.from, (ServiceId{Role::kMicro, 0}));
  EXPECT_EQ(back.to_role, Role::kMeso);
  EXPECT_EQ(back.to_region, Region::kOuterFront);
  EXPECT_EQ(back.reason, HandoffReason::kBorder);
  EXPECT_DOUBLE_EQ(m.d_m(), road.lane_center_d(Direction::kBackward, 0));
}

TEST(Convert, VehicleStateCarriesPoseAndOwner) {
  const Road road(road_config());
  const msg::VehicleState m = to_msg(VehicleReport{sample_vehicle(), Region::kInner}, ServiceId{Role::kMeso, 2}, 5, 0.5, road);
  EXPECT_EQ(ServiceId::from_code(m.owner()), (ServiceId{Role::kMeso, 2}));
  EXPECT_EQ(m.region(), static_cast<uint8_t>(Region::kInner));
  EXPECT_DOUBLE_EQ(m.x_m(), 1234.5);
  EXPECT_NEAR(std::abs(m.heading_rad()), 3.14159265358979, 1e-9);
  EXPECT_FALSE(check(m, limits()).has_value());
  const ObservedVehicle o = from_msg(m);
  EXPECT_EQ(o.id, 42U);
  EXPECT_EQ(o.direction, Direction::kBackward);
}

TEST(Convert, BadSamplesAreRefusedWithAReason) {
  const Road road(road_config());
  msg::VehicleState m = to_msg(VehicleReport{sample_vehicle(), Region::kInner}, ServiceId{Role::kMicro, 0}, 1, 0.1, road);
  msg::VehicleState nan = m;
  nan.speed_mps(std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(check(nan, limits())->find("not finite"), std::string::npos);
  msg::VehicleState lane = m;
  lane.lane(1);  // the backward direction has one lane
  EXPECT_NE(check(lane, limits())->find("lane 1"), std::string::npos);
  SampleLimits two_way = limits();
  two_way.two_way = true;  // on a rural road lane 1 of the backward direction is the oncoming lane
  EXPECT_FALSE(check(lane, two_way).has_value());
  lane.lane(3);
  EXPECT_TRUE(check(lane, two_way).has_value());
  msg::VehicleState type = m;
  type.type_index(9);
  EXPECT_NE(check(type, limits())->find("vehicle type"), std::string::npos);
  msg::VehicleState id0 = m;
  id0.id(0);
  EXPECT_TRUE(check(id0, limits()).has_value());
  msg::VehicleState fast = m;
  fast.speed_mps(500.0);
  EXPECT_TRUE(check(fast, limits()).has_value());
  msg::Handoff h = to_msg(make_handoff(sample_vehicle(), 1, ServiceId{Role::kMicro, 0}, Role::kMeso,
                                       Region::kOuterRear, HandoffReason::kBorder),
                          0.1, road);
  h.handoff_sequence(0);
  EXPECT_TRUE(check(h, limits()).has_value());
}

TEST(Convert, StepDoneCountsRoundTrip) {
  TopicCounts c{};
  c[static_cast<std::size_t>(Topic::kVehicleState)] = 12;
  c[static_cast<std::size_t>(Topic::kHandoff)] = 3;
  const msg::StepDone m = make_step_done(ServiceId{Role::kMeso, 1}, 99, c, 40);
  EXPECT_EQ(counts_of(m), c);
  EXPECT_EQ(m.owned_vehicles(), 40U);
  EXPECT_EQ(m.step(), 99U);
}

}  // namespace
}  // namespace entourage::dds

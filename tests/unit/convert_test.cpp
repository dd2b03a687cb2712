// Topic samples to and from the model, and the checks that refuse bad samples.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dds/convert.hpp"
#include "traffic/carried_states.hpp"
#include "dds_test_util.hpp"

namespace entourage::dds {
namespace {

using testing::limits;
using testing::road_config;

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
  v.driver.car_following.coolness = 0.99;
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
  EXPECT_DOUBLE_EQ(b.driver.car_following.coolness, 0.99);
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

TEST(Convert, AVehicleStateCarriesItsLaneChangeAndGivesTheOwnersRecordBack) {
  const Road road(road_config());
  Vehicle v = sample_vehicle();
  v.direction = Direction::kForward;
  v.lane_change = {0, 1, LaneChangePhase::kMoving, 1.25, 4.5, 0.0, 0.0};
  v.control.mode = ControlMode::kControlled;
  v.control.indicator = 2;
  const VehicleReport r{v, Region::kOuterFront};
  const msg::VehicleState m = to_msg(r, ServiceId{Role::kMeso, 0}, 5, 0.5, road);
  EXPECT_FALSE(check(m, limits()).has_value());
  const VehicleReport back = report_from_msg(m);
  EXPECT_TRUE(same_state(back, r));
  EXPECT_EQ(to_msg(back, ServiceId{Role::kMeso, 0}, 5, 0.5, road), m);
  msg::VehicleState bad = m;
  bad.lane_change_phase(3);
  EXPECT_NE(check(bad, limits()).value_or("").find("lane change phase"), std::string::npos);
  bad = m;
  bad.lane_change_duration_s(0.0);
  EXPECT_NE(check(bad, limits()).value_or("").find("positive duration"), std::string::npos);
  bad = m;
  bad.lane_change_elapsed_s(std::numeric_limits<double>::infinity());
  EXPECT_NE(check(bad, limits()).value_or("").find("not finite"), std::string::npos);
  bad = m;
  bad.lane_change_to(7);
  EXPECT_NE(check(bad, limits()).value_or("").find("lane change: target lane 7"), std::string::npos);
  bad = m;
  bad.control_indicator(4);
  EXPECT_NE(check(bad, limits()).value_or("").find("indicator 4"), std::string::npos);
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
  h.handoff_sequence(1);
  EXPECT_FALSE(check(h, limits()).has_value());
  h.driver().coolness(1.0);  // the ACC model without IDM: no desired gap at all
  EXPECT_EQ(check(h, limits()).value_or(""), "coolness must be in [0, 1)");
}

ActorControl sample_control() {
  ActorControl c;
  c.mode = ControlMode::kControlled;
  c.play_id = 3;
  c.speed_mps = 22.5;
  c.accel_mps2 = 1.25;
  c.decel_mps2 = 4.5;
  c.max_jerk_mps3 = 1.5;
  c.lane = 1;
  c.force_lane = true;
  c.lane_change_duration_s = 2.5;
  c.indicator = 1;
  return c;
}

void expect_same_control(const ActorControl& b, const ActorControl& a) {
  EXPECT_EQ(b.mode, a.mode);
  EXPECT_EQ(b.play_id, a.play_id);
  EXPECT_EQ(b.speed_mps, a.speed_mps);
  EXPECT_EQ(b.accel_mps2, a.accel_mps2);
  EXPECT_EQ(b.decel_mps2, a.decel_mps2);
  EXPECT_EQ(b.max_jerk_mps3, a.max_jerk_mps3);
  EXPECT_EQ(b.lane, a.lane);
  EXPECT_EQ(b.force_lane, a.force_lane);
  EXPECT_EQ(b.lane_change_duration_s, a.lane_change_duration_s);
  EXPECT_EQ(b.indicator, a.indicator);
}

TEST(Convert, HandoffCarriesTheActorControl) {
  const Road road(road_config());
  Vehicle v = sample_vehicle();
  v.control = sample_control();
  const msg::Handoff m =
      to_msg(make_handoff(v, 12, ServiceId{Role::kMeso, 1}, Role::kMicro, Region::kInner, HandoffReason::kBorder), 1.2,
             road);
  EXPECT_FALSE(check(m, limits()).has_value());
  EXPECT_EQ(m.control().mode(), 2);
  expect_same_control(from_msg(m).vehicle.control, v.control);
  // An everyday vehicle: autonomous, with the defaults of ActorControl.
  const Handoff plain = from_msg(to_msg(
      make_handoff(sample_vehicle(), 12, ServiceId{Role::kMeso, 1}, Role::kMicro, Region::kInner, HandoffReason::kBorder),
      1.2, road));
  expect_same_control(plain.vehicle.control, ActorControl{});
  EXPECT_FALSE(plain.vehicle.control.active());
}

TEST(Convert, ABirthFromTheDirectorPassesTheChecks) {
  const Road road(road_config());
  Vehicle v = sample_vehicle();
  v.id = kDirectorFirstVehicleId;
  v.handoff_sequence = 0;  // a new vehicle, as the generator makes them
  v.control = sample_control();
  v.control.mode = ControlMode::kTransported;
  const msg::Handoff m = to_msg(
      make_handoff(v, 40, ServiceId{Role::kDirector, 0}, Role::kMeso, Region::kOuterFront, HandoffReason::kDirector),
      4.0, road);
  EXPECT_EQ(m.handoff_sequence(), 1U);
  EXPECT_FALSE(check(m, limits()).has_value());
  const Handoff back = from_msg(m);
  EXPECT_EQ(back.from, (ServiceId{Role::kDirector, 0}));
  EXPECT_EQ(back.reason, HandoffReason::kDirector);
  EXPECT_EQ(back.vehicle.control.mode, ControlMode::kTransported);
}

TEST(Convert, AHandoffWithABadControlIsRefused) {
  const Road road(road_config());
  Vehicle v = sample_vehicle();
  v.control = sample_control();
  const msg::Handoff good =
      to_msg(make_handoff(v, 1, ServiceId{Role::kMicro, 0}, Role::kMeso, Region::kOuterRear, HandoffReason::kBorder),
             0.1, road);
  msg::Handoff mode = good;
  mode.control().mode(5);
  EXPECT_NE(check(mode, limits())->find("control mode 5"), std::string::npos);
  msg::Handoff nan = good;
  nan.control().speed_mps(std::numeric_limits<double>::infinity());
  EXPECT_NE(check(nan, limits())->find("not finite"), std::string::npos);
  msg::Handoff rate = good;
  rate.control().decel_mps2(0.0);
  EXPECT_NE(check(rate, limits())->find("deceleration"), std::string::npos);
}

TEST(Convert, VehicleStateCarriesTheControlMode) {
  const Road road(road_config());
  Vehicle v = sample_vehicle();
  v.control.mode = ControlMode::kReleasing;
  const msg::VehicleState m = to_msg(VehicleReport{v, Region::kInner}, ServiceId{Role::kMicro, 0}, 5, 0.5, road);
  EXPECT_EQ(m.control(), 3);
  EXPECT_FALSE(check(m, limits()).has_value());
  EXPECT_EQ(from_msg(m).control, ControlMode::kReleasing);
  const msg::VehicleState plain =
      to_msg(VehicleReport{sample_vehicle(), Region::kInner}, ServiceId{Role::kMicro, 0}, 5, 0.5, road);
  EXPECT_EQ(plain.control(), 0);
  EXPECT_EQ(from_msg(plain).control, ControlMode::kAutonomous);
  msg::VehicleState bad = m;
  bad.control(5);
  EXPECT_NE(check(bad, limits())->find("control mode 5"), std::string::npos);
}

TEST(Convert, ActorCommandRoundTrip) {
  ActorCommand c;
  c.vehicle = 77;
  c.step = 120;
  c.control = sample_control();
  const msg::ActorCommand m = to_msg(c, 12.0);
  EXPECT_EQ(m.vehicle_id(), 77U);
  EXPECT_EQ(m.step(), 120U);
  EXPECT_EQ(m.time_s(), 12.0);
  EXPECT_FALSE(check(m, limits()).has_value());
  const ActorCommand back = from_msg(m);
  EXPECT_EQ(back.vehicle, 77U);
  EXPECT_EQ(back.step, 120U);
  expect_same_control(back.control, c.control);
}

// The director's withdrawal (a gap in the oncoming traffic) carries no speed or rates of its own.
TEST(Convert, AWithdrawalCommandRoundTrips) {
  ActorCommand c;
  c.vehicle = 78;
  c.step = 121;
  c.control.mode = ControlMode::kWithdrawn;
  c.control.play_id = 3;
  const msg::ActorCommand m = to_msg(c, 12.1);
  EXPECT_EQ(m.mode(), 4);
  EXPECT_FALSE(check(m, limits()).has_value());
  expect_same_control(from_msg(m).control, c.control);
}

TEST(Convert, BadActorCommandsAreRefusedWithAReason) {
  ActorCommand c;
  c.vehicle = 77;
  c.step = 120;
  c.control = sample_control();
  const msg::ActorCommand good = to_msg(c, 12.0);
  auto reason = [](const msg::ActorCommand& m) { return check(m, limits()).value_or("accepted"); };
  msg::ActorCommand m = good;
  m.accel_mps2(std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(reason(m).find("not finite"), std::string::npos);
  m = good;
  m.time_s(std::numeric_limits<double>::infinity());
  EXPECT_NE(reason(m).find("not finite"), std::string::npos);
  m = good;
  m.mode(5);
  EXPECT_EQ(reason(m), "unknown control mode 5");
  m = good;
  m.indicator(3);
  EXPECT_NE(reason(m).find("indicator 3"), std::string::npos);
  m = good;
  m.accel_mps2(0.0);
  EXPECT_NE(reason(m).find("(0, 15] m/s^2"), std::string::npos);
  m = good;
  m.decel_mps2(15.5);
  EXPECT_NE(reason(m).find("(0, 15] m/s^2"), std::string::npos);
  m.decel_mps2(15.0);
  EXPECT_EQ(reason(m), "accepted");
  m = good;
  m.mode(static_cast<uint8_t>(ControlMode::kReleasing));  // the rates matter only under control
  m.accel_mps2(0.0);
  EXPECT_EQ(reason(m), "accepted");
  m.max_jerk_mps3(0.0);
  EXPECT_NE(reason(m).find("jerk"), std::string::npos);
  m = good;
  m.mode(static_cast<uint8_t>(ControlMode::kControlled));
  m.speed_mps(-1.0);
  EXPECT_NE(reason(m).find("speed"), std::string::npos);
  // Transported at the driver's own desired speed: the one negative value taken.
  m.mode(static_cast<uint8_t>(ControlMode::kTransported));
  m.speed_mps(kOwnDesiredSpeed_mps);
  EXPECT_EQ(reason(m), "accepted");
  m.speed_mps(-0.5);
  EXPECT_NE(reason(m).find("speed"), std::string::npos);
  m.speed_mps(100.0);
  EXPECT_NE(reason(m).find("speed"), std::string::npos);
  m.speed_mps(99.9);
  EXPECT_EQ(reason(m), "accepted");
  m = good;
  m.lane(-2);
  EXPECT_NE(reason(m).find("lane -2"), std::string::npos);
  m.lane(16);
  EXPECT_NE(reason(m).find("lane 16"), std::string::npos);
  m.lane(-1);
  EXPECT_EQ(reason(m), "accepted");
  m.lane(15);
  EXPECT_EQ(reason(m), "accepted");
  m = good;
  m.lane_change_duration_s(-0.5);
  EXPECT_NE(reason(m).find("duration"), std::string::npos);
  m = good;
  m.vehicle_id(kEgoVehicleId);
  EXPECT_NE(reason(m).find("ego"), std::string::npos);
}

TEST(Convert, StepDoneCountsRoundTrip) {
  TopicCounts c{};
  c[static_cast<std::size_t>(Topic::kVehicleState)] = 12;
  c[static_cast<std::size_t>(Topic::kHandoff)] = 3;
  c[static_cast<std::size_t>(Topic::kPlayStatus)] = 1;
  c[static_cast<std::size_t>(Topic::kActorCommand)] = 2;
  const msg::StepDone m = make_step_done(ServiceId{Role::kMeso, 1}, 99, c, 40);
  EXPECT_EQ(counts_of(m), c);
  EXPECT_EQ(m.actor_commands(), 2U);
  EXPECT_EQ(m.owned_vehicles(), 40U);
  EXPECT_EQ(m.step(), 99U);
}

}  // namespace
}  // namespace entourage::dds

namespace entourage::dds {
namespace {

using testing::limits;

TEST(Convert, BadPlayStatusIsRefusedWithAReason) {
  msg::PlayStatus good;
  good.play_id(1);
  good.step(300);
  good.time_s(30.0);
  good.phase(3);
  good.ego_s_m(3200.0);
  good.trigger1_s_m(3000.0);
  good.trigger2_s_m(5000.0);
  good.estimated_start_time_s(95.0);
  good.position_error_m(12.0);
  good.speed_error_mps(1.5);
  auto reason = [](const msg::PlayStatus& m) { return check(m, limits()).value_or("accepted"); };
  EXPECT_EQ(reason(good), "accepted");
  msg::PlayStatus m = good;
  m.phase(kPlayPhases);
  EXPECT_EQ(reason(m), "unknown play phase 8");
  m = good;
  m.ego_s_m(std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(reason(m).find("not finite"), std::string::npos);
  m = good;
  m.position_error_m(-1.0);
  EXPECT_NE(reason(m).find("negative error"), std::string::npos);
  m = good;
  m.estimated_start_time_s(-1.0);  // unknown
  EXPECT_EQ(reason(m), "accepted");
  m.estimated_start_time_s(-3.0);
  EXPECT_NE(reason(m).find("estimated start time"), std::string::npos);
}

}  // namespace
}  // namespace entourage::dds

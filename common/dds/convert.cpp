#include "dds/convert.hpp"

#include <cmath>
#include <initializer_list>

#include "traffic/lateral.hpp"

namespace entourage::dds {

namespace {

Direction direction_of(int d) { return d < 0 ? Direction::kBackward : Direction::kForward; }

bool all_finite(std::initializer_list<double> xs) {
  for (double x : xs) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

std::optional<std::string> check_lane(int direction, int lane, int target_lane, const SampleLimits& l) {
  if (direction != 1 && direction != -1) return "direction " + std::to_string(direction) + " is not +1 or -1";
  const int own = direction == 1 ? l.lanes_forward : l.lanes_backward;
  const int lanes = l.two_way ? l.lanes_forward + l.lanes_backward : own;
  if (lane < 0 || lane >= lanes) return "lane " + std::to_string(lane) + " does not exist";
  if (target_lane < 0 || target_lane >= lanes) return "target lane " + std::to_string(target_lane) + " does not exist";
  return std::nullopt;
}

std::optional<std::string> check_motion(double speed, double accel, const SampleLimits& l) {
  if (speed < 0.0 || speed > l.max_speed_mps) return "speed " + std::to_string(speed) + " m/s out of range";
  if (std::abs(accel) > l.max_abs_accel_mps2) return "acceleration " + std::to_string(accel) + " m/s^2 out of range";
  return std::nullopt;
}

// The control of an actor, in the fields ActorCommand and ActorControlRecord share.
template <class M>
ActorControl control_of(const M& m) {
  ActorControl c;
  c.mode = static_cast<ControlMode>(m.mode());
  c.play_id = m.play_id();
  c.speed_mps = m.speed_mps();
  c.accel_mps2 = m.accel_mps2();
  c.decel_mps2 = m.decel_mps2();
  c.max_jerk_mps3 = m.max_jerk_mps3();
  c.lane = m.lane();
  c.force_lane = m.force_lane();
  c.lane_change_duration_s = m.lane_change_duration_s();
  c.indicator = m.indicator();
  return c;
}

template <class M>
void set_control(M& m, const ActorControl& c) {
  m.mode(static_cast<uint8_t>(c.mode));
  m.play_id(c.play_id);
  m.speed_mps(c.speed_mps);
  m.accel_mps2(c.accel_mps2);
  m.decel_mps2(c.decel_mps2);
  m.max_jerk_mps3(c.max_jerk_mps3);
  m.lane(static_cast<int16_t>(c.lane));
  m.force_lane(c.force_lane);
  m.lane_change_duration_s(c.lane_change_duration_s);
  m.indicator(c.indicator);
}

constexpr int kMaxControlMode = static_cast<int>(ControlMode::kWithdrawn);
constexpr int kMaxIndicator = 2;               // 0 off, 1 left, 2 right
constexpr double kMaxControlRate_mps2 = 15.0;  // a controlled actor's acceleration and deceleration
constexpr int kMaxControlLane = 15;            // lane index in the vehicle's own direction

std::optional<std::string> check_control_mode(int mode) {
  if (mode > kMaxControlMode) return "unknown control mode " + std::to_string(mode);
  return std::nullopt;
}

// The checks an actor's control passes, in a command or carried by a handoff.
template <class M>
std::optional<std::string> check_control(const M& m, const SampleLimits& l) {
  if (!all_finite({m.speed_mps(), m.accel_mps2(), m.decel_mps2(), m.max_jerk_mps3(), m.lane_change_duration_s()})) {
    return "a control value is not finite";
  }
  if (auto e = check_control_mode(m.mode())) return e;
  if (m.indicator() > kMaxIndicator) return "indicator " + std::to_string(m.indicator()) + " is not 0, 1 or 2";
  const bool own_speed = m.mode() == static_cast<int>(ControlMode::kTransported) && m.speed_mps() == kOwnDesiredSpeed_mps;
  if (!own_speed && (m.speed_mps() < 0.0 || m.speed_mps() >= l.max_speed_mps)) {
    return "control speed " + std::to_string(m.speed_mps()) + " m/s out of range";
  }
  if (m.lane() < -1 || m.lane() > kMaxControlLane) return "control lane " + std::to_string(m.lane()) + " out of range";
  if (m.lane_change_duration_s() < 0.0) return "lane change duration must not be negative";
  const auto mode = static_cast<ControlMode>(m.mode());
  if (mode == ControlMode::kControlled) {
    for (double rate : {m.accel_mps2(), m.decel_mps2()}) {
      if (rate <= 0.0 || rate > kMaxControlRate_mps2) {
        return "controlled acceleration and deceleration must be in (0, 15] m/s^2, not " + std::to_string(rate);
      }
    }
  }
  if ((mode == ControlMode::kTransported || mode == ControlMode::kReleasing) && m.max_jerk_mps3() <= 0.0) {
    return "the jerk limit must be positive";
  }
  return std::nullopt;
}

}  // namespace

EgoObservation from_msg(const msg::EgoState& m) {
  EgoObservation e;
  e.step = m.step();
  e.time_s = m.time_s();
  e.direction = direction_of(m.direction());
  e.lane = m.lane();
  e.target_lane = m.target_lane();
  e.indicator = m.indicator();
  e.s_m = m.s_m();
  e.d_m = m.d_m();
  e.speed_mps = m.speed_mps();
  e.accel_mps2 = m.accel_mps2();
  e.length_m = m.length_m();
  e.width_m = m.width_m();
  return e;
}

msg::EgoState to_msg(const EgoObservation& e, const Road& road) {
  msg::EgoState m;
  m.ego_id(kEgoVehicleId);
  m.step(e.step);
  m.time_s(e.time_s);
  m.direction(static_cast<int16_t>(sign(e.direction)));
  m.lane(static_cast<int16_t>(e.lane));
  m.target_lane(static_cast<int16_t>(e.target_lane));
  m.indicator(e.indicator);
  m.s_m(e.s_m);
  m.d_m(e.d_m);
  const Pose pose = road.pose(e.s_m, e.d_m, e.direction);
  m.x_m(pose.x_m);
  m.y_m(pose.y_m);
  m.heading_rad(pose.heading_rad);
  m.speed_mps(e.speed_mps);
  m.accel_mps2(e.accel_mps2);
  m.length_m(e.length_m);
  m.width_m(e.width_m);
  return m;
}

ObservedVehicle from_msg(const msg::VehicleState& m) {
  ObservedVehicle v;
  v.id = m.id();
  v.owner = ServiceId::from_code(m.owner());
  v.step = m.step();
  v.direction = direction_of(m.direction());
  v.lane = m.lane();
  v.target_lane = m.target_lane();
  v.type_index = m.type_index();
  v.indicator = m.indicator();
  v.control = static_cast<ControlMode>(m.control());
  v.s_m = m.s_m();
  v.d_m = m.d_m();
  v.speed_mps = m.speed_mps();
  v.accel_mps2 = m.accel_mps2();
  v.length_m = m.length_m();
  v.width_m = m.width_m();
  return v;
}

msg::VehicleState to_msg(const VehicleReport& r, ServiceId owner, Step step, double time_s, const Road& road) {
  msg::VehicleState m;
  m.id(r.id);
  m.step(step);
  m.time_s(time_s);
  m.owner(owner.code());
  m.region(static_cast<uint8_t>(r.region));
  m.type_index(r.type_index);
  m.indicator(static_cast<uint8_t>(r.indicator));
  m.control(static_cast<uint8_t>(r.control));
  m.direction(static_cast<int16_t>(sign(r.direction)));
  m.lane(static_cast<int16_t>(r.lane));
  m.target_lane(static_cast<int16_t>(r.target_lane));
  m.s_m(r.s_m);
  const double d = lateral_offset_m(road, r);
  m.d_m(d);
  const Pose pose = road.pose(r.s_m, d, r.direction);
  m.x_m(pose.x_m);
  m.y_m(pose.y_m);
  m.heading_rad(pose.heading_rad);
  m.speed_mps(r.speed_mps);
  m.accel_mps2(r.accel_mps2);
  m.length_m(r.length_m);
  m.width_m(r.width_m);
  m.lane_change_phase(static_cast<uint8_t>(r.lane_change.phase));
  m.lane_change_from(static_cast<int16_t>(r.lane_change.from_lane));
  m.lane_change_to(static_cast<int16_t>(r.lane_change.to_lane));
  m.lane_change_elapsed_s(r.lane_change.phase_elapsed_s);
  m.lane_change_duration_s(r.lane_change.duration_s);
  m.control_indicator(static_cast<uint8_t>(r.control_indicator));
  return m;
}

VehicleReport report_from_msg(const msg::VehicleState& m) {
  VehicleReport r;
  r.id = m.id();
  r.region = static_cast<Region>(m.region());
  r.type_index = m.type_index();
  r.direction = direction_of(m.direction());
  r.indicator = static_cast<Indicator>(m.indicator());
  r.control = static_cast<ControlMode>(m.control());
  r.lane = m.lane();
  r.target_lane = m.target_lane();
  r.s_m = m.s_m();
  r.speed_mps = m.speed_mps();
  r.accel_mps2 = m.accel_mps2();
  r.length_m = m.length_m();
  r.width_m = m.width_m();
  r.lane_change.phase = static_cast<LaneChangePhase>(m.lane_change_phase());
  r.lane_change.from_lane = m.lane_change_from();
  r.lane_change.to_lane = m.lane_change_to();
  r.lane_change.phase_elapsed_s = m.lane_change_elapsed_s();
  r.lane_change.duration_s = m.lane_change_duration_s();
  r.lateral_fraction = r.lane_change.lateral_fraction();  // as the owner's record has it
  r.control_indicator = static_cast<Indicator>(m.control_indicator());
  return r;
}

Handoff from_msg(const msg::Handoff& m) {
  Handoff h;
  Vehicle& v = h.vehicle;
  v.id = m.vehicle_id();
  v.handoff_sequence = m.handoff_sequence();
  v.type_index = m.type_index();
  v.direction = direction_of(m.direction());
  v.lane = m.lane();
  v.s_m = m.s_m();
  v.speed_mps = m.speed_mps();
  v.accel_mps2 = m.accel_mps2();
  v.length_m = m.length_m();
  v.width_m = m.width_m();
  const msg::LaneChange& lc = m.lane_change();
  v.lane_change.from_lane = lc.from_lane();
  v.lane_change.to_lane = lc.to_lane();
  v.lane_change.phase = static_cast<LaneChangePhase>(lc.phase());
  v.lane_change.phase_elapsed_s = lc.phase_elapsed_s();
  v.lane_change.duration_s = lc.duration_s();
  v.lane_change.since_last_change_s = lc.since_last_change_s();
  v.lane_change.decision_wait_s = lc.decision_wait_s();
  const msg::DriverRecord& d = m.driver();
  DriverParams& p = v.driver;
  p.car_following.model = static_cast<CarFollowingModel>(d.car_following_model());
  p.lane_change = static_cast<LaneChangeModel>(d.lane_change_model());
  p.car_following.idm = {d.desired_speed_mps(), d.time_gap_s(), d.max_accel_mps2(), d.comfort_decel_mps2(),
                         d.min_gap_m(), d.accel_exponent()};
  p.car_following.beta = d.beta();
  p.car_following.coolness = d.coolness();
  p.car_following.gipps = {d.gipps_reaction_time_s(), d.gipps_max_decel_mps2(), d.gipps_leader_decel_estimate_mps2()};
  p.car_following.human_driver = d.human_driver();
  p.car_following.hdm = {d.hdm_reaction_time_s(), d.hdm_anticipated_leaders(), d.hdm_distance_error(),
                         d.hdm_inverse_ttc_error_per_s(), d.hdm_error_persistence_s()};
  p.mobil = {d.politeness(), d.change_threshold_mps2(), d.right_bias_mps2(), d.safe_decel_mps2()};
  p.max_decel_mps2 = d.max_decel_mps2();
  p.lane_change_duration_s = d.lane_change_duration_s();
  p.desired_speed_median_mps = d.desired_speed_median_mps();
  p.keep_right = d.keep_right();
  p.rng_state = d.rng_state();
  v.hdm_errors = {d.hdm_w_distance(), d.hdm_w_approach()};
  v.requested_lane = m.requested_lane();
  v.control = control_of(m.control());
  h.step = m.step();
  h.from = ServiceId::from_code(m.from_service());
  h.to_role = static_cast<Role>(m.to_role());
  h.to_region = static_cast<Region>(m.to_region());
  h.reason = static_cast<HandoffReason>(m.reason());
  return h;
}

msg::Handoff to_msg(const Handoff& h, double time_s, const Road& road) {
  const Vehicle& v = h.vehicle;
  msg::Handoff m;
  m.vehicle_id(v.id);
  m.handoff_sequence(v.handoff_sequence);
  m.step(h.step);
  m.time_s(time_s);
  m.from_service(h.from.code());
  m.to_role(static_cast<uint8_t>(h.to_role));
  m.to_region(static_cast<uint8_t>(h.to_region));
  m.reason(static_cast<uint8_t>(h.reason));
  m.type_index(v.type_index);
  m.direction(static_cast<int16_t>(sign(v.direction)));
  m.lane(static_cast<int16_t>(v.lane));
  m.s_m(v.s_m);
  m.d_m(lateral_offset_m(road, v));
  m.speed_mps(v.speed_mps);
  m.accel_mps2(v.accel_mps2);
  m.length_m(v.length_m);
  m.width_m(v.width_m);
  msg::LaneChange& lc = m.lane_change();
  lc.from_lane(static_cast<int16_t>(v.lane_change.from_lane));
  lc.to_lane(static_cast<int16_t>(v.lane_change.to_lane));
  lc.phase(static_cast<uint8_t>(v.lane_change.phase));
  lc.phase_elapsed_s(v.lane_change.phase_elapsed_s);
  lc.duration_s(v.lane_change.duration_s);
  lc.since_last_change_s(v.lane_change.since_last_change_s);
  lc.decision_wait_s(v.lane_change.decision_wait_s);
  const DriverParams& p = v.driver;
  msg::DriverRecord& d = m.driver();
  d.car_following_model(static_cast<uint8_t>(p.car_following.model));
  d.lane_change_model(static_cast<uint8_t>(p.lane_change));
  d.desired_speed_mps(p.car_following.idm.desired_speed_mps);
  d.desired_speed_median_mps(p.desired_speed_median_mps);
  d.time_gap_s(p.car_following.idm.time_gap_s);
  d.max_accel_mps2(p.car_following.idm.max_accel_mps2);
  d.comfort_decel_mps2(p.car_following.idm.comfort_decel_mps2);
  d.min_gap_m(p.car_following.idm.min_gap_m);
  d.accel_exponent(p.car_following.idm.accel_exponent);
  d.beta(p.car_following.beta);
  d.coolness(p.car_following.coolness);
  d.politeness(p.mobil.politeness);
  d.change_threshold_mps2(p.mobil.change_threshold_mps2);
  d.right_bias_mps2(p.mobil.right_bias_mps2);
  d.safe_decel_mps2(p.mobil.safe_decel_mps2);
  d.max_decel_mps2(p.max_decel_mps2);
  d.lane_change_duration_s(p.lane_change_duration_s);
  d.keep_right(p.keep_right);
  d.rng_state(p.rng_state);
  d.gipps_reaction_time_s(p.car_following.gipps.reaction_time_s);
  d.gipps_max_decel_mps2(p.car_following.gipps.max_decel_mps2);
  d.gipps_leader_decel_estimate_mps2(p.car_following.gipps.leader_decel_estimate_mps2);
  d.human_driver(p.car_following.human_driver);
  d.hdm_reaction_time_s(p.car_following.hdm.reaction_time_s);
  d.hdm_anticipated_leaders(static_cast<int16_t>(p.car_following.hdm.anticipated_leaders));
  d.hdm_distance_error(p.car_following.hdm.distance_error);
  d.hdm_inverse_ttc_error_per_s(p.car_following.hdm.inverse_ttc_error_per_s);
  d.hdm_error_persistence_s(p.car_following.hdm.error_persistence_s);
  d.hdm_w_distance(v.hdm_errors.w_distance);
  d.hdm_w_approach(v.hdm_errors.w_approach);
  m.requested_lane(static_cast<int16_t>(v.requested_lane));
  set_control(m.control(), v.control);
  return m;
}

ActorCommand from_msg(const msg::ActorCommand& m) {
  ActorCommand c;
  c.vehicle = m.vehicle_id();
  c.step = m.step();
  c.control = control_of(m);
  return c;
}

msg::ActorCommand to_msg(const ActorCommand& c, double time_s) {
  msg::ActorCommand m;
  m.vehicle_id(c.vehicle);
  m.step(c.step);
  m.time_s(time_s);
  set_control(m, c.control);
  return m;
}

msg::StepDone make_step_done(ServiceId service, Step step, const TopicCounts& written, std::uint32_t owned) {
  msg::StepDone m;
  m.service(service.code());
  m.step(step);
  m.ego_states(written[static_cast<std::size_t>(Topic::kEgoState)]);
  m.vehicle_states(written[static_cast<std::size_t>(Topic::kVehicleState)]);
  m.handoffs(written[static_cast<std::size_t>(Topic::kHandoff)]);
  m.play_status(written[static_cast<std::size_t>(Topic::kPlayStatus)]);
  m.actor_commands(written[static_cast<std::size_t>(Topic::kActorCommand)]);
  m.owned_vehicles(owned);
  return m;
}

TopicCounts counts_of(const msg::StepDone& m) {
  TopicCounts c{};
  c[static_cast<std::size_t>(Topic::kEgoState)] = m.ego_states();
  c[static_cast<std::size_t>(Topic::kVehicleState)] = m.vehicle_states();
  c[static_cast<std::size_t>(Topic::kHandoff)] = m.handoffs();
  c[static_cast<std::size_t>(Topic::kPlayStatus)] = m.play_status();
  c[static_cast<std::size_t>(Topic::kActorCommand)] = m.actor_commands();
  return c;
}

SampleLimits SampleLimits::of(const ScenarioConfig& sc) {
  SampleLimits l;
  l.lanes_forward = sc.road.lanes_forward;
  l.lanes_backward = sc.road.lanes_backward;
  l.vehicle_types = static_cast<int>(sc.vehicle_types.size());
  l.two_way = sc.road.kind == RoadKind::kRural;
  return l;
}

std::optional<std::string> check(const msg::EgoState& m, const SampleLimits& limits) {
  if (!all_finite({m.time_s(), m.s_m(), m.d_m(), m.x_m(), m.y_m(), m.heading_rad(), m.speed_mps(), m.accel_mps2(),
                   m.length_m(), m.width_m()})) {
    return "a value is not finite";
  }
  if (auto e = check_lane(m.direction(), m.lane(), m.target_lane(), limits)) return e;
  if (auto e = check_motion(m.speed_mps(), m.accel_mps2(), limits)) return e;
  if (m.length_m() <= 0.0 || m.width_m() <= 0.0) return "length and width must be positive";
  return std::nullopt;
}

// The lane change a vehicle state carries (for a reader that carries the state forward).
std::optional<std::string> check_lane_change(const msg::VehicleState& m, const SampleLimits& limits) {
  if (m.lane_change_phase() > static_cast<uint8_t>(LaneChangePhase::kMoving)) {
    return "unknown lane change phase " + std::to_string(m.lane_change_phase());
  }
  if (m.lane_change_phase() == 0) return std::nullopt;
  if (auto e = check_lane(m.direction(), m.lane_change_from(), m.lane_change_to(), limits)) return "lane change: " + *e;
  if (m.lane_change_elapsed_s() < 0.0) return "a lane change's elapsed time is negative";
  const bool moving = m.lane_change_phase() == static_cast<uint8_t>(LaneChangePhase::kMoving);
  if (moving && m.lane_change_duration_s() <= 0.0) return "a lane change under way must have a positive duration";
  return std::nullopt;
}

std::optional<std::string> check(const msg::VehicleState& m, const SampleLimits& limits) {
  if (!all_finite({m.time_s(), m.s_m(), m.d_m(), m.x_m(), m.y_m(), m.heading_rad(), m.speed_mps(), m.accel_mps2(),
                   m.length_m(), m.width_m(), m.lane_change_elapsed_s(), m.lane_change_duration_s()})) {
    return "a value is not finite";
  }
  if (m.id() == kEgoVehicleId) return "vehicle id 0 is reserved for the ego";
  if (auto e = check_lane(m.direction(), m.lane(), m.target_lane(), limits)) return e;
  if (auto e = check_motion(m.speed_mps(), m.accel_mps2(), limits)) return e;
  if (m.type_index() >= limits.vehicle_types) return "unknown vehicle type " + std::to_string(m.type_index());
  if (m.length_m() <= 0.0 || m.width_m() <= 0.0) return "length and width must be positive";
  if (auto e = check_control_mode(m.control())) return e;
  if (auto e = check_lane_change(m, limits)) return e;
  if (m.control_indicator() > kMaxIndicator) {
    return "indicator " + std::to_string(m.control_indicator()) + " is not 0, 1 or 2";
  }
  return std::nullopt;
}

std::optional<std::string> check(const msg::Handoff& m, const SampleLimits& limits) {
  if (!all_finite({m.time_s(), m.s_m(), m.speed_mps(), m.accel_mps2(), m.length_m(), m.width_m(),
                   m.driver().desired_speed_mps(), m.driver().time_gap_s(), m.driver().max_accel_mps2(),
                   m.driver().comfort_decel_mps2(), m.driver().min_gap_m()})) {
    return "a value is not finite";
  }
  if (m.vehicle_id() == kEgoVehicleId) return "vehicle id 0 is reserved for the ego";
  if (m.handoff_sequence() == 0) return "handoff sequence numbers start at 1";
  const int lane_to = m.lane_change().phase() == 0 ? m.lane() : m.lane_change().to_lane();
  if (auto e = check_lane(m.direction(), m.lane(), lane_to, limits)) return e;
  if (auto e = check_motion(m.speed_mps(), m.accel_mps2(), limits)) return e;
  if (m.type_index() >= limits.vehicle_types) return "unknown vehicle type " + std::to_string(m.type_index());
  if (m.driver().desired_speed_mps() <= 0.0 || m.driver().time_gap_s() <= 0.0 || m.driver().max_accel_mps2() <= 0.0 ||
      m.driver().comfort_decel_mps2() <= 0.0) {
    return "driver parameters must be positive";
  }
  if (!(m.driver().coolness() >= 0.0 && m.driver().coolness() < 1.0)) return "coolness must be in [0, 1)";
  if (auto e = check_control(m.control(), limits)) return e;
  return std::nullopt;
}

std::optional<std::string> check(const msg::ActorCommand& m, const SampleLimits& limits) {
  if (!std::isfinite(m.time_s())) return "a value is not finite";
  if (m.vehicle_id() == kEgoVehicleId) return "vehicle id 0 is the ego, which the director cannot command";
  return check_control(m, limits);
}

std::optional<std::string> check(const msg::PlayStatus& m, const SampleLimits& /*limits*/) {
  for (double x : {m.time_s(), m.ego_s_m(), m.trigger1_s_m(), m.trigger2_s_m(), m.estimated_start_time_s(),
                   m.position_error_m(), m.speed_error_mps()}) {
    if (!std::isfinite(x)) return "a value is not finite";
  }
  if (m.phase() >= kPlayPhases) return "unknown play phase " + std::to_string(m.phase());
  if (m.position_error_m() < 0.0 || m.speed_error_mps() < 0.0) return "a negative error (errors are magnitudes)";
  if (m.estimated_start_time_s() < 0.0 && m.estimated_start_time_s() != -1.0) {
    return "estimated start time " + std::to_string(m.estimated_start_time_s()) + " (a time, or -1 for unknown)";
  }
  return std::nullopt;
}

}  // namespace entourage::dds

#include "recording/tables.hpp"

#include <algorithm>
#include <charconv>
#include <string_view>

#include "core/ids.hpp"
#include "traffic/actor_control.hpp"
#include "traffic/handoff.hpp"

namespace entourage::recording {

namespace {

const char* role_name(std::uint8_t role) {
  switch (static_cast<Role>(role)) {
    case Role::kNone: return "none";
    case Role::kMicro: return "micro";
    case Role::kMeso: return "meso";
    case Role::kDirector: return "director";
    default: return "other";
  }
}

HandoffRow handoff_row(const msg::Handoff& h) {
  return {h.step(),
          h.time_s(),
          h.vehicle_id(),
          h.handoff_sequence(),
          to_string(ServiceId::from_code(h.from_service())),
          role_name(h.to_role()),
          to_string(static_cast<Region>(h.to_region())),
          to_string(static_cast<HandoffReason>(h.reason())),
          h.lane(),
          h.s_m(),
          h.speed_mps()};
}

PlayRow play_row(const msg::PlayStatus& p) {
  return {p.step(),   p.time_s(),   p.play_id(),          p.name().to_string(),
          p.phase(),  p.ego_s_m(),  p.estimated_start_time_s(), p.actors(),
          p.created(), p.cleared(), p.position_error_m(), p.speed_error_mps(),
          p.detail().to_string()};
}

const char* control_name(std::uint8_t mode) { return to_string(static_cast<ControlMode>(mode)); }

CommandRow command_row(const msg::ActorCommand& c) {
  CommandRow row;
  row.step = c.step();
  row.time_s = c.time_s();
  row.vehicle_id = c.vehicle_id();
  row.play_id = c.play_id();
  row.mode = control_name(c.mode());
  row.speed_mps = c.speed_mps();
  row.accel_mps2 = c.accel_mps2();
  row.decel_mps2 = c.decel_mps2();
  row.max_jerk_mps3 = c.max_jerk_mps3();
  row.lane = c.lane();
  row.force_lane = c.force_lane();
  row.lane_change_duration_s = c.lane_change_duration_s();
  row.indicator = c.indicator();
  return row;
}

}  // namespace

Tables tables_from(const Recording& r, const std::vector<std::string>& type_names) {
  Tables t;
  t.info = r.info;
  t.undecodable = r.undecodable;
  t.vehicles.reserve(r.vehicles.size());
  for (const auto& m : r.vehicles) {
    VehicleRow row;
    row.step = m.step();
    row.time_s = m.time_s();
    row.id = m.id();
    row.owner = to_string(ServiceId::from_code(m.owner()));
    row.region = to_string(static_cast<Region>(m.region()));
    row.direction = m.direction();
    row.lane = m.lane();
    row.target_lane = m.target_lane();
    row.s_m = m.s_m();
    row.d_m = m.d_m();
    row.x_m = m.x_m();
    row.y_m = m.y_m();
    row.heading_rad = m.heading_rad();
    row.speed_mps = m.speed_mps();
    row.accel_mps2 = m.accel_mps2();
    row.length_m = m.length_m();
    row.width_m = m.width_m();
    row.type = m.type_index() < type_names.size() ? type_names[m.type_index()] : "type" + std::to_string(m.type_index());
    row.control = control_name(m.control());
    t.vehicles.push_back(std::move(row));
  }
  for (const auto& m : r.egos) {
    t.ego.push_back({m.step(), m.time_s(), m.s_m(), m.d_m(), m.x_m(), m.y_m(), m.heading_rad(), m.speed_mps(),
                     m.accel_mps2(), m.lane(), m.length_m(), m.width_m()});
  }
  for (const auto& h : r.handoffs) t.handoffs.push_back(handoff_row(h));
  for (const auto& p : r.plays) t.plays.push_back(play_row(p));
  for (const auto& c : r.commands) t.commands.push_back(command_row(c));
  sort_rows(t);
  return t;
}

void sort_rows(Tables& t) {
  std::stable_sort(t.vehicles.begin(), t.vehicles.end(),
                   [](const VehicleRow& a, const VehicleRow& b) { return a.step != b.step ? a.step < b.step : a.id < b.id; });
  std::stable_sort(t.ego.begin(), t.ego.end(), [](const EgoRow& a, const EgoRow& b) { return a.step < b.step; });
}

std::optional<Role> role_of_service(const std::string& name) {
  if (const auto id = service_from_name(name)) return id->role;
  if (name == "launcher") return Role::kLauncher;
  constexpr std::string_view kNumbered = "service-";  // to_string(ServiceId) of an unnamed service
  if (name.rfind(kNumbered, 0) != 0) return std::nullopt;
  unsigned code = 0;
  const char* first = name.data() + kNumbered.size();
  const char* last = name.data() + name.size();
  const auto [end, ec] = std::from_chars(first, last, code);
  if (ec != std::errc() || end != last || first == last || code > 0xFFFFU) return std::nullopt;
  return ServiceId::from_code(static_cast<std::uint16_t>(code)).role;
}

}  // namespace entourage::recording

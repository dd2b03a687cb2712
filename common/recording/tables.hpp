#pragma once
// A recording as plain rows, the shape of the CSV export (`entourage export`, csv_tables.hpp), so
// that every analysis and check runs the same on a recording and on its exported CSV files.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/ids.hpp"
#include "recording/recording.hpp"

namespace entourage::recording {

struct VehicleRow {
  std::uint64_t step = 0;
  double time_s = 0.0;
  std::uint32_t id = 0;
  std::string owner;   // service name
  std::string region;  // outer_rear, inner, outer_front, outside
  int direction = 1;
  int lane = 0;
  int target_lane = 0;  // = lane unless it moves sideways (not in the CSV export; read back as lane)
  double s_m = 0.0;
  double d_m = 0.0;
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_rad = 0.0;
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 0.0;
  double width_m = 0.0;
  std::string type;
  std::string control = "autonomous";  // its ControlMode: autonomous, transported, controlled, releasing
};

struct EgoRow {
  std::uint64_t step = 0;
  double time_s = 0.0;
  double s_m = 0.0;
  double d_m = 0.0;
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_rad = 0.0;
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  int lane = 0;
  double length_m = 4.6;  // not in ego.csv; the ego's size from the scenario
  double width_m = 1.8;
};

// An ownership change; names as in VehicleRow.
struct HandoffRow {
  std::uint64_t step = 0;
  double time_s = 0.0;
  std::uint32_t vehicle_id = 0;
  std::uint32_t sequence = 0;
  std::string from;       // service name
  std::string to_role;    // none (retired), micro, meso, director, other
  std::string to_region;  // outer_rear, inner, outer_front, outside
  std::string reason;     // birth, initial_fill, border, left_window, director, unknown
  int lane = 0;
  double s_m = 0.0;
  double speed_mps = 0.0;
};

// A play's status report from the director.
struct PlayRow {
  std::uint64_t step = 0;
  double time_s = 0.0;
  std::uint32_t play_id = 0;
  std::string name;
  std::uint32_t phase = 0;
  double ego_s_m = 0.0;
  double estimated_start_time_s = 0.0;
  std::uint32_t actors = 0;
  std::uint32_t created = 0;
  std::uint32_t cleared = 0;
  double position_error_m = 0.0;
  double speed_error_mps = 0.0;
  std::string detail;
};

// A command of the director to one of its actors (ActorCommand.idl).
struct CommandRow {
  std::uint64_t step = 0;  // the director's step that wrote it; applied at the next one
  double time_s = 0.0;
  std::uint32_t vehicle_id = 0;
  std::uint32_t play_id = 0;
  std::string mode;  // autonomous, transported, controlled, releasing (unknown for a bad value)
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double decel_mps2 = 0.0;
  double max_jerk_mps3 = 0.0;
  int lane = -1;  // -1 none
  bool force_lane = false;
  double lane_change_duration_s = 0.0;
  std::uint32_t indicator = 0;  // 0 off, 1 left, 2 right
};

struct Tables {
  RecordingInfo info;               // the run's settings and scenario text
  std::uint64_t undecodable = 0;    // recorded messages that did not decode
  std::vector<VehicleRow> vehicles;  // sorted by step, then id
  std::vector<EgoRow> ego;           // sorted by step
  std::vector<HandoffRow> handoffs;  // as recorded
  std::vector<PlayRow> plays;        // as recorded
  std::vector<CommandRow> commands;  // as recorded
};

// `type_names[i]` names vehicle type i (from the recorded scenario).
Tables tables_from(const Recording& r, const std::vector<std::string>& type_names);
// Sorts vehicles by step, then id, and the ego by step (stable: equal keys keep their order).
void sort_rows(Tables& t);
// The role of a service named as in VehicleRow::owner and HandoffRow::from (to_string(ServiceId));
// nullopt if no service has that name.
std::optional<Role> role_of_service(const std::string& name);

}  // namespace entourage::recording

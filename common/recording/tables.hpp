#pragma once
// A recording as plain rows, the shape of the CSV export (`entourage export`), so that every
// analysis and check runs the same on a recording and on its exported CSV files.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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

struct Tables {
  std::vector<VehicleRow> vehicles;  // sorted by step, then id
  std::vector<EgoRow> ego;           // sorted by step
};

// `type_names[i]` names vehicle type i (from the recorded scenario).
Tables tables_from(const Recording& r, const std::vector<std::string>& type_names);

// Writes DIR/vehicles.csv, DIR/ego.csv, DIR/handoffs.csv and DIR/plays.csv (creating DIR).
bool write_csv(const Recording& r, const Tables& t, const std::string& dir, std::string* error);
// Reads DIR/vehicles.csv and DIR/ego.csv back.
std::optional<Tables> read_csv(const std::string& dir, std::string* error);

extern const char* const kVehiclesHeader;
extern const char* const kEgoHeader;

}  // namespace entourage::recording

#include "recording/transitions.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/ids.hpp"
#include "traffic/handoff.hpp"

namespace entourage::recording {

namespace {

using RowsById = std::unordered_map<std::uint32_t, std::vector<const VehicleRow*>>;

RowsById rows_by_id(const Tables& t) {
  RowsById rows;
  for (const VehicleRow& r : t.vehicles) rows[r.id].push_back(&r);  // in step order: t.vehicles is sorted
  return rows;
}

bool owned_by(const VehicleRow& r, Role role) { return role_of_service(r.owner) == role; }

bool autonomous(const VehicleRow& r) { return r.control == "autonomous"; }

// Nearest-rank quantile of a sorted sample.
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

// The largest deceleration of a vehicle handed into micro at `step`, over its first rows in micro;
// nullopt when it is not seen there or drives under a command.
std::optional<double> largest_decel_in_micro(const std::vector<const VehicleRow*>& rows, std::uint64_t step,
                                             std::uint64_t window_steps) {
  std::optional<double> largest;
  for (const VehicleRow* r : rows) {
    if (r->step <= step) continue;
    if (r->step > step + window_steps || !owned_by(*r, Role::kMicro)) break;
    if (!autonomous(*r)) return std::nullopt;
    largest = std::max(largest.value_or(0.0), -r->accel_mps2);
  }
  return largest;
}

void into_micro(const HandoffRow& h, const RowsById& rows, std::uint64_t window_steps, std::vector<double>& decels) {
  const auto it = rows.find(h.vehicle_id);
  if (it == rows.end()) return;
  if (const auto d = largest_decel_in_micro(it->second, h.step, window_steps)) decels.push_back(*d);
}

void into_meso(const HandoffRow& h, const RowsById& rows, double step_s, IntoMeso& m, double& jump_sum) {
  const auto it = rows.find(h.vehicle_id);
  if (it == rows.end()) return;
  const VehicleRow* last_micro = nullptr;
  const VehicleRow* first_meso = nullptr;
  for (const VehicleRow* r : it->second) {
    if (r->step <= h.step && owned_by(*r, Role::kMicro)) last_micro = r;
    if (r->step > h.step && owned_by(*r, Role::kMeso)) {
      first_meso = r;
      break;
    }
  }
  if (last_micro == nullptr || first_meso == nullptr || !autonomous(*last_micro) || !autonomous(*first_meso)) return;
  ++m.handoffs;
  if (first_meso->lane == last_micro->lane || first_meso->lane == last_micro->target_lane) ++m.lane_kept;
  const double dt = step_s * static_cast<double>(first_meso->step - last_micro->step);
  const double jump = std::abs(first_meso->speed_mps - (last_micro->speed_mps + last_micro->accel_mps2 * dt));
  m.max_speed_jump_mps = std::max(m.max_speed_jump_mps, jump);
  jump_sum += jump;
}

}  // namespace

Transitions measure_transitions(const Tables& t, double step_s) {
  const RowsById rows = rows_by_id(t);
  const auto window_steps = static_cast<std::uint64_t>(std::llround(kIntoMicroWindow_s / step_s));
  const std::string border = to_string(HandoffReason::kBorder);
  Transitions out;
  std::vector<double> decels;
  double jump_sum = 0.0;
  for (const HandoffRow& h : t.handoffs) {
    if (h.reason != border) continue;
    const auto from = role_of_service(h.from);
    if (from == Role::kMeso && h.to_role == "micro") into_micro(h, rows, window_steps, decels);
    if (from == Role::kMicro && h.to_role == "meso") into_meso(h, rows, step_s, out.into_meso, jump_sum);
  }
  std::sort(decels.begin(), decels.end());
  IntoMicro& m = out.into_micro;
  m.handoffs = decels.size();
  m.median_decel_mps2 = quantile(decels, 0.5);
  m.p95_decel_mps2 = quantile(decels, 0.95);
  m.max_decel_mps2 = decels.empty() ? 0.0 : decels.back();
  m.hard = static_cast<std::uint64_t>(
      std::count_if(decels.begin(), decels.end(), [](double d) { return d > kHardBorderDecel_mps2; }));
  if (out.into_meso.handoffs > 0) out.into_meso.mean_speed_jump_mps = jump_sum / static_cast<double>(out.into_meso.handoffs);
  return out;
}

}  // namespace entourage::recording

#include "director/core/zones.hpp"

#include <algorithm>

namespace entourage::director {

std::vector<ZoneAtStart> zones_of(const PlayConfig& play, Direction ego_direction, int ego_lane, double ego_s_m,
                                  const Lanes& lanes) {
  std::vector<ZoneAtStart> out;
  for (const PlayClearZoneConfig& z : play.clear) {
    const int lane = ego_lane + z.lane_offset;
    if (lane < 0 || lane >= lanes.of(ego_direction)) continue;
    const double a = ego_s_m + sign(ego_direction) * z.from_m;
    const double b = ego_s_m + sign(ego_direction) * z.to_m;
    out.push_back({ego_direction, lane, std::min(a, b), std::max(a, b)});
  }
  return out;
}

ZoneAtStart actor_room(Direction dir, int lane, double s_m, double length_m, double speed_mps) {
  const double half = 0.5 * length_m;
  const double a = s_m - sign(dir) * (half + kSlotGapBehind_m);
  const double b = s_m + sign(dir) * (half + kSlotMinGap_m + kSlotTimeGap_s * speed_mps);
  return {dir, lane, std::min(a, b), std::max(a, b)};
}

std::vector<ZoneAtStart> slot_zones(const std::vector<Slot>& slots, const std::vector<double>& lengths_m,
                                    Direction ego_direction) {
  std::vector<ZoneAtStart> out;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const Slot& slot = slots[i];
    if (slot.direction != ego_direction) continue;
    out.push_back(actor_room(slot.direction, slot.lane, slot.s_m, lengths_m[i], slot.speed_mps));
  }
  return out;
}

bool in_zone(const ZoneAtStart& z, int lane, double s_m, double length_m) {
  return lane == z.lane && s_m + 0.5 * length_m > z.from_s_m && s_m - 0.5 * length_m < z.to_s_m;
}

const ZoneAtStart* zone_hit(const std::vector<ZoneAtStart>& zones, const ObservedVehicle& v, double s_m) {
  for (const ZoneAtStart& z : zones) {
    if (z.direction == v.direction && (in_zone(z, v.lane, s_m, v.length_m) || in_zone(z, v.target_lane, s_m, v.length_m))) {
      return &z;
    }
  }
  return nullptr;
}

ZoneAtStart joined_zone(const ZoneAtStart& zone, const std::vector<ZoneAtStart>& zones, double gap_m) {
  ZoneAtStart out = zone;
  for (bool grew = true; grew;) {
    grew = false;
    for (const ZoneAtStart& z : zones) {
      if (z.direction != out.direction || z.lane != out.lane) continue;
      if (z.to_s_m + gap_m <= out.from_s_m || z.from_s_m - gap_m >= out.to_s_m) continue;
      if (z.from_s_m < out.from_s_m || z.to_s_m > out.to_s_m) {
        out.from_s_m = std::min(out.from_s_m, z.from_s_m);
        out.to_s_m = std::max(out.to_s_m, z.to_s_m);
        grew = true;
      }
    }
  }
  return out;
}

}  // namespace entourage::director

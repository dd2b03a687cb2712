#pragma once
// Zones at the start of a play: the stretches of road that must be clear of other vehicles when
// the play is handed over (the play's own clear zones, relative to the ego) and the room each
// actor of the ego's direction keeps around its start. Clearing (clearing.hpp) asks the vehicles
// that would stand in them to leave; the handover checks the play's zones (play.hpp).

#include <vector>

#include "director/core/stage.hpp"

namespace entourage::director {

// A zone at the handover, in road s, in one lane of the ego's direction, with the ego at
// `ego_s_m` (trigger point 2 while preparing; where it is at the handover).
struct ZoneAtStart {
  Direction direction = Direction::kForward;
  int lane = 0;
  double from_s_m = 0.0;  // lower s
  double to_s_m = 0.0;    // higher s
};
std::vector<ZoneAtStart> zones_of(const PlayConfig& play, Direction ego_direction, int ego_lane, double ego_s_m,
                                  const Lanes& lanes);

// The room each actor of the ego's direction needs at its start, besides the play's own zones:
// its length, kSlotGapBehind_m behind it and a safe headway ahead (kSlotMinGap_m plus
// kSlotTimeGap_s at the slot's speed). A vehicle there keeps an actor that must change into the
// lane from getting in (and would stand between it and the ego). Cleared, not checked at the
// handover. `lengths_m[i]`: the length of slot i's actor.
inline constexpr double kSlotGapBehind_m = 2.0;
inline constexpr double kSlotMinGap_m = 5.0;
inline constexpr double kSlotTimeGap_s = 1.0;
std::vector<ZoneAtStart> slot_zones(const std::vector<Slot>& slots, const std::vector<double>& lengths_m,
                                    Direction ego_direction);
// The room an actor of `length_m` at `s_m` driving at `speed_mps` keeps around it (slot_zones).
ZoneAtStart actor_room(Direction dir, int lane, double s_m, double length_m, double speed_mps);

// Where `v` is `t_s` from now at its present speed (road s).
inline double s_after_m(const ObservedVehicle& v, double t_s) { return v.s_m + sign(v.direction) * v.speed_mps * t_s; }

// Does a vehicle of length `length_m` with its centre at `s_m` in `lane` overlap a zone?
bool in_zone(const ZoneAtStart& z, int lane, double s_m, double length_m);
// The first zone `v` overlaps with its centre at `s_m` (in either lane it occupies), or nullptr.
const ZoneAtStart* zone_hit(const std::vector<ZoneAtStart>& zones, const ObservedVehicle& v, double s_m);

// `zone` with every zone of its lane that comes within `gap_m` of it (repeatedly): the stretch a
// vehicle must be ahead of or behind, since it cannot stand between them.
ZoneAtStart joined_zone(const ZoneAtStart& zone, const std::vector<ZoneAtStart>& zones, double gap_m);

}  // namespace entourage::director

#pragma once
// Identities shared by every service: vehicles, directions, regions and services.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace entourage {

using VehicleId = std::uint32_t;
using Step = std::uint64_t;

// The ego carries this id when it appears among the neighbours of simulated vehicles.
inline constexpr VehicleId kEgoVehicleId = 0;
// No vehicle has this id (a vehicle not placed yet, or a query that skips nobody).
inline constexpr VehicleId kNoVehicle = 0xFFFFFFFFu;
// Ids from the generator start at 1; ids created by the director start here.
inline constexpr VehicleId kDirectorFirstVehicleId = 0x80000000u;

// Travel direction along the road reference line.
enum class Direction : std::int8_t { kForward = 1, kBackward = -1 };

inline int sign(Direction d) { return static_cast<int>(d); }
inline Direction opposite(Direction d) { return d == Direction::kForward ? Direction::kBackward : Direction::kForward; }
// 0 for the ego's direction, 1 for the oncoming one: an index into per-direction arrays.
inline std::size_t dir_index(Direction d) { return d == Direction::kForward ? 0 : 1; }
inline const char* to_string(Direction d) { return d == Direction::kForward ? "forward" : "backward"; }

// Where a road position lies in the window that moves with the ego (see road/window.hpp).
enum class Region : std::uint8_t { kOutside = 0, kOuterRear = 1, kInner = 2, kOuterFront = 3 };

const char* to_string(Region r);

// The kind of process. Values are part of the topic types (idl/): never renumber.
enum class Role : std::uint8_t {
  kNone = 0,
  kEgo = 1,
  kGenerator = 2,
  kMicro = 3,
  kMeso = 4,
  kDirector = 5,
  kRecorder = 6,
  kLauncher = 7,
};

// A service: a role and an instance number (several meso processes may run side by side).
struct ServiceId {
  Role role = Role::kNone;
  std::uint8_t instance = 0;

  std::uint16_t code() const { return static_cast<std::uint16_t>(static_cast<unsigned>(role) << 8U | instance); }
  static ServiceId from_code(std::uint16_t code) {
    return ServiceId{static_cast<Role>(code >> 8U), static_cast<std::uint8_t>(code & 0xFFU)};
  }
  bool operator==(const ServiceId& o) const { return role == o.role && instance == o.instance; }
  bool operator!=(const ServiceId& o) const { return !(*this == o); }
  bool operator<(const ServiceId& o) const { return code() < o.code(); }
};

// Canonical names: ego, generator, micro, meso, meso-front, meso-rear, director, recorder.
std::string to_string(ServiceId id);
std::optional<ServiceId> service_from_name(std::string_view name);

// Meso instances: 0 serves both outer regions, 1 only the front one, 2 only the rear one.
inline constexpr std::uint8_t kMesoBoth = 0;
inline constexpr std::uint8_t kMesoFront = 1;
inline constexpr std::uint8_t kMesoRear = 2;

}  // namespace entourage

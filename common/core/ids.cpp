#include "core/ids.hpp"

#include <array>
#include <utility>

namespace entourage {

const char* to_string(Region r) {
  switch (r) {
    case Region::kOuterRear: return "outer_rear";
    case Region::kInner: return "inner";
    case Region::kOuterFront: return "outer_front";
    case Region::kOutside: break;
  }
  return "outside";
}

namespace {
using Named = std::pair<const char*, ServiceId>;
constexpr std::array<Named, 8> kServiceNames{{
    {"ego", {Role::kEgo, 0}},
    {"generator", {Role::kGenerator, 0}},
    {"micro", {Role::kMicro, 0}},
    {"meso", {Role::kMeso, kMesoBoth}},
    {"meso-front", {Role::kMeso, kMesoFront}},
    {"meso-rear", {Role::kMeso, kMesoRear}},
    {"director", {Role::kDirector, 0}},
    {"recorder", {Role::kRecorder, 0}},
}};
}  // namespace

std::string to_string(ServiceId id) {
  for (const auto& [name, sid] : kServiceNames) {
    if (sid == id) return name;
  }
  if (id.role == Role::kLauncher) return "launcher";
  return "service-" + std::to_string(id.code());
}

std::optional<ServiceId> service_from_name(std::string_view name) {
  for (const auto& [n, sid] : kServiceNames) {
    if (name == n) return sid;
  }
  return std::nullopt;
}

}  // namespace entourage

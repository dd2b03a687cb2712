#pragma once
// The IDL source text of each topic type, as stored in recordings (MCAP schema, encoding omgidl).

#include <string_view>

namespace entourage::msg {

// Text of idl/<type_name>.idl, e.g. idl_text("VehicleState"); empty if unknown.
std::string_view idl_text(std::string_view type_name);

}  // namespace entourage::msg

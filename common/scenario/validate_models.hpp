#pragma once
// Validation of the behavioural-model parts of a scenario: a vehicle type's driver (car
// following, lane changes, Gipps, the Human Driver Model), speed adaptation and overtaking.
// Internal to scenario validation (validate.cpp).

#include "scenario/validate_cursor.hpp"

namespace entourage::scenario::detail {

// The ACC model's coolness, for a type's drivers and the ego: c = 1 would drop IDM altogether (CAH
// alone keeps no desired gap).
inline constexpr double kMaxCoolness = 0.999;

void check_driver(const Cursor& c, const Driver& d);
void check_speed_adaptation(const Cursor& top, const Scenario& s);
void check_overtaking(const Cursor& top, const Scenario& s);

}  // namespace entourage::scenario::detail

#pragma once
// Validation of a scenario's plays (trigger points, roles, actions, clear zones, end, release) and
// of the director's parameters. Internal to scenario validation (validate.cpp).

#include "scenario/validate_cursor.hpp"

namespace entourage::scenario::detail {

void check_plays(const Cursor& top, const Scenario& s);
void check_director(const Cursor& top, const Scenario& s);

}  // namespace entourage::scenario::detail

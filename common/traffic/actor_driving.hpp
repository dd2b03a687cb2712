#pragma once
// How a vehicle's own driver model carries out what the event director asks of it
// (traffic/actor_control.hpp). Pure functions used by driving.cpp (micro) and by meso.

#include <optional>

#include "traffic/driving_environment.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

// The desired speed the driver aims for: the director's while transported or controlled, else
// `own_mps` (its own at its place).
double actor_desired_speed_mps(const Vehicle& v, double own_mps);

// Whether the driver weighs discretionary lane changes and overtakings of its own: not while it
// is transported or controlled (an actor does not wander off its part).
bool chooses_lanes_freely(const Vehicle& v);

// The lane the director wants a transported vehicle to reach (changed into like a mandatory
// change, with the model's safety test), -1: none.
int director_lane(const Vehicle& v);

// A controlled actor's acceleration: towards its target speed at the script's rates (reaching it
// without overshoot), on a free road exactly that; with a leader no more than car following at
// an unbounded desired speed allows there (`car_following_mps2`, with the driver's own a as its
// free-road value `free_road_mps2`), so an actor never drives into the vehicle ahead.
double scripted_accel_mps2(const Vehicle& v, double car_following_mps2, double free_road_mps2, double dt_s);

// Transported and releasing actors: the acceleration rises no faster than the control's jerk
// limit (braking is never held back).
double limit_rise_mps2(const Vehicle& v, double accel_mps2, double dt_s);

// A controlled actor's scripted lane change to control.lane: starts moving at once when the
// target lane is physically free beside it (forced), or, when polite, through the ordinary
// mandatory change; nullopt: nothing to start now.
std::optional<LaneChangeState> scripted_lane_change(const Vehicle& v, const LaneIndex& index,
                                                    const DrivingEnvironment& env);

}  // namespace entourage

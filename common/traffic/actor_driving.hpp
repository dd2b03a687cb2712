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

// A transported vehicle faster than the director's speed (`director_mps`, its desired speed now)
// eases down to it as drivers do to a lower speed of their own choosing: at its model's free-road
// acceleration there, but no harder than its comfortable deceleration b; its leaders still brake it
// as hard as they need. Left to the model, the free-road term above the desired speed grows with
// (v/v0)^delta: vehicles the director slowed braked at up to 6 m/s^2 on a free road 57 m behind
// their leader (stopped vehicle, stop 30; the median of the cleared vehicles' hardest braking per
// run fell from 5.9 to 5.2 m/s^2 with the easing, the rest is car following behind vehicles that
// change in ahead). Cf. the improved IDM's free-road deceleration above v0, bounded by b (Treiber
// & Kesting, Traffic Flow Dynamics, 2013, ch. 11.3.6).
bool eases_down(const Vehicle& v, double director_mps);
// The easing acceleration: `cf` with the director's speed as its desired speed.
double easing_accel_mps2(const CarFollowingParams& cf, double speed_mps);

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

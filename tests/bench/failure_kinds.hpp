#pragma once
// How the director bench groups the reasons a play's start condition was not met (the failed
// report's detail, services/director/core/play.cpp): by role and kind, so that equal causes count
// together in `entourage-bench-director`'s summary.

#include <set>
#include <string>

#include "scenario/config.hpp"

namespace entourage::bench {

// The kind of one problem of a start condition: "truck: 12.0 m from its start position" is
// "truck: position", "cutter: -11.6 km/h from its start speed" is "cutter: speed", "vehicle 8 in a
// clear zone" is "a vehicle in a clear zone". A position miss that leaves an actor of the ego's
// direction whose start is ahead of the ego behind the ego (the error runs along the ego's
// direction, > 0 beyond the start) is "role: behind the ego": the ego passed the slow truck, or
// the cutter never got past the ego.
std::string kind_of(const std::string& problem, const PlayConfig& play);

// The kinds of the problems in a "; "-separated list, each once.
std::set<std::string> kinds_of(const std::string& problems, const PlayConfig& play);

// A failed report's first reason as its kind ("start condition not met on passing trigger point
// 2: truck: 20.0 m from its start position; ..." is "truck: position"); any other detail as it is.
std::string cause_of(const std::string& detail, const PlayConfig& play);

}  // namespace entourage::bench

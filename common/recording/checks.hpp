#pragma once
// The design's invariants, checked on recorded rows (a recording or its CSV export):
//   one_owner        no vehicle is published twice in a step (one owner per live vehicle)
//   continuity       a vehicle is present in every step between its first and last appearance
//   no_pop_in        no vehicle appears in the inner region (except those of the initial fill, in
//                    the first two steps with vehicles) and none disappears there (except at the end:
//                    an owner's last recorded step may be cut short by the recorder stopping)
//   no_overlap       no two vehicles (ego included) of a direction overlap (length x width boxes)
//   ego_interacts    the ego is the leader of a micro vehicle in some step (the ego is a vehicle
//                    like any other to micro), unless no vehicle was ever right behind it in the
//                    inner region (nobody caught up: rural seed 2's five minutes, where the
//                    nearest follower stayed in the outer region). How often a micro vehicle is the ego's leader is
//                    reported too, but not required: an ego slower than everything on the road
//                    (rural_ego_slow) may have nobody ahead of it in the inner region for minutes.
//                    A transparent ego (a probe) interacts with nobody: the check does not apply

#include <cstdint>
#include <string>
#include <vector>

#include "recording/tables.hpp"
#include "scenario/config.hpp"

namespace entourage::recording {

struct CheckResult {
  std::string name;
  bool passed = false;
  std::uint64_t violations = 0;
  std::string detail;  // the first violations, or what was measured
};

// `ego`: its size, and whether it is transparent (scenario `ego.transparent`: a probe the traffic
// drives through, so it is left out of no_overlap, and ego_interacts does not apply).
std::vector<CheckResult> check_invariants(const Tables& t, const EgoConfig& ego);

}  // namespace entourage::recording

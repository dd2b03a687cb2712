#pragma once
// Casting as an assignment problem (paper IV): roles are given to candidate vehicles so that the
// sum of the costs is least, every vehicle playing at most one role. A role may stay without a
// vehicle at its own cost (the director then creates one out of sight), so a poor fit is not
// forced on a role just because some vehicle exists. Exact: a dynamic programme over the subsets
// of roles (plays have few roles), O(candidates * 2^roles * roles).

#include <cstddef>
#include <vector>

namespace entourage::director {

inline constexpr std::size_t kMaxRoles = 8;

// cost[r][c]: role r played by candidate c (infinity: it cannot). unassigned_cost[r]: role r gets
// no candidate (infinity: not allowed). Returns, per role, the candidate index or -1.
std::vector<int> assign_roles(const std::vector<std::vector<double>>& cost, const std::vector<double>& unassigned_cost);

}  // namespace entourage::director

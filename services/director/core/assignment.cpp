#include "director/core/assignment.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace entourage::director {

std::vector<int> assign_roles(const std::vector<std::vector<double>>& cost, const std::vector<double>& unassigned_cost) {
  const std::size_t roles = unassigned_cost.size();
  if (roles > kMaxRoles) throw std::invalid_argument("assign_roles: too many roles");
  const std::size_t candidates = roles == 0 ? 0 : cost[0].size();
  const std::size_t masks = std::size_t{1} << roles;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr int kUnused = -1;

  // best[c][mask]: least cost of giving the roles in mask to candidates before c;
  // chose[c][mask]: the role candidate c-1 took on the way there (kUnused: none).
  std::vector<std::vector<double>> best(candidates + 1, std::vector<double>(masks, kInf));
  std::vector<std::vector<int>> chose(candidates + 1, std::vector<int>(masks, kUnused));
  best[0][0] = 0.0;
  for (std::size_t c = 0; c < candidates; ++c) {
    for (std::size_t mask = 0; mask < masks; ++mask) {
      const double here = best[c][mask];
      if (!std::isfinite(here)) continue;
      if (here < best[c + 1][mask]) {
        best[c + 1][mask] = here;
        chose[c + 1][mask] = kUnused;
      }
      for (std::size_t r = 0; r < roles; ++r) {
        const std::size_t bit = std::size_t{1} << r;
        if ((mask & bit) != 0 || !std::isfinite(cost[r][c])) continue;
        const double next = here + cost[r][c];
        if (next < best[c + 1][mask | bit]) {
          best[c + 1][mask | bit] = next;
          chose[c + 1][mask | bit] = static_cast<int>(r);
        }
      }
    }
  }
  double least = kInf;
  std::size_t least_mask = 0;
  for (std::size_t mask = 0; mask < masks; ++mask) {
    double total = best[candidates][mask];
    for (std::size_t r = 0; r < roles && std::isfinite(total); ++r) {
      if ((mask & (std::size_t{1} << r)) == 0) total += unassigned_cost[r];
    }
    if (total < least) {
      least = total;
      least_mask = mask;
    }
  }
  std::vector<int> out(roles, -1);
  if (!std::isfinite(least)) return out;
  std::size_t mask = least_mask;
  for (std::size_t c = candidates; c > 0; --c) {
    const int r = chose[c][mask];
    if (r == kUnused) continue;
    out[static_cast<std::size_t>(r)] = static_cast<int>(c - 1);
    mask &= ~(std::size_t{1} << static_cast<unsigned>(r));
  }
  return out;
}

}  // namespace entourage::director

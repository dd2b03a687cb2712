#include "failure_kinds.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace entourage::bench {

namespace {
bool behind_the_ego(const std::string& role, const std::string& problem, const PlayConfig& play) {
  const auto rc = std::find_if(play.roles.begin(), play.roles.end(), [&](const PlayRoleConfig& r) { return r.name == role; });
  if (rc == play.roles.end() || rc->direction != Direction::kForward || rc->ahead_m <= 0.0) return false;
  const std::string error = problem.substr(role.size() + 2);
  return rc->ahead_m + std::strtod(error.c_str(), nullptr) < 0.0;
}
}  // namespace

std::string kind_of(const std::string& problem, const PlayConfig& play) {
  if (problem.find("in a clear zone") != std::string::npos) return "a vehicle in a clear zone";
  const std::string role = problem.substr(0, problem.find(": "));
  for (const auto& [text, kind] : {std::pair<const char*, const char*>{"start position", "position"},
                                   {"start speed", "speed"},
                                   {"in lane", "lane"},
                                   {"no actor", "no actor"}}) {
    if (problem.find(text) == std::string::npos) continue;
    if (std::string(kind) == "position" && behind_the_ego(role, problem, play)) return role + ": behind the ego";
    return role + ": " + kind;
  }
  return problem;
}

std::set<std::string> kinds_of(const std::string& problems, const PlayConfig& play) {
  std::set<std::string> out;
  for (std::size_t from = 0; from < problems.size();) {
    const std::size_t end = std::min(problems.find("; ", from), problems.size());
    out.insert(kind_of(problems.substr(from, end - from), play));
    from = end + 2;
  }
  return out;
}

std::string cause_of(const std::string& detail, const PlayConfig& play) {
  const auto start = detail.find(": ");
  if (detail.rfind("start condition not met", 0) != 0 || start == std::string::npos) return detail;
  return kind_of(detail.substr(start + 2, detail.find(';', start) - start - 2), play);
}

}  // namespace entourage::bench

#include "paired_runs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "director/core/play.hpp"
#include "play_runs.hpp"

namespace entourage::bench {

namespace {
// The ego driver's name as the verbose line prints it (to_string(EgoVariant)) at the start of
// `rest`; some names have two words. Empty when none fits.
std::string variant_at(const std::string& rest) {
  for (const EgoVariant v : {EgoVariant::kSteady, EgoVariant::kBrakes, EgoVariant::kChangesLane}) {
    const std::string name = to_string(v);
    if (rest.compare(0, name.size(), name) == 0 && (rest.size() == name.size() || rest[name.size()] == ' ')) {
      return name;
    }
  }
  return {};
}
}  // namespace

std::map<std::uint64_t, bool> outcomes_by_seed(const std::string& verbose_text) {
  const std::string done = director::to_string(director::PlayPhase::kDone);
  std::map<std::uint64_t, bool> out;
  std::istringstream lines(verbose_text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string run_word, index, seed_word, rest, phase;
    std::uint64_t seed = 0;
    if (!(words >> run_word >> index >> seed_word >> seed) || run_word != "run" || seed_word != "seed") continue;
    std::getline(words >> std::ws, rest);
    const std::string variant = variant_at(rest);
    if (variant.empty()) continue;
    std::istringstream after(rest.substr(variant.size()));
    if (!(after >> phase)) continue;
    out[seed] = phase == done;
  }
  return out;
}

PairedRuns pair_runs(const std::map<std::uint64_t, bool>& before, const std::map<std::uint64_t, bool>& now) {
  PairedRuns p;
  for (const auto& [seed, done_now] : now) {
    const auto b = before.find(seed);
    if (b == before.end()) {
      ++p.unpaired;
    } else if (b->second && done_now) {
      ++p.both_done;
    } else if (!b->second && done_now) {
      ++p.gained;
    } else if (b->second && !done_now) {
      ++p.lost;
    } else {
      ++p.both_failed;
    }
  }
  return p;
}

double flips_p_value(int gained, int lost) {
  const int n = gained + lost;
  if (n <= 0) return 1.0;
  const int k = std::min(gained, lost);
  // P(X <= k) for X ~ Binomial(n, 1/2), summed in logarithms (n may be in the thousands).
  double tail = 0.0;
  for (int i = 0; i <= k; ++i) {
    tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) - n * std::log(2.0));
  }
  return std::min(1.0, 2.0 * tail);
}

}  // namespace entourage::bench

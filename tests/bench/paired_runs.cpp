#include "paired_runs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace entourage::bench {

namespace {
// The ego drivers' names as the verbose line prints them (to_string(EgoVariant)); one has two words.
constexpr const char* kTwoWordVariantFirst = "changes";
}  // namespace

std::map<std::uint64_t, bool> outcomes_by_seed(const std::string& verbose_text) {
  std::map<std::uint64_t, bool> out;
  std::istringstream lines(verbose_text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string run_word, index, seed_word, variant, phase;
    std::uint64_t seed = 0;
    if (!(words >> run_word >> index >> seed_word >> seed >> variant) || run_word != "run" || seed_word != "seed") continue;
    if (variant == kTwoWordVariantFirst && !(words >> variant)) continue;
    if (!(words >> phase)) continue;
    out[seed] = phase == "done";
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

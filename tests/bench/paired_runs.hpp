#pragma once
// Two versions of the director on the same runs: which runs a change gained and which it lost.
// The bench's runs are paired (run i has the same traffic seed and ego driver in both versions),
// so a change is judged by the runs whose outcome it flipped, not by the difference of two
// success rates, and by McNemar's exact test on those flips: under "no effect" a flipped run is
// as likely gained as lost (a fair coin), and the p-value is how often a coin gives a split at
// least as uneven. (Stop 39: a deadlock mend flipped 23 of 200 cut-in runs, 10 gained and 13 lost,
// p = 0.68: its change of the success rate, 171 to 168, is what chance gives any change.)

#include <cstdint>
#include <map>
#include <string>

namespace entourage::bench {

// A run's outcome by its traffic seed, read from the bench's `--verbose` lines
// ("run I seed S VARIANT PHASE ..."): true where the phase was "done".
std::map<std::uint64_t, bool> outcomes_by_seed(const std::string& verbose_text);

struct PairedRuns {
  int both_done = 0;
  int gained = 0;   // failed before, done now
  int lost = 0;     // done before, failed now
  int both_failed = 0;
  int unpaired = 0;  // runs of `now` without a run of the same seed in `before`
};
PairedRuns pair_runs(const std::map<std::uint64_t, bool>& before, const std::map<std::uint64_t, bool>& now);

// McNemar's exact two-sided test: the chance that a fair coin splits gained + lost flips at least
// as unevenly as observed (1 when nothing flipped).
double flips_p_value(int gained, int lost);

}  // namespace entourage::bench

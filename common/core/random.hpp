#pragma once
// Seeded random streams. Every random draw in Entourage comes from a Random owned by a service
// (or carried by a driver), so a run is reproducible from its seed. The generator is xoshiro256**
// seeded through splitmix64; distributions are implemented here rather than taken from <random>,
// whose distributions differ between standard libraries.

#include <cstdint>

namespace entourage {

class Random {
 public:
  explicit Random(std::uint64_t seed);
  // A stream derived from a parent seed and a label (e.g. a vehicle id): independent of how
  // many other streams were derived before it, so results do not depend on process layout.
  static Random derived(std::uint64_t seed, std::uint64_t label);

  std::uint64_t next_u64();
  double uniform();                            // [0, 1)
  double uniform(double lo, double hi);        // [lo, hi)
  double normal(double mean, double stddev);   // Marsaglia polar method
  // Normal truncated to [lo, hi] by rejection (lo < hi; falls back to clamping after 64 tries).
  double truncated_normal(double mean, double stddev, double lo, double hi);
  double exponential(double rate);             // mean 1 / rate
  bool bernoulli(double p);

 private:
  std::uint64_t s_[4];
  double spare_normal_ = 0.0;
  bool has_spare_ = false;
};

// A 64-bit-state stream (splitmix64) for per-driver noise that is handed over with the vehicle.
class SmallRandom {
 public:
  explicit SmallRandom(std::uint64_t state) : state_(state) {}
  std::uint64_t next_u64();
  double uniform();                           // [0, 1)
  double normal();                            // standard normal, Box-Muller (no cached spare)
  std::uint64_t state() const { return state_; }

 private:
  std::uint64_t state_;
};

std::uint64_t splitmix64(std::uint64_t& state);

}  // namespace entourage

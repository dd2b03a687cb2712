#include "core/random.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kInv2Pow53 = 1.0 / 9007199254740992.0;  // 2^-53

std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
double to_unit(std::uint64_t x) { return static_cast<double>(x >> 11U) * kInv2Pow53; }
}  // namespace

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31U);
}

Random::Random(std::uint64_t seed) {
  std::uint64_t sm = seed;
  for (auto& s : s_) s = splitmix64(sm);
}

Random Random::derived(std::uint64_t seed, std::uint64_t label) {
  std::uint64_t sm = seed ^ (label * 0xD1B54A32D192ED03ULL);
  return Random(splitmix64(sm) ^ label);
}

std::uint64_t Random::next_u64() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17U;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Random::uniform() { return to_unit(next_u64()); }

double Random::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

double Random::normal(double mean, double stddev) {
  if (has_spare_) {
    has_spare_ = false;
    return mean + stddev * spare_normal_;
  }
  double u = 0.0;
  double v = 0.0;
  double s = 0.0;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * std::log(s) / s);
  spare_normal_ = v * f;
  has_spare_ = true;
  return mean + stddev * u * f;
}

double Random::truncated_normal(double mean, double stddev, double lo, double hi) {
  if (stddev <= 0.0) return std::clamp(mean, lo, hi);
  for (int i = 0; i < 64; ++i) {
    const double x = normal(mean, stddev);
    if (x >= lo && x <= hi) return x;
  }
  return std::clamp(mean, lo, hi);
}

double Random::exponential(double rate) {
  double u = uniform();
  while (u <= 0.0) u = uniform();
  return -std::log(u) / rate;
}

bool Random::bernoulli(double p) { return uniform() < p; }

std::uint64_t SmallRandom::next_u64() { return splitmix64(state_); }

double SmallRandom::uniform() { return to_unit(next_u64()); }

double SmallRandom::normal() {
  double u1 = uniform();
  while (u1 <= 0.0) u1 = uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

}  // namespace entourage

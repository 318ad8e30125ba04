#pragma once
// Random streams, one per component, seeded from (run seed, component id) as
// ns-3's AssignStreams does: adding a robot or a link does not reshuffle the
// numbers any other component draws.
//
// The generator is xoshiro256** (Blackman & Vigna), seeded through SplitMix64,
// and every draw below is defined bit for bit here (uniform doubles from the
// top 53 bits, unbiased integers by rejection), so a stream produces the same
// values with any compiler or standard library. Exponential() and Normal()
// use std::log / std::sqrt / std::cos, whose last-bit results may differ
// between libm versions; do not rely on them for byte-identical outputs.
#include <cstdint>
#include <limits>
#include <string_view>

#include "sim/random_bits.h"

namespace dvpr {

// A stable 64-bit id for a named component ("link", "robot/3"): FNV-1a.
std::uint64_t ComponentId(std::string_view name);

class RandomStream {
 public:
  using result_type = std::uint64_t;  // UniformRandomBitGenerator, for std algorithms

  RandomStream(std::uint64_t run_seed, std::uint64_t component_id);
  // A generator in the given raw xoshiro256** state (not all zero): for
  // checking against the reference implementation's published outputs.
  static RandomStream FromState(std::uint64_t s0, std::uint64_t s1, std::uint64_t s2, std::uint64_t s3);

  std::uint64_t NextU64();
  // Uniform in [0, 1), a multiple of 2^-53.
  double Uniform01();
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform01(); }
  // Uniform integer in [0, n), unbiased; n > 0.
  std::uint64_t UniformInt(std::uint64_t n);
  // True with probability p (p <= 0: never, p >= 1: always).
  bool Bernoulli(double p);
  // Exponential with the given mean (> 0).
  double Exponential(double mean);
  // Standard normal (Box-Muller; one value per call).
  double Normal();

  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() { return NextU64(); }

 private:
  RandomStream() = default;
  Xoshiro256 gen_{0};
};

}  // namespace dvpr

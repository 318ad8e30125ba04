#pragma once
// Portable pseudo-random bits: the one xoshiro256** and SplitMix64 of dvpr, used by the random
// streams (sim/random.h), k-means seeding, run seeds and the synthetic data. Written out here rather than taken from <random> so that a seed gives byte-identical
// results with every standard library: std::*_distribution is implementation-defined.
#include <cstdint>

namespace dvpr {

// SplitMix64 (Steele, Lea, Flood 2014): one 64-bit mixing step. Also used to derive
// independent seeds from tuples, e.g. MixSeed(MixSeed(seed, robots), run).
constexpr std::uint64_t SplitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// A seed for a child stream keyed by `key`: different keys give unrelated seeds, and adding a
// key never changes the seeds of the others.
constexpr std::uint64_t MixSeed(std::uint64_t seed, std::uint64_t key) {
  std::uint64_t state = seed;
  std::uint64_t first = SplitMix64(state);
  state = first ^ key;
  return SplitMix64(state);
}

// xoshiro256** 1.0 (Blackman, Vigna 2018), state filled from SplitMix64 as its authors advise.
class Xoshiro256 {
 public:
  explicit constexpr Xoshiro256(std::uint64_t seed) {
    for (auto& word : s_) word = SplitMix64(seed);
  }
  // A generator in a raw state (not all zero), e.g. to check the reference outputs.
  static constexpr Xoshiro256 FromState(std::uint64_t s0, std::uint64_t s1, std::uint64_t s2, std::uint64_t s3) {
    Xoshiro256 x(0);
    x.s_[0] = s0;
    x.s_[1] = s1;
    x.s_[2] = s2;
    x.s_[3] = s3;
    return x;
  }

  constexpr std::uint64_t Next() {
    const std::uint64_t result = Rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = Rotl(s_[3], 45);
    return result;
  }

  // Uniform in [0, 1) with 53 random bits.
  constexpr double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }

  // Uniform in [0, n), n > 0: rejection of the 2^64 mod n lowest values keeps it unbiased.
  constexpr std::uint64_t Below(std::uint64_t n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (true) {
      const std::uint64_t r = Next();
      if (r >= threshold) return r % n;
    }
  }

 private:
  static constexpr std::uint64_t Rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4]{};
};

}  // namespace dvpr

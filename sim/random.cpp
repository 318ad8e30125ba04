#include "sim/random.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dvpr {
namespace {

std::uint64_t Rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

std::uint64_t ComponentId(std::string_view name) {
  std::uint64_t h = 0xCBF29CE484222325ULL;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ULL;
  }
  return h;
}

RandomStream::RandomStream(std::uint64_t run_seed, std::uint64_t component_id) {
  // Mix each input through its own SplitMix64 step before combining, so
  // nearby (seed, id) pairs give unrelated streams.
  std::uint64_t a = run_seed;
  std::uint64_t b = component_id ^ 0xD1B54A32D192ED03ULL;
  gen_ = Xoshiro256(SplitMix64(a) ^ Rotl(SplitMix64(b), 17));
}

RandomStream RandomStream::FromState(std::uint64_t s0, std::uint64_t s1, std::uint64_t s2, std::uint64_t s3) {
  RandomStream r;
  r.gen_ = Xoshiro256::FromState(s0, s1, s2, s3);
  return r;
}

std::uint64_t RandomStream::NextU64() { return gen_.Next(); }

double RandomStream::Uniform01() {
  return static_cast<double>(NextU64() >> 11) * 0x1.0p-53;
}

std::uint64_t RandomStream::UniformInt(std::uint64_t n) {
  if (n == 0) throw std::invalid_argument("RandomStream::UniformInt: n must be positive");
  // Reject the top partial block so every residue is equally likely.
  const std::uint64_t limit = max() - (max() % n + 1) % n;
  for (;;) {
    const std::uint64_t x = NextU64();
    if (x <= limit) return x % n;
  }
}

bool RandomStream::Bernoulli(double p) {
  if (p <= 0.0) return false;
  if (p >= 1.0) return true;
  return Uniform01() < p;
}

double RandomStream::Exponential(double mean) {
  if (!(mean > 0.0)) throw std::invalid_argument("RandomStream::Exponential: mean must be positive");
  return -mean * std::log1p(-Uniform01());
}

double RandomStream::Normal() {
  const double u1 = 1.0 - Uniform01();  // (0, 1]: log is finite
  const double u2 = Uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace dvpr

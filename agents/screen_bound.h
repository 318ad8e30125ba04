#pragma once
// What HalfScreen and ByteScreen share: the limit a float partial sum must stay under, and the
// test of 8 rows' sums against it.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace dvpr::screen_bound {

// Eight rows side by side: a GNU vector of 8 floats (one AVX register, two SSE ones).
using Lanes = float __attribute__((vector_size(8 * sizeof(float))));

// A row within `exact` (squared) of the query has a copy within sqrt(exact) + error of it
// (triangle inequality), and a float sum of `terms` squared differences of float values exceeds
// the exact one by at most (terms + 2) units of 2^-24 relative (4 x that here, which also covers
// the rounding of this expression).
inline float Limit(double exact, float error, int terms) {
  const double root = std::sqrt(std::max(0.0, exact)) * (1.0 + 0x1.0p-50) + error;
  const double limit = root * root * (1.0 + 4.0 * (terms + 3) * 0x1.0p-24);
  return std::nextafter(static_cast<float>(limit), std::numeric_limits<float>::infinity());
}

// Bit l set where lane l of `sums` is not above `limit` (NaN is not above: such a row is kept).
inline unsigned NotAbove(const Lanes& sums, float limit) {
#if defined(__AVX__)
  __m256 wide;
  std::memcpy(&wide, &sums, sizeof wide);
  return ~static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(wide, _mm256_set1_ps(limit), _CMP_GT_OQ))) & 0xFFu;
#else
  unsigned mask = 0;
  for (unsigned l = 0; l < 8; ++l) mask |= (sums[l] > limit ? 0u : 1u) << l;
  return mask;
#endif
}

// The error bound of a row from its exact ||row - copy||^2 (double), rounded up to a float;
// +inf when it is not finite (a value the copy cannot hold: no bound).
inline float RowError(double squared) {
  // The double sum's own rounding (dim terms) is far below the 2^-30 added.
  const double bound = std::sqrt(squared) * (1.0 + 0x1.0p-30);
  return std::isfinite(bound) ? std::nextafter(static_cast<float>(bound), std::numeric_limits<float>::infinity())
                              : std::numeric_limits<float>::infinity();
}

}  // namespace dvpr::screen_bound

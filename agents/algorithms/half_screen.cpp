#include "agents/algorithms/half_screen.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__AVX__) && defined(__F16C__)
#include <immintrin.h>
#define DVPR_HALF_SCREEN_AVX 1
#else
#define DVPR_HALF_SCREEN_AVX 0
#endif

namespace dvpr {
namespace {

constexpr int kFirstCheck = 32;
constexpr int kCheckEvery = 16;

// Eight rows side by side: a GNU vector of 8 floats (one AVX register, two SSE ones).
using Lanes = float __attribute__((vector_size(8 * sizeof(float))));

// The value of IEEE binary16 bits, exactly.
float HalfToFloat(std::uint16_t h) {
#if DVPR_HALF_SCREEN_AVX
  return _cvtsh_ss(h);
#else
  const int exponent = (h >> 10) & 0x1F;
  const auto mantissa = static_cast<float>(h & 0x3FF);
  float magnitude = 0.0f;
  if (exponent == 0) {
    magnitude = std::ldexp(mantissa, -24);  // zero and subnormals: units of 2^-24
  } else if (exponent == 31) {
    magnitude = mantissa == 0.0f ? std::numeric_limits<float>::infinity() : std::numeric_limits<float>::quiet_NaN();
  } else {
    magnitude = std::ldexp(mantissa + 1024.0f, exponent - 25);  // (1024 + m) x 2^(e - 15 - 10)
  }
  return (h & 0x8000u) != 0 ? -magnitude : magnitude;
#endif
}

// A float's IEEE binary16 bits, rounded to nearest, ties to even (as F16C's conversion).
std::uint16_t FloatToHalf(float f) {
#if DVPR_HALF_SCREEN_AVX
  return static_cast<std::uint16_t>(_cvtss_sh(f, 0));
#else
  const std::uint16_t sign = std::signbit(f) ? 0x8000u : 0u;
  const float a = std::fabs(f);
  if (std::isnan(f)) return static_cast<std::uint16_t>(sign | 0x7E00u);
  if (a >= 65520.0f) return static_cast<std::uint16_t>(sign | 0x7C00u);  // rounds to infinity
  if (a < 0x1p-14f) {  // subnormal: units of 2^-24 (1024 units is the smallest normal, 0x0400)
    return static_cast<std::uint16_t>(sign | static_cast<std::uint16_t>(std::nearbyint(a * 0x1p24f)));
  }
  int e = 0;
  std::frexp(a, &e);  // a in [2^(e-1), 2^e)
  int exponent = e - 1;
  auto units = static_cast<std::uint32_t>(std::nearbyint(std::ldexp(a, 10 - exponent)));  // 1024..2048
  if (units == 2048) units = 1024, ++exponent;
  if (exponent > 15) return static_cast<std::uint16_t>(sign | 0x7C00u);
  return static_cast<std::uint16_t>(sign | static_cast<std::uint32_t>(exponent + 15) << 10 | (units - 1024));
#endif
}

// acc += (the 8 halves at `halves`, as floats, - q)^2, lane by lane.
inline void AddSquaredDiffs(Lanes& acc, const std::uint16_t* halves, float q) {
  Lanes x;
#if DVPR_HALF_SCREEN_AVX
  const __m256 wide = _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(halves)));  // 8 at once
  std::memcpy(&x, &wide, sizeof x);
#else
  for (int l = 0; l < 8; ++l) x[l] = HalfToFloat(halves[l]);
#endif
  const Lanes diff = x - q;
  acc += diff * diff;
}

// Adds the squared differences of one band's tile (width values) to the lanes' sums. Four sums
// a lane, so that the adds do not wait on each other; any order of a float sum obeys the
// limit's error bound.
inline void AddBand(Lanes (&acc)[4], const std::uint16_t* tile, const float* q, std::size_t width) {
  std::size_t j = 0;
  for (; j + 4 <= width; j += 4) {
    for (std::size_t a = 0; a < 4; ++a) AddSquaredDiffs(acc[a], tile + (j + a) * HalfScreen::kTileRows, q[j + a]);
  }
  for (; j < width; ++j) AddSquaredDiffs(acc[0], tile + j * HalfScreen::kTileRows, q[j]);
}

// Bit l set where lane l of `sums` is not above `limit` (NaN is not above: such a row is kept).
unsigned NotAbove(const Lanes& sums, float limit) {
#if DVPR_HALF_SCREEN_AVX
  __m256 wide;
  std::memcpy(&wide, &sums, sizeof wide);
  return ~static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(wide, _mm256_set1_ps(limit), _CMP_GT_OQ))) & 0xFFu;
#else
  unsigned mask = 0;
  for (unsigned l = 0; l < 8; ++l) mask |= (sums[l] > limit ? 0u : 1u) << l;
  return mask;
#endif
}

}  // namespace

HalfScreen::HalfScreen(int dim) {
  for (int end = kFirstCheck; end < dim; end += kCheckEvery) checks_.push_back(end);
  checks_.push_back(dim);
  bands_.resize(checks_.size());
}

void HalfScreen::Append(const float* row) {
  std::size_t from = 0;
  double error = 0.0;  // ||row - half(row)||^2: each difference of a float and a half is exact in double
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    const auto width = static_cast<std::size_t>(checks_[k]) - from;
    std::vector<std::uint16_t>& band = bands_[k];
    if (rows_ % kTileRows == 0) band.resize(band.size() + width * kTileRows, 0);
    std::uint16_t* tile = band.data() + rows_ / kTileRows * width * kTileRows + rows_ % kTileRows;
    for (std::size_t j = 0; j < width; ++j) {
      const std::uint16_t half = FloatToHalf(row[from + j]);
      tile[j * kTileRows] = half;
      const double diff = static_cast<double>(row[from + j]) - static_cast<double>(HalfToFloat(half));
      error += diff * diff;
    }
    from += width;
  }
  ++rows_;
  // The double sum's own rounding (dim terms) is far below the 2^-30 added; an overflowed or
  // NaN value leaves the screen without a bound (every row is then computed).
  const double bound = std::sqrt(error) * (1.0 + 0x1.0p-30);
  const float rounded_up = std::nextafter(static_cast<float>(bound), std::numeric_limits<float>::infinity());
  error_ = std::isfinite(bound) ? std::max(error_, rounded_up) : std::numeric_limits<float>::infinity();
}

void HalfScreen::Clear() {
  for (auto& band : bands_) band.clear();
  rows_ = 0;
  error_ = 0.0f;
}

// A row within `exact` of the query has a copy within sqrt(exact) + error of it (triangle
// inequality), and a float sum of `terms` squared differences exceeds the exact one by at most
// (terms + 2) units of 2^-24 relative (4 x that here).
float HalfScreen::Limit(double exact, std::size_t k) const {
  const double root = std::sqrt(std::max(0.0, exact)) * (1.0 + 0x1.0p-50) + error_;
  const double limit = root * root * (1.0 + 4.0 * (checks_[k] + 3) * 0x1.0p-24);
  return std::nextafter(static_cast<float>(limit), std::numeric_limits<float>::infinity());
}

unsigned HalfScreen::Survivors(std::size_t first, const float* query, const float* limits) const {
  return SurvivorsFrom(first, query, limits, 0, nullptr);
}

unsigned HalfScreen::Survivors(std::size_t first, const float* query, const float* limits,
                               const float* first_sums) const {
  return SurvivorsFrom(first, query, limits, 1, first_sums);
}

void HalfScreen::FirstBandSums(std::size_t first, const float* query, float* sums) const {
  Lanes acc[4] = {};
  AddBand(acc, bands_[0].data() + first * static_cast<std::size_t>(checks_[0]), query, static_cast<std::size_t>(checks_[0]));
  const Lanes total = (acc[0] + acc[1]) + (acc[2] + acc[3]);
  std::memcpy(sums, &total, sizeof total);
}

unsigned HalfScreen::SurvivorsFrom(std::size_t first, const float* query, const float* limits, std::size_t band,
                                   const float* sums) const {
  Lanes acc[4] = {};
  unsigned alive = (1u << kTileRows) - 1;
  if (band > 0) {
    std::memcpy(&acc[0], sums, sizeof acc[0]);
    alive &= NotAbove(acc[0], limits[0]);
    if (alive == 0) return 0;
  }
  for (std::size_t k = band; k < checks_.size(); ++k) {
    const auto from = static_cast<std::size_t>(k == 0 ? 0 : checks_[k - 1]);
    const auto width = static_cast<std::size_t>(checks_[k]) - from;
    AddBand(acc, bands_[k].data() + first * width, query + from, width);
    const Lanes total = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    alive &= NotAbove(total, limits[k]);
    if (alive == 0) return 0;
  }
  return alive;
}

}  // namespace dvpr

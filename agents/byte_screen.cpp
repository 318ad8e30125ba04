#include "agents/byte_screen.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__AVX2__)
#include <immintrin.h>
#define DVPR_BYTE_SCREEN_AVX2 1
#else
#define DVPR_BYTE_SCREEN_AVX2 0
#endif

#include "agents/screen_bound.h"

namespace dvpr {
namespace {

using screen_bound::Lanes;

constexpr int kFirstCheck = 32;  // as HalfScreen: the same checks, so the same early exits
constexpr int kCheckEvery = 16;
constexpr float kLargestCode = 127.0f;  // codes in [-127, 127]

// The step for a first row whose largest magnitude is `largest`: the smallest power of two with
// 2 x largest <= 127 steps; 2^-7 for a row of zeros. A power of two, so code x step is exact.
float StepFor(float largest) {
  if (!(largest > 0.0f) || !std::isfinite(largest)) return 0x1.0p-7f;
  int exponent = 0;
  std::frexp(2.0f * largest / kLargestCode, &exponent);  // 2 largest / 127 in [2^(e-1), 2^e)
  return std::ldexp(1.0f, std::max(exponent, -100));   // far from float's subnormals
}

// acc += (the 8 codes at `codes` x step - q)^2, lane by lane; code x step is exact.
inline void AddSquaredDiffs(Lanes& acc, const std::int8_t* codes, float step, float q) {
  Lanes x;
#if DVPR_BYTE_SCREEN_AVX2
  const __m128i eight = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(codes));
  const __m256 wide = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_cvtepi8_epi32(eight)), _mm256_set1_ps(step));
  std::memcpy(&x, &wide, sizeof x);
#else
  for (int l = 0; l < 8; ++l) x[l] = static_cast<float>(codes[l]) * step;
#endif
  const Lanes diff = x - q;
  acc += diff * diff;
}

// One band's tile (width values) added to the lanes' sums, four sums a lane so that the adds do
// not wait on each other (any order of a float sum obeys the limit's error bound).
inline void AddBand(Lanes (&acc)[4], const std::int8_t* tile, float step, const float* q, std::size_t width) {
  std::size_t j = 0;
  for (; j + 4 <= width; j += 4) {
    for (std::size_t a = 0; a < 4; ++a) AddSquaredDiffs(acc[a], tile + (j + a) * ByteScreen::kTileRows, step, q[j + a]);
  }
  for (; j < width; ++j) AddSquaredDiffs(acc[0], tile + j * ByteScreen::kTileRows, step, q[j]);
}

}  // namespace

ByteScreen::ByteScreen(int dim) {
  for (int end = kFirstCheck; end < dim; end += kCheckEvery) checks_.push_back(end);
  checks_.push_back(dim);
  bands_.resize(checks_.size());
}

void ByteScreen::Append(const float* row) {
  if (rows_ == 0) {
    float largest = 0.0f;
    for (int j = 0; j < checks_.back(); ++j) largest = std::max(largest, std::fabs(row[j]));
    step_ = StepFor(largest);
  }
  std::size_t from = 0;
  double error = 0.0;  // ||row - copy||^2: each difference of a float and a code x step is exact in double
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    const auto width = static_cast<std::size_t>(checks_[k]) - from;
    GrowableArray<std::int8_t>& band = bands_[k];
    if (rows_ % kTileRows == 0) band.resize(band.size() + width * kTileRows);  // zeros: the padding rows
    std::int8_t* tile = band.data() + rows_ / kTileRows * width * kTileRows + rows_ % kTileRows;
    for (std::size_t j = 0; j < width; ++j) {
      const float v = row[from + j];
      // NaN stays NaN through the clamp's comparisons; it becomes code 0 and an error of NaN.
      const float units = std::clamp(std::nearbyint(v / step_), -kLargestCode, kLargestCode);
      const auto code = static_cast<std::int8_t>(std::isnan(units) ? 0.0f : units);
      tile[j * kTileRows] = code;
      const double diff = static_cast<double>(v) - static_cast<double>(code) * static_cast<double>(step_);
      error += diff * diff;
    }
    from += width;
  }
  ++rows_;
  error_ = std::max(error_, screen_bound::RowError(error));  // +inf (no bound) for a value not finite
}

void ByteScreen::Clear() {
  for (auto& band : bands_) band.clear();
  rows_ = 0;
  step_ = 0.0f;
  error_ = 0.0f;
}

float ByteScreen::Limit(double exact, std::size_t k) const { return screen_bound::Limit(exact, error_, checks_[k]); }

unsigned ByteScreen::Survivors(std::size_t first, const float* query, const float* limits) const {
  Lanes acc[4] = {};
  unsigned alive = (1u << kTileRows) - 1;
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    const auto from = static_cast<std::size_t>(k == 0 ? 0 : checks_[k - 1]);
    const auto width = static_cast<std::size_t>(checks_[k]) - from;
    AddBand(acc, bands_[k].data() + first * width, step_, query + from, width);
    const Lanes total = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    alive &= screen_bound::NotAbove(total, limits[k]);
    if (alive == 0) return 0;
  }
  return alive;
}

}  // namespace dvpr

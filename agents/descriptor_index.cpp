#include "agents/descriptor_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "agents/gemv_row.h"
#include "agents/l2.h"

namespace dvpr {
namespace {

bool InWindow(FrameId stored, FrameId query, int window) {
  return std::abs(static_cast<long>(stored.value) - query.value) <= window;
}

// The model's distance from a row's dot product: the one expression both searches round alike.
float ExpandedDistance(float norm, float dot, float q_norm) { return norm - 2.0f * dot + q_norm; }

// Eight rows side by side: a GNU vector of 8 floats (one AVX register, two SSE ones).
using Lanes = float __attribute__((vector_size(8 * sizeof(float))));

// acc += (the 8 halves at `halves`, as floats, - q)^2, lane by lane.
inline void AddSquaredDiffs(Lanes& acc, const _Float16* halves, float q) {
  Lanes x;
#if defined(__F16C__) && defined(__AVX__)
  // One instruction for 8 values (GCC 12 converts a _Float16 vector value by value).
  const __m256 wide = _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(halves)));
  std::memcpy(&x, &wide, sizeof x);
#else
  for (int l = 0; l < 8; ++l) x[l] = static_cast<float>(halves[l]);
#endif
  const Lanes diff = x - q;
  acc += diff * diff;
}

// The largest float partial sum over `terms` values of the screen that a row can have and still
// reach a model distance <= best. Its exact distance is then at most best + margin (the model's
// distance is within margin of the exact one: GemmErrorBound), so the exact partial sum of its
// half-precision copy is at most (sqrt(best + margin) + screen error)^2 (triangle inequality),
// and a float sum of `terms` squared differences exceeds the exact one by at most (terms + 2)
// units of 2^-24 relative (4 x that here).
float ScreenLimit(float best, double margin, double screen_error, int terms) {
  const double exact = std::max(0.0, static_cast<double>(best) + margin);
  const double root = std::sqrt(exact) * (1.0 + 0x1.0p-50) + screen_error;
  const double limit = root * root * (1.0 + 4.0 * (terms + 3) * 0x1.0p-24);
  return std::nextafter(static_cast<float>(limit), std::numeric_limits<float>::infinity());
}

// Bit l set where lane l of `sums` is not above `limit` (NaN is not above: such a row is kept).
unsigned NotAbove(const Lanes& sums, float limit) {
#if defined(__AVX__)
  __m256 wide;
  std::memcpy(&wide, &sums, sizeof wide);
  return ~static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(wide, _mm256_set1_ps(limit), _CMP_GT_OQ))) & 0xFFu;
#endif
  const auto above = sums > limit;
  unsigned mask = 0;
  for (unsigned l = 0; l < 8; ++l) mask |= (above[l] == 0 ? 1u : 0u) << l;
  return mask;
}

}  // namespace

IncrementalIndex::IncrementalIndex(int dim) : dim_(dim) {
  if (dim <= 0) throw std::invalid_argument("IncrementalIndex: dim must be positive, got " + std::to_string(dim));
  for (int end = kFirstCheck; end < dim; end += kCheckEvery) checks_.push_back(end);
  checks_.push_back(dim);
  limits_.resize(checks_.size());
  screen_.resize(checks_.size());
}

void IncrementalIndex::AppendScreen(std::size_t i, const float* row) {
  std::size_t from = 0;
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    const auto width = static_cast<std::size_t>(checks_[k]) - from;
    std::vector<_Float16>& band = screen_[k];
    if (i % kTileRows == 0) band.resize(band.size() + width * kTileRows, _Float16{});
    _Float16* tile = band.data() + i / kTileRows * width * kTileRows;
    for (std::size_t j = 0; j < width; ++j) tile[j * kTileRows + i % kTileRows] = static_cast<_Float16>(row[from + j]);
    from += width;
  }
  double error = 0.0;  // ||row - half(row)||^2: each difference of a float and a half is exact in double
  for (std::size_t j = 0; j < static_cast<std::size_t>(dim_); ++j) {
    const _Float16 half = static_cast<_Float16>(row[j]);  // round to nearest, as stored above
    const double diff = static_cast<double>(row[j]) - static_cast<double>(static_cast<float>(half));
    error += diff * diff;
  }
  // The double sum's own rounding (dim terms) is far below the 2^-30 added; an overflowed or
  // NaN value leaves the screen without a bound for this store (every row is then computed).
  const double bound = std::sqrt(error) * (1.0 + 0x1.0p-30);
  const float rounded_up = std::nextafter(static_cast<float>(bound), std::numeric_limits<float>::infinity());
  screen_error_ = std::isfinite(bound) ? std::max(screen_error_, rounded_up) : std::numeric_limits<float>::infinity();
}

void IncrementalIndex::Add(RobotId robot, FrameId frame, const float* descriptor) {
  data_.insert(data_.end(), descriptor, descriptor + dim_);
  norms_.push_back(Eigen::Map<const Eigen::VectorXf>(descriptor, dim_).squaredNorm());
  max_norm_ = std::max(max_norm_, norms_.back());
  AppendScreen(entries_.size(), descriptor);
  entries_.push_back({robot, frame});
}

void IncrementalIndex::RemoveIf(const std::function<bool(std::size_t)>& remove) {
  const auto dim = static_cast<std::size_t>(dim_);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (remove(i)) continue;
    if (kept != i) {
      std::copy_n(data_.begin() + static_cast<std::ptrdiff_t>(i * dim), dim,
                  data_.begin() + static_cast<std::ptrdiff_t>(kept * dim));
      norms_[kept] = norms_[i];
      entries_[kept] = entries_[i];
    }
    ++kept;
  }
  entries_.resize(kept);
  norms_.resize(kept);
  data_.resize(kept * dim);
  for (auto& band : screen_) band.clear();
  screen_error_ = 0.0f;
  for (std::size_t i = 0; i < kept; ++i) AppendScreen(i, Descriptor(i));
  max_norm_ = norms_.empty() ? 0.0f : *std::max_element(norms_.begin(), norms_.end());
  hint_ = 0;
}

IndexSearchResult IncrementalIndex::SearchFullScan(const float* query, FrameId query_frame, int window) const {
  IndexSearchResult result;
  const auto n = static_cast<Eigen::Index>(entries_.size());
  result.comparisons = n;
  if (n == 0) return result;

  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const Eigen::Map<const RowMajor> stored(data_.data(), n, dim_);
  const Eigen::Map<const Eigen::VectorXf> q(query, dim_);
  scratch_.resize(static_cast<std::size_t>(n));
  Eigen::Map<Eigen::VectorXf> dot(scratch_.data(), n);
  dot.noalias() = stored * q;
  const float q_norm = q.squaredNorm();

  Eigen::Index best = -1;
  float best_distance = 0.0f;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (InWindow(entries_[static_cast<std::size_t>(i)].frame, query_frame, window)) continue;
    const float d = ExpandedDistance(norms_[static_cast<std::size_t>(i)], dot[i], q_norm);
    if (best < 0 || d < best_distance) {
      best = i;
      best_distance = d;
    }
  }
  if (best >= 0) result.best = Match(static_cast<std::size_t>(best), best_distance);
  return result;
}

IndexSearchResult IncrementalIndex::Search(const float* query, FrameId query_frame, int window) const {
  IndexSearchResult result;
  const std::size_t n = entries_.size();
  result.comparisons = static_cast<std::int64_t>(n);
  if (n == 0) return result;
  const float q_norm = Eigen::Map<const Eigen::VectorXf>(query, dim_).squaredNorm();
  if (n <= kReadEveryRow && GemvRowKernelMatches(static_cast<Eigen::Index>(n), dim_)) {
    result.best = SearchEveryRow(query, query_frame, window, q_norm);
    return result;
  }
  const double margin = GemmErrorBound(max_norm_, q_norm, dim_);
  std::size_t best = n;
  float best_distance = 0.0f;
  const auto take = [&](std::size_t i, float d) {
    best = i, best_distance = d;
    SetLimits(d, margin);
  };
  if (hint_ < n && !InWindow(entries_[hint_].frame, query_frame, window)) {
    take(hint_, ModelDistance(hint_, query, q_norm));
  }
  for (std::size_t first = 0; first < n; first += kTileRows) {
    const unsigned survivors = best < n ? ScreenTile(first, query) : (1u << kTileRows) - 1;
    for (std::size_t i = first; i < std::min(n, first + kTileRows); ++i) {
      if ((survivors >> (i - first) & 1u) == 0 || i == best) continue;
      if (InWindow(entries_[i].frame, query_frame, window)) continue;
      const float d = ModelDistance(i, query, q_norm);
      if (best == n || d < best_distance || (d == best_distance && i < best)) take(i, d);
    }
  }
  if (best == n) return result;
  hint_ = best;
  result.best = Match(best, best_distance);
  return result;
}

void IncrementalIndex::SetLimits(float best, double margin) const {
  for (std::size_t k = 0; k < checks_.size(); ++k) limits_[k] = ScreenLimit(best, margin, screen_error_, checks_[k]);
}

// The rows of the tile starting at `first` that no check of the screen rules out. Four sums a
// lane, so that the adds do not wait on each other; any order of a float sum obeys the limit's
// error bound.
unsigned IncrementalIndex::ScreenTile(std::size_t first, const float* query) const {
  Lanes acc[4] = {};
  unsigned alive = (1u << kTileRows) - 1;
  std::size_t from = 0;
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    const auto end = static_cast<std::size_t>(checks_[k]);
    const _Float16* tile = screen_[k].data() + first * (end - from);  // first is a multiple of kTileRows
    const float* q = query + from;
    std::size_t j = 0;
    for (; j + 4 <= end - from; j += 4) {
      for (std::size_t a = 0; a < 4; ++a) AddSquaredDiffs(acc[a], tile + (j + a) * kTileRows, q[j + a]);
    }
    for (; j < end - from; ++j) AddSquaredDiffs(acc[0], tile + j * kTileRows, q[j]);
    const Lanes sums = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    alive &= NotAbove(sums, limits_[k]);
    if (alive == 0) return 0;
    from = end;
  }
  return alive;
}

// Every row's model distance, 8 rows at a time with the product's own kernel (gemv_row.h): the
// full scan's answer without an Eigen call or a bound.
std::optional<IndexMatch> IncrementalIndex::SearchEveryRow(const float* query, FrameId query_frame, int window,
                                                           float q_norm) const {
#if DVPR_GEMV_ROW_KERNEL
  const std::size_t n = entries_.size();
  scratch_.resize(n + kTileRows);
  for (std::size_t first = 0; first < n; first += kTileRows) {
    const float* rows[kTileRows];
    for (std::size_t r = 0; r < kTileRows; ++r) rows[r] = Descriptor(std::min(first + r, n - 1));
    GemvEightRows(rows, query, dim_, scratch_.data() + first);
  }
  std::size_t best = n;
  float best_distance = 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    if (InWindow(entries_[i].frame, query_frame, window)) continue;
    const float d = ExpandedDistance(norms_[i], scratch_[i], q_norm);
    if (best == n || d < best_distance) best = i, best_distance = d;
  }
  if (best == n) return std::nullopt;
  hint_ = best;
  return Match(best, best_distance);
#else
  (void)query, (void)query_frame, (void)window, (void)q_norm;
  throw std::logic_error("IncrementalIndex::SearchEveryRow: no row kernel in this build");
#endif
}

float IncrementalIndex::ModelDistance(std::size_t i, const float* query, float q_norm) const {
  const auto n = static_cast<Eigen::Index>(entries_.size());
#if DVPR_GEMV_ROW_KERNEL
  if (GemvRowKernelMatches(n, dim_)) return ExpandedDistance(norms_[i], GemvOneRow(Descriptor(i), query, dim_), q_norm);
#endif
  const float dot = GemvRowAsInFullProduct(data_.data(), n, dim_, static_cast<Eigen::Index>(i), query);
  return ExpandedDistance(norms_[i], dot, q_norm);
}

IndexMatch IncrementalIndex::Match(std::size_t i, float distance) const {
  // Rounding can make the expansion slightly negative for identical vectors.
  return IndexMatch{entries_[i].robot, entries_[i].frame, distance < 0.0f ? 0.0f : distance};
}

}  // namespace dvpr

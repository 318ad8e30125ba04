#include "agents/descriptor_index.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "agents/gemv_row.h"
#include "agents/l2.h"

namespace dvpr {
namespace {

bool InWindow(FrameId stored, FrameId query, int window) {
  return std::abs(static_cast<long>(stored.value) - query.value) <= window;
}

// The model's distance from a row's dot product: the one expression both searches round alike.
float ExpandedDistance(float norm, float dot, float q_norm) { return norm - 2.0f * dot + q_norm; }

// sum over [0, to) of (x - q)^2, in float, eight independent sums (vectorised).
float PartialSquaredL2(const float* x, const float* q, int to) {
  constexpr int kLanes = 8;
  float acc[kLanes] = {};
  int j = 0;
  for (; j + kLanes <= to; j += kLanes) {
    for (int l = 0; l < kLanes; ++l) {
      const float diff = x[j + l] - q[j + l];
      acc[l] += diff * diff;
    }
  }
  float sum = ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
  for (; j < to; ++j) sum += (x[j] - q[j]) * (x[j] - q[j]);
  return sum;
}

// For the 8 rows of a tile (value j of row l at tile[j * 8 + l]), the sum over [0, width) of
// (x - q)^2, in float: one vector of 8 sums, one row a lane, in the order of the values.
void TilePartialSquaredL2(const float* tile, const float* q, int width, float* out) {
  // A GNU vector of 8 floats (one AVX register, two SSE ones): the compiler left to itself
  // reduces across the values of a row instead of summing 8 rows side by side.
  using Lanes = float __attribute__((vector_size(8 * sizeof(float))));
  Lanes acc = {};
  for (int j = 0; j < width; ++j) {
    Lanes x;
    std::memcpy(&x, tile + static_cast<std::ptrdiff_t>(j) * 8, sizeof x);
    const Lanes diff = x - q[j];
    acc += diff * diff;
  }
  std::memcpy(out, &acc, sizeof acc);
}

// The largest float partial sum over `terms` values that a row can have and still reach a model
// distance <= best: the model's distance is within `margin` of the exact one (GemmErrorBound),
// the exact distance is at least the exact partial sum, and a float sum of `terms` squared
// differences exceeds the exact one by at most (terms + 2) units of 2^-24 relative (4 x that here).
float PruneLimit(float best, double margin, int terms) {
  const double exact = std::max(0.0, static_cast<double>(best) + margin);
  const double limit = exact * (1.0 + 4.0 * (terms + 3) * 0x1.0p-24);
  return std::nextafter(static_cast<float>(limit), std::numeric_limits<float>::infinity());
}

}  // namespace

IncrementalIndex::IncrementalIndex(int dim) : dim_(dim) {
  if (dim <= 0) throw std::invalid_argument("IncrementalIndex: dim must be positive, got " + std::to_string(dim));
  for (int end : {32, 64}) {
    if (end < dim) stage_end_[static_cast<std::size_t>(stages_++)] = end;
  }
  stage_end_[static_cast<std::size_t>(stages_++)] = dim;
}

void IncrementalIndex::AppendLead(std::size_t i, const float* row) {
  const auto width = static_cast<std::size_t>(stage_end_[0]);
  if (i % kTileRows == 0) tiles_.resize(tiles_.size() + width * kTileRows, 0.0f);
  float* tile = tiles_.data() + i / kTileRows * width * kTileRows;
  for (std::size_t j = 0; j < width; ++j) tile[j * kTileRows + i % kTileRows] = row[j];
  for (std::size_t s = 1; s + 1 < static_cast<std::size_t>(stages_); ++s) {
    lead_[s].insert(lead_[s].end(), row + stage_end_[s - 1], row + stage_end_[s]);
  }
}

bool IncrementalIndex::RestWithinLimits(std::size_t i, float partial, const float* query,
                                        const std::array<float, kMaxStages>& limits) const {
  for (std::size_t s = 1; s < static_cast<std::size_t>(stages_); ++s) {
    const int from = stage_end_[s - 1];
    const int width = stage_end_[s] - from;
    const bool lead = s + 1 < static_cast<std::size_t>(stages_);
    const float* x = lead ? lead_[s].data() + i * static_cast<std::size_t>(width) : Descriptor(i) + from;
    partial += PartialSquaredL2(x, query + from, width);
    if (partial > limits[s]) return false;
  }
  return true;
}

void IncrementalIndex::Add(RobotId robot, FrameId frame, const float* descriptor) {
  data_.insert(data_.end(), descriptor, descriptor + dim_);
  norms_.push_back(Eigen::Map<const Eigen::VectorXf>(descriptor, dim_).squaredNorm());
  max_norm_ = std::max(max_norm_, norms_.back());
  AppendLead(entries_.size(), descriptor);
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
  tiles_.clear();
  for (auto& lead : lead_) lead.clear();
  for (std::size_t i = 0; i < kept; ++i) AppendLead(i, Descriptor(i));
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
  std::array<float, kMaxStages> limits{};
  const auto take = [&](std::size_t i, float d) {
    best = i, best_distance = d;
    for (std::size_t s = 0; s < static_cast<std::size_t>(stages_); ++s) limits[s] = PruneLimit(d, margin, stage_end_[s]);
  };
  if (hint_ < n && !InWindow(entries_[hint_].frame, query_frame, window)) {
    take(hint_, ModelDistance(hint_, query, q_norm));
  }
  const auto width = static_cast<std::size_t>(stage_end_[0]);
  for (std::size_t first = 0; first < n; first += kTileRows) {
    float partial[kTileRows];
    TilePartialSquaredL2(tiles_.data() + first * width, query, stage_end_[0], partial);
    for (std::size_t i = first; i < std::min(n, first + kTileRows); ++i) {
      const float p = partial[i - first];
      if (best < n && p > limits[0]) continue;
      if (i == best || InWindow(entries_[i].frame, query_frame, window)) continue;
      if (best < n && !RestWithinLimits(i, p, query, limits)) continue;
      const float d = ModelDistance(i, query, q_norm);
      if (best == n || d < best_distance || (d == best_distance && i < best)) take(i, d);
    }
  }
  if (best == n) return result;
  hint_ = best;
  result.best = Match(best, best_distance);
  return result;
}

// Every row's model distance, 8 rows at a time with the product's own kernel (gemv_row.h): the
// full scan's answer without an Eigen call or a bound.
std::optional<IndexMatch> IncrementalIndex::SearchEveryRow(const float* query, FrameId query_frame, int window,
                                                           float q_norm) const {
#if DVPR_GEMV_ROW_KERNEL
  const std::size_t n = entries_.size();
  scratch_.resize(n + 2 * kTileRows);
  std::size_t first = 0;
  if (HasGemvSixteenRows()) {  // the same values, 16 rows at a time where the CPU has AVX-512
    for (; first + kTileRows < n; first += 2 * kTileRows) {
      const float* rows[2 * kTileRows];
      for (std::size_t r = 0; r < 2 * kTileRows; ++r) rows[r] = Descriptor(std::min(first + r, n - 1));
      GemvSixteenRows(rows, query, dim_, scratch_.data() + first);
    }
  }
  for (; first < n; first += kTileRows) {
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

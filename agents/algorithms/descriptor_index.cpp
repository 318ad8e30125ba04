#include "agents/algorithms/descriptor_index.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "agents/algorithms/gemv_row.h"
#include "agents/algorithms/l2.h"

namespace dvpr {
namespace {

bool InWindow(FrameId stored, const FrameInterval& window) { return window.Contains(stored.value); }

// The model's distance from a row's dot product: the one expression both searches round alike.
float ExpandedDistance(float norm, float dot, float q_norm) { return norm - 2.0f * dot + q_norm; }

}  // namespace

IncrementalIndex::IncrementalIndex(int dim) : dim_(dim), screen_(dim) {
  if (dim <= 0) throw std::invalid_argument("IncrementalIndex: dim must be positive, got " + std::to_string(dim));
  limits_.resize(screen_.checks().size());
}

void IncrementalIndex::Add(RobotId robot, FrameId frame, const float* descriptor) {
  data_.insert(data_.end(), descriptor, descriptor + dim_);
  norms_.push_back(Eigen::Map<const Eigen::VectorXf>(descriptor, dim_).squaredNorm());
  max_norm_ = std::max(max_norm_, norms_.back());
  screen_.Append(descriptor);
  entries_.push_back({robot, frame});
  ++changes_;
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
  screen_.Clear();
  for (std::size_t i = 0; i < kept; ++i) screen_.Append(Descriptor(i));
  max_norm_ = norms_.empty() ? 0.0f : *std::max_element(norms_.begin(), norms_.end());
  hint_ = 0;
  ++changes_;
}

IndexSearchResult IncrementalIndex::SearchFullScan(const float* query, FrameId query_frame,
                                                   const FrameWindow& window) const {
  IndexSearchResult result;
  const FrameInterval skip = window.Around(query_frame.value);
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
    if (InWindow(entries_[static_cast<std::size_t>(i)].frame, skip)) continue;
    const float d = ExpandedDistance(norms_[static_cast<std::size_t>(i)], dot[i], q_norm);
    if (best < 0 || d < best_distance) {
      best = i;
      best_distance = d;
    }
  }
  if (best >= 0) result.best = Match(static_cast<std::size_t>(best), best_distance);
  return result;
}

IndexSearchResult IncrementalIndex::Search(const float* query, FrameId query_frame, const FrameWindow& window) const {
  IndexSearchResult result;
  const FrameInterval skip = window.Around(query_frame.value);
  const std::size_t n = entries_.size();
  result.comparisons = static_cast<std::int64_t>(n);
  if (n == 0) return result;
  const float q_norm = Eigen::Map<const Eigen::VectorXf>(query, dim_).squaredNorm();
  if (n <= kReadEveryRow && GemvRowKernelMatches(static_cast<Eigen::Index>(n), dim_)) {
    result.best = SearchEveryRow(query, skip, q_norm);
    return result;
  }
  const double margin = GemmErrorBound(max_norm_, q_norm, dim_);
  std::size_t best = n;
  float best_distance = 0.0f;
  const auto take = [&](std::size_t i, float d) {
    best = i, best_distance = d;
    SetLimits(d, margin);
  };
  if (hint_ < n && !InWindow(entries_[hint_].frame, skip)) {
    take(hint_, ModelDistance(hint_, query, q_norm));
  }
  for (std::size_t first = 0; first < n; first += HalfScreen::kTileRows) {
    const unsigned survivors = best < n ? screen_.Survivors(first, query, limits_.data()) : 0xFFu;
    for (std::size_t i = first; i < std::min(n, first + HalfScreen::kTileRows); ++i) {
      if ((survivors >> (i - first) & 1u) == 0 || i == best) continue;
      if (InWindow(entries_[i].frame, skip)) continue;
      const float d = ModelDistance(i, query, q_norm);
      if (best == n || d < best_distance || (d == best_distance && i < best)) take(i, d);
    }
  }
  if (best == n) return result;
  hint_ = best;
  result.best = Match(best, best_distance);
  return result;
}

// A row can still win if its model distance is at most best, so its exact distance at most
// best + margin (the model's distance is within margin of the exact one: GemmErrorBound).
void IncrementalIndex::SetLimits(float best, double margin) const {
  for (std::size_t k = 0; k < limits_.size(); ++k) limits_[k] = screen_.Limit(static_cast<double>(best) + margin, k);
}

// Every row's model distance, 8 rows at a time with the product's own kernel (gemv_row.h): the
// full scan's answer without an Eigen call or a bound.
std::optional<IndexMatch> IncrementalIndex::SearchEveryRow(const float* query, const FrameInterval& skip,
                                                           float q_norm) const {
#if DVPR_GEMV_ROW_KERNEL
  const std::size_t n = entries_.size();
  constexpr std::size_t kKernelRows = 8;  // GemvEightRows
  scratch_.resize(n + 2 * kKernelRows);
  std::size_t first = 0;
  if (HasGemvSixteenRows()) {  // the same values, 16 rows at a time where the CPU has AVX-512
    for (; first + kKernelRows < n; first += 2 * kKernelRows) {
      const float* rows[2 * kKernelRows];
      for (std::size_t r = 0; r < 2 * kKernelRows; ++r) rows[r] = Descriptor(std::min(first + r, n - 1));
      GemvSixteenRows(rows, query, dim_, scratch_.data() + first);
    }
  }
  for (; first < n; first += kKernelRows) {
    const float* rows[kKernelRows];
    for (std::size_t r = 0; r < kKernelRows; ++r) rows[r] = Descriptor(std::min(first + r, n - 1));
    GemvEightRows(rows, query, dim_, scratch_.data() + first);
  }
  std::size_t best = n;
  float best_distance = 0.0f;
  for (std::size_t i = 0; i < n; ++i) {
    if (InWindow(entries_[i].frame, skip)) continue;
    const float d = ExpandedDistance(norms_[i], scratch_[i], q_norm);
    if (best == n || d < best_distance) best = i, best_distance = d;
  }
  if (best == n) return std::nullopt;
  hint_ = best;
  return Match(best, best_distance);
#else
  (void)query, (void)skip, (void)q_norm;
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

#include "agents/descriptor_index.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "agents/l2.h"

namespace dvpr {
namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Whether row i of an n-row product `stored * q` falls in the single-row tail of Eigen 3.4's
// row-major matrix-vector kernel (general_matrix_vector_product<..., RowMajor, ...>::run in
// GeneralMatrixVector.h): rows go in blocks of 8 (none when a row is over 32000 bytes), then
// 4, then 2, all summing a row alike; only a last single row sums the dim % packet tail with
// half packets, which can round differently.
bool GemvSingleRow(std::size_t i, std::size_t n, int dim) {
  const auto rows = static_cast<long>(n);
  long next = 0;
  const long n8 = static_cast<std::size_t>(dim) * sizeof(float) > 32000 ? 0 : rows - 7;
  if (next < n8) next += (n8 - next + 7) / 8 * 8;
  if (next < rows - 3) next += (rows - 3 - next + 3) / 4 * 4;
  if (next < rows - 1) next += (rows - 1 - next + 1) / 2 * 2;
  return static_cast<long>(i) >= next;
}

// Row i's entry of the n-row product `stored * q` that SearchAll computes, bit for bit: the same
// Eigen expression on 1, 2 or 3 rows around i, chosen so that row i is summed by the same code
// (Eigen takes a dot product for one row, the 2-row block or the single-row tail otherwise).
float GemvRowDot(const float* data, std::size_t n, int dim, std::size_t i, const float* query) {
  const auto d = static_cast<std::size_t>(dim);
  std::size_t first = i;
  Eigen::Index rows = 1;
  if (n > 1 && GemvSingleRow(i, n, dim)) {  // the last row and n >= 3, so i >= 2
    first = i - 2;
    rows = 3;
  } else if (n > 1) {
    first = i + 1 < n ? i : i - 1;
    rows = 2;
  }
  float out[3];
  Eigen::Map<Eigen::VectorXf> dot(out, rows);
  dot.noalias() = Eigen::Map<const RowMajor>(data + first * d, rows, dim) * Eigen::Map<const Eigen::VectorXf>(query, dim);
  return out[i - first];
}

}  // namespace

IncrementalIndex::IncrementalIndex(int dim) : dim_(dim) {
  if (dim <= 0) throw std::invalid_argument("IncrementalIndex: dim must be positive, got " + std::to_string(dim));
}

void IncrementalIndex::Add(RobotId robot, FrameId frame, const float* descriptor) {
  data_.insert(data_.end(), descriptor, descriptor + dim_);
  norms_.push_back(Eigen::Map<const Eigen::VectorXf>(descriptor, dim_).squaredNorm());
  max_norm_ = std::max(max_norm_, norms_.back());
  entries_.push_back({robot, frame});
  if (!groups_.empty()) groups_.Add(descriptor, static_cast<std::uint32_t>(size() - 1));
  if (size() >= regroup_at_) {  // regroup when the store has doubled: amortised O(sqrt(n)) per row
    groups_.Rebuild(data_.data(), size(), dim_);
    regroup_at_ = 2 * size();
  }
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
  groups_.Clear();  // members' indices moved; max_norm_ still bounds the survivors
  regroup_at_ = std::max(kGroupedFrom, kept);
  if (kept >= kGroupedFrom) {
    groups_.Rebuild(data_.data(), kept, dim_);
    regroup_at_ = 2 * kept;
  }
}

IndexSearchResult IncrementalIndex::Search(const float* query, FrameId query_frame, int window) const {
  return groups_.empty() ? SearchAll(query, query_frame, window) : SearchGrouped(query, query_frame, window);
}

float IncrementalIndex::PlainDistance(std::size_t i, const float* query, float q_norm) const {
  return norms_[i] - 2.0f * GemvRowDot(data_.data(), size(), dim_, i, query) + q_norm;
}

// Groups in the order of their lower bounds; a row whose float distance (any summation order,
// off the exact one by at most `err`) is within 4 err of the best so far is a candidate, and a
// group whose bound exceeds the best by 8 err cannot hold one. Returns the best float distance.
double IncrementalIndex::CollectCandidates(const float* query, float q_norm, double err, FrameId query_frame,
                                           int window) const {
  groups_.LowerBounds(query, q_norm, bounds_);
  order_.resize(bounds_.size());
  for (std::size_t g = 0; g < order_.size(); ++g) order_[g] = static_cast<std::uint32_t>(g);
  std::sort(order_.begin(), order_.end(), [this](std::uint32_t a, std::uint32_t b) {
    return bounds_[a] < bounds_[b] || (bounds_[a] == bounds_[b] && a < b);
  });
  const Eigen::Map<const Eigen::VectorXf> q(query, dim_);
  double best = std::numeric_limits<double>::infinity();
  candidates_.clear();
  for (const std::uint32_t g : order_) {
    if (bounds_[g] > best + 8.0 * err) break;
    for (const std::uint32_t i : groups_.members(g)) {
      if (InWindow(i, query_frame, window)) continue;
      const float screen = norms_[i] - 2.0f * Eigen::Map<const Eigen::VectorXf>(Descriptor(i), dim_).dot(q) + q_norm;
      if (static_cast<double>(screen) > best + 4.0 * err) continue;
      candidates_.emplace_back(screen, i);
      best = std::min(best, static_cast<double>(screen));
    }
  }
  return best;
}

// The candidates left within 4 err of the final best include every row SearchAll could pick
// (its distance is off the exact one by at most err too); their SearchAll distances decide.
IndexSearchResult IncrementalIndex::SearchGrouped(const float* query, FrameId query_frame, int window) const {
  IndexSearchResult result;
  result.comparisons = static_cast<std::int64_t>(size());
  const float q_norm = Eigen::Map<const Eigen::VectorXf>(query, dim_).squaredNorm();
  const double err = static_cast<double>(GemmErrorBound(q_norm, max_norm_, dim_));
  const double best = CollectCandidates(query, q_norm, err, query_frame, window);
  std::int64_t best_i = -1;
  float best_distance = 0.0f;
  for (const auto& [screen, i] : candidates_) {
    if (static_cast<double>(screen) > best + 4.0 * err) continue;
    const float d = PlainDistance(i, query, q_norm);
    if (best_i < 0 || d < best_distance || (d == best_distance && i < best_i)) {
      best_i = i;
      best_distance = d;
    }
  }
  if (best_i >= 0) {
    const auto& e = entries_[static_cast<std::size_t>(best_i)];
    result.best = IndexMatch{e.robot, e.frame, best_distance < 0.0f ? 0.0f : best_distance};
  }
  return result;
}

IndexSearchResult IncrementalIndex::SearchAll(const float* query, FrameId query_frame, int window) const {
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
    const auto& e = entries_[static_cast<std::size_t>(i)];
    if (std::abs(static_cast<long>(e.frame.value) - query_frame.value) <= window) continue;
    const float d = norms_[static_cast<std::size_t>(i)] - 2.0f * dot[i] + q_norm;
    if (best < 0 || d < best_distance) {
      best = i;
      best_distance = d;
    }
  }
  if (best >= 0) {
    const auto& e = entries_[static_cast<std::size_t>(best)];
    // Rounding can make the expansion slightly negative for identical vectors.
    result.best = IndexMatch{e.robot, e.frame, best_distance < 0.0f ? 0.0f : best_distance};
  }
  return result;
}

}  // namespace dvpr

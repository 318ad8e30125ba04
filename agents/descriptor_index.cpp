#include "agents/descriptor_index.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

namespace dvpr {

IncrementalIndex::IncrementalIndex(int dim) : dim_(dim) {
  if (dim <= 0) throw std::invalid_argument("IncrementalIndex: dim must be positive, got " + std::to_string(dim));
}

void IncrementalIndex::Add(RobotId robot, FrameId frame, const float* descriptor) {
  data_.insert(data_.end(), descriptor, descriptor + dim_);
  norms_.push_back(Eigen::Map<const Eigen::VectorXf>(descriptor, dim_).squaredNorm());
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
}

IndexSearchResult IncrementalIndex::Search(const float* query, FrameId query_frame, int window) const {
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

#include "agents/subcentroids.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "agents/l2.h"

namespace dvpr {
namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
constexpr int kLloydIterations = 3;
// Radii are exact double distances rounded up by this factor: double rounding is ~1e-16.
constexpr double kRadiusSlack = 1.0 + 1e-9;

}  // namespace

void SubCentroids::Clear() {
  centroids_.clear();
  centroid_norms_.clear();
  radius_.clear();
  members_.clear();
  max_centroid_norm_ = 0.0f;
}

void SubCentroids::Rebuild(const float* data, std::size_t n, int dim) {
  Clear();
  if (n == 0) return;
  dim_ = dim;
  const auto d = static_cast<std::size_t>(dim);
  const std::size_t k = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(n))));
  centroids_.resize(k * d);
  for (std::size_t g = 0; g < k; ++g) {  // evenly spaced rows seed the groups: deterministic
    std::copy_n(data + (g * n / k) * d, d, centroids_.begin() + static_cast<std::ptrdiff_t>(g * d));
  }
  UpdateNorms();
  std::vector<std::uint32_t> group;
  for (int it = 0; it < kLloydIterations; ++it) {
    AssignAll(data, n, group);
    MoveCentroids(data, group);
  }
  AssignAll(data, n, group);
  members_.assign(k, {});
  radius_.assign(k, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    members_[group[i]].push_back(static_cast<std::uint32_t>(i));
    Widen(group[i], data + i * d);
  }
}

void SubCentroids::AssignAll(const float* data, std::size_t n, std::vector<std::uint32_t>& group) const {
  const auto k = static_cast<Eigen::Index>(centroid_norms_.size());
  const Eigen::Map<const RowMajor> c(centroids_.data(), k, dim_);
  const Eigen::Map<const Eigen::VectorXf> cn(centroid_norms_.data(), k);
  group.resize(n);
  constexpr std::size_t kBlock = 1024;  // rows per GEMM, so the distance block stays small
  RowMajor dots;
  for (std::size_t first = 0; first < n; first += kBlock) {
    const auto rows = static_cast<Eigen::Index>(std::min(kBlock, n - first));
    const Eigen::Map<const RowMajor> x(data + first * static_cast<std::size_t>(dim_), rows, dim_);
    dots.noalias() = x * c.transpose();
    for (Eigen::Index r = 0; r < rows; ++r) {
      Eigen::Index best = 0;  // the row's own norm is common to all centroids
      (cn.transpose() - 2.0f * dots.row(r)).minCoeff(&best);
      group[first + static_cast<std::size_t>(r)] = static_cast<std::uint32_t>(best);
    }
  }
}

void SubCentroids::MoveCentroids(const float* data, const std::vector<std::uint32_t>& group) {
  const auto d = static_cast<std::size_t>(dim_);
  const std::size_t k = centroids_.size() / d;
  std::vector<double> sum(k * d, 0.0);
  std::vector<std::size_t> count(k, 0);
  for (std::size_t i = 0; i < group.size(); ++i) {
    double* s = sum.data() + group[i] * d;
    for (std::size_t j = 0; j < d; ++j) s[j] += data[i * d + j];
    ++count[group[i]];
  }
  for (std::size_t g = 0; g < k; ++g) {
    if (count[g] == 0) continue;  // an empty group keeps its centroid
    for (std::size_t j = 0; j < d; ++j) {
      centroids_[g * d + j] = static_cast<float>(sum[g * d + j] / static_cast<double>(count[g]));
    }
  }
  UpdateNorms();
}

void SubCentroids::UpdateNorms() {
  const std::size_t k = centroids_.size() / static_cast<std::size_t>(dim_);
  const Eigen::Map<const RowMajor> c(centroids_.data(), static_cast<Eigen::Index>(k), dim_);
  centroid_norms_.resize(k);
  Eigen::Map<Eigen::VectorXf>(centroid_norms_.data(), static_cast<Eigen::Index>(k)) = c.rowwise().squaredNorm();
  max_centroid_norm_ = *std::max_element(centroid_norms_.begin(), centroid_norms_.end());
}

std::size_t SubCentroids::Nearest(const float* row) const {
  const auto k = static_cast<Eigen::Index>(centroid_norms_.size());
  const Eigen::Map<const RowMajor> c(centroids_.data(), k, dim_);
  const Eigen::Map<const Eigen::VectorXf> x(row, dim_);
  Eigen::Index best = 0;
  (Eigen::Map<const Eigen::VectorXf>(centroid_norms_.data(), k) - 2.0f * (c * x)).minCoeff(&best);
  return static_cast<std::size_t>(best);
}

void SubCentroids::Widen(std::size_t g, const float* row) {
  const double dist = std::sqrt(ExactSquaredL2(row, centroids_.data() + g * static_cast<std::size_t>(dim_), dim_));
  radius_[g] = std::max(radius_[g], dist * kRadiusSlack);
}

void SubCentroids::Add(const float* row, std::uint32_t index) {
  const std::size_t g = Nearest(row);
  members_[g].push_back(index);
  Widen(g, row);
}

void SubCentroids::LowerBounds(const float* query, float query_sq_norm, std::vector<double>& out) const {
  const auto k = static_cast<Eigen::Index>(centroid_norms_.size());
  const Eigen::Map<const RowMajor> c(centroids_.data(), k, dim_);
  scratch_.resize(static_cast<std::size_t>(k));
  Eigen::Map<Eigen::VectorXf> dots(scratch_.data(), k);
  dots.noalias() = c * Eigen::Map<const Eigen::VectorXf>(query, dim_);
  // Rounding of the float expansion, and a factor 2 more for sqrt and the subtraction below.
  const double err = 2.0 * static_cast<double>(GemmErrorBound(query_sq_norm, max_centroid_norm_, dim_));
  out.resize(static_cast<std::size_t>(k));
  for (Eigen::Index g = 0; g < k; ++g) {
    const double qc = static_cast<double>(centroid_norms_[static_cast<std::size_t>(g)]) -
                      2.0 * static_cast<double>(dots[g]) + static_cast<double>(query_sq_norm);
    const double gap = std::sqrt(std::max(0.0, qc - err)) - radius_[static_cast<std::size_t>(g)];
    out[static_cast<std::size_t>(g)] = gap > 0.0 ? gap * gap / kRadiusSlack : 0.0;
  }
}

}  // namespace dvpr

#include "agents/algorithms/balanced_kmeans.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace dvpr {

namespace {

using EigenIndex = Eigen::Index;
using DoubleMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Pair {
  double distance;
  std::int32_t point;
  std::int32_t cluster;
};

// Exact squared distances, N x k, in double (the greedy sorts them, so ties must be real ties).
DoubleMatrix SquaredDistances(const DescriptorMatrix& points, const CentroidMatrix& centroids) {
  const DoubleMatrix x = points.cast<double>();
  const DoubleMatrix c = centroids.cast<double>();
  DoubleMatrix d = (-2.0 * x) * c.transpose();
  d.colwise() += x.rowwise().squaredNorm();
  d.rowwise() += c.rowwise().squaredNorm().transpose();
  return d.cwiseMax(0.0);
}

void CheckShapes(const DescriptorMatrix& points, const CentroidMatrix& centroids) {
  if (centroids.rows() < 1) throw std::invalid_argument("balanced k-means: no centroids");
  if (points.cols() != centroids.cols()) {
    throw std::invalid_argument("balanced k-means: points have " + std::to_string(points.cols()) +
                                " dimensions, centroids " + std::to_string(centroids.cols()));
  }
  if (points.rows() < centroids.rows()) {
    throw std::invalid_argument("balanced k-means: " + std::to_string(points.rows()) + " points for " +
                                std::to_string(centroids.rows()) + " clusters (need at least one each)");
  }
  if (!points.allFinite() || !centroids.allFinite()) {
    throw std::invalid_argument("balanced k-means: non-finite value in the points or centroids");
  }
}

CentroidMatrix Means(const DescriptorMatrix& points, const std::vector<int>& labels, EigenIndex k) {
  DoubleMatrix sums = DoubleMatrix::Zero(k, points.cols());
  std::vector<double> counts(static_cast<std::size_t>(k), 0.0);
  for (EigenIndex i = 0; i < points.rows(); ++i) {
    const int c = labels[static_cast<std::size_t>(i)];
    sums.row(c) += points.row(i).cast<double>();
    counts[static_cast<std::size_t>(c)] += 1.0;
  }
  for (EigenIndex c = 0; c < k; ++c) sums.row(c) /= counts[static_cast<std::size_t>(c)];  // every size >= 1
  return sums.cast<float>();
}

double Cost(const DescriptorMatrix& points, const CentroidMatrix& centroids, const std::vector<int>& labels) {
  double cost = 0;
  for (EigenIndex i = 0; i < points.rows(); ++i) {
    cost += (points.row(i).cast<double>() - centroids.row(labels[static_cast<std::size_t>(i)]).cast<double>())
                .squaredNorm();
  }
  return cost;
}

}  // namespace

std::vector<int> BalancedAssignment(const DescriptorMatrix& points, const CentroidMatrix& centroids) {
  CheckShapes(points, centroids);
  const EigenIndex n = points.rows();
  const EigenIndex k = centroids.rows();
  const DoubleMatrix d = SquaredDistances(points, centroids);
  std::vector<Pair> pairs;
  pairs.reserve(static_cast<std::size_t>(n * k));
  for (EigenIndex i = 0; i < n; ++i) {
    for (EigenIndex c = 0; c < k; ++c) pairs.push_back({d(i, c), static_cast<std::int32_t>(i), static_cast<std::int32_t>(c)});
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.point != b.point) return a.point < b.point;
    return a.cluster < b.cluster;
  });
  std::vector<int> labels(static_cast<std::size_t>(n), -1);
  std::vector<EigenIndex> sizes(static_cast<std::size_t>(k), 0);
  EigenIndex left = n;
  // Two passes: up to floor(N/k) per cluster, then the N mod k points left, one per cluster.
  for (const EigenIndex capacity : {n / k, n / k + 1}) {
    for (const Pair& p : pairs) {
      if (left == 0) break;
      int& label = labels[static_cast<std::size_t>(p.point)];
      EigenIndex& size = sizes[static_cast<std::size_t>(p.cluster)];
      if (label >= 0 || size >= capacity) continue;
      label = p.cluster;
      ++size;
      --left;
    }
  }
  return labels;
}

BalancedKMeansResult BalancedKMeansDetailed(const DescriptorMatrix& points, const KMeansParams& params) {
  params.Validate();
  if (points.rows() < params.k) {
    throw std::invalid_argument("balanced k-means: " + std::to_string(points.rows()) + " points for k = " +
                                std::to_string(params.k) + " clusters (need at least one each)");
  }
  CentroidMatrix centroids = KMeans(points, params);
  BalancedKMeansResult best;
  best.cost = -1;
  std::vector<int> previous;
  int since_best = 0;  // the greedy can cycle: stop after kPatience steps without a lower cost
  constexpr int kPatience = 10;
  for (int it = 1; it <= params.max_iterations && since_best < kPatience; ++it) {
    std::vector<int> labels = BalancedAssignment(points, centroids);
    const bool repeated = labels == previous;
    centroids = Means(points, labels, params.k);
    const double cost = Cost(points, centroids, labels);
    if (best.cost < 0 || cost < best.cost) {
      best.centroids = centroids;
      best.labels = labels;
      best.cost = cost;
      since_best = 0;
    } else {
      ++since_best;
    }
    best.iterations = it;
    if (repeated) {
      best.converged = true;
      break;
    }
    previous = std::move(labels);
  }
  best.sizes.assign(static_cast<std::size_t>(params.k), 0);
  for (int label : best.labels) ++best.sizes[static_cast<std::size_t>(label)];
  return best;
}

CentroidMatrix BalancedKMeans(const DescriptorMatrix& points, const KMeansParams& params) {
  return BalancedKMeansDetailed(points, params).centroids;
}

}  // namespace dvpr

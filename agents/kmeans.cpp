#include "agents/kmeans.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "agents/l2.h"
#include "agents/random_bits.h"

namespace dvpr {

void KMeansParams::Validate() const {
  if (k < 1) throw std::invalid_argument("KMeansParams.k must be >= 1, got " + std::to_string(k));
  if (max_iterations < 1) {
    throw std::invalid_argument("KMeansParams.max_iterations must be >= 1, got " +
                                std::to_string(max_iterations));
  }
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("KMeansParams.tolerance must be finite and >= 0");
  }
  if (restarts < 1) {
    throw std::invalid_argument("KMeansParams.restarts must be >= 1, got " +
                                std::to_string(restarts));
  }
}

namespace {

using Index = Eigen::Index;
using SumMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
constexpr Index kBlockRows = 512;  // rows per GEMM block: the block stays in L2 while reduced

struct Points {
  const DescriptorMatrix& x;
  Eigen::VectorXf norms;  // ||x_i||^2
};

// Index drawn with probability weight[i] / sum(weight); sum > 0.
Index DrawWeighted(const std::vector<double>& weight, double total, Xoshiro256& rng) {
  const double target = rng.Uniform() * total;
  double cumulative = 0;
  Index last_positive = 0;
  for (std::size_t i = 0; i < weight.size(); ++i) {
    if (weight[i] <= 0) continue;
    cumulative += weight[i];
    last_positive = static_cast<Index>(i);
    if (cumulative > target) return last_positive;
  }
  return last_positive;  // rounding left target just above the running sum
}

// Squared distance of every point to `center`, min-ed into `nearest`.
void UpdateNearest(const Points& p, const Eigen::RowVectorXf& center, std::vector<double>& nearest) {
  const Eigen::VectorXf dots = p.x * center.transpose();
  const float cn = center.squaredNorm();
  for (Index i = 0; i < p.x.rows(); ++i) {
    const double d = std::max(0.0f, p.norms[i] - 2.0f * dots[i] + cn);
    nearest[static_cast<std::size_t>(i)] = std::min(nearest[static_cast<std::size_t>(i)], d);
  }
}

// k-means++ (Arthur, Vassilvitskii 2007): first centre uniform, each next one drawn with
// probability proportional to the squared distance to the nearest centre chosen so far.
CentroidMatrix SeedPlusPlus(const Points& p, int k, Xoshiro256& rng) {
  const Index n = p.x.rows();
  CentroidMatrix centers(k, p.x.cols());
  std::vector<double> nearest(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  Index chosen = static_cast<Index>(rng.Below(static_cast<std::uint64_t>(n)));
  for (int c = 0; c < k; ++c) {
    centers.row(c) = p.x.row(chosen);
    if (c + 1 == k) break;
    UpdateNearest(p, centers.row(c), nearest);
    const double total = std::accumulate(nearest.begin(), nearest.end(), 0.0);
    // All points coincide with a centre: any point will do; the duplicate centre's cluster
    // comes out empty and is re-seeded by Lloyd.
    chosen = total > 0 ? DrawWeighted(nearest, total, rng)
                       : static_cast<Index>(rng.Below(static_cast<std::uint64_t>(n)));
  }
  return centers;
}

struct Assignment {
  std::vector<int> labels;
  std::vector<float> distance;  // squared distance to the assigned centroid
  SumMatrix sums;               // per cluster, sum of its points (double: order-independent enough)
  std::vector<Index> counts;
  double inertia = 0;
  Index changed = 0;            // points whose label differs from the previous assignment
};

// Nearest centroid of every point (ties to the lowest index) and the per-cluster sums, in one
// pass over the points: GEMM on a block of rows, then reduce it while it is in cache.
void Assign(const Points& p, const CentroidMatrix& centers, Assignment& a) {
  const Index n = p.x.rows();
  const Index k = centers.rows();
  const Eigen::VectorXf cn = SquaredNorms(centers);
  a.sums.setZero(k, p.x.cols());
  a.counts.assign(static_cast<std::size_t>(k), 0);
  a.inertia = 0;
  a.changed = 0;
  DistanceMatrix dots;
  for (Index first = 0; first < n; first += kBlockRows) {
    const Index rows = std::min(kBlockRows, n - first);
    dots.resize(rows, k);
    dots.noalias() = p.x.middleRows(first, rows) * centers.transpose();
    for (Index r = 0; r < rows; ++r) {
      const Index i = first + r;
      int best = 0;
      float best_score = cn[0] - 2.0f * dots(r, 0);
      for (Index c = 1; c < k; ++c) {
        const float score = cn[c] - 2.0f * dots(r, c);
        if (score < best_score) best_score = score, best = static_cast<int>(c);
      }
      auto& label = a.labels[static_cast<std::size_t>(i)];
      a.changed += (label != best);
      label = best;
      const float dist = std::max(0.0f, p.norms[i] + best_score);
      a.distance[static_cast<std::size_t>(i)] = dist;
      a.inertia += dist;
      a.sums.row(best) += p.x.row(i).cast<double>();
      ++a.counts[static_cast<std::size_t>(best)];
    }
  }
}

// Moves the farthest points (from their own centroid) into the empty clusters.
int RelocateEmpty(const Points& p, Assignment& a) {
  std::vector<int> empty;
  for (std::size_t c = 0; c < a.counts.size(); ++c) {
    if (a.counts[c] == 0) empty.push_back(static_cast<int>(c));
  }
  if (empty.empty()) return 0;
  std::vector<Index> order(a.labels.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index l, Index r) {
    return a.distance[static_cast<std::size_t>(l)] > a.distance[static_cast<std::size_t>(r)];
  });
  std::size_t next = 0;
  for (int c : empty) {
    while (next < order.size() &&
           a.counts[static_cast<std::size_t>(a.labels[static_cast<std::size_t>(order[next])])] < 2) {
      ++next;  // taking the only point of a cluster would just move the hole
    }
    if (next == order.size()) break;  // fewer distinct points than clusters: stays empty
    const Index i = order[next++];
    auto& label = a.labels[static_cast<std::size_t>(i)];
    a.sums.row(label) -= p.x.row(i).cast<double>();
    --a.counts[static_cast<std::size_t>(label)];
    a.sums.row(c) = p.x.row(i).cast<double>();
    a.counts[static_cast<std::size_t>(c)] = 1;
    label = c;
  }
  return static_cast<int>(empty.size());
}

double MeanVariance(const DescriptorMatrix& x) {
  const Eigen::RowVectorXd mean = x.cast<double>().colwise().mean();
  const double ss = (x.cast<double>().rowwise() - mean).squaredNorm();
  return ss / static_cast<double>(x.rows() * x.cols());
}

KMeansResult Lloyd(const Points& p, const KMeansParams& params, std::uint64_t seed,
                   double abs_tolerance) {
  Xoshiro256 rng(seed);
  KMeansResult result;
  result.centroids = SeedPlusPlus(p, params.k, rng);
  Assignment a;
  a.labels.assign(static_cast<std::size_t>(p.x.rows()), -1);
  a.distance.assign(static_cast<std::size_t>(p.x.rows()), 0.0f);
  for (int it = 0; it < params.max_iterations; ++it) {
    Assign(p, result.centroids, a);
    result.iterations = it + 1;
    if (it > 0 && a.changed == 0) {  // same labels, same centroids: a fixed point
      result.converged = true;
      break;
    }
    result.empty_cluster_reseeds += RelocateEmpty(p, a);
    double shift = 0;
    for (Index c = 0; c < result.centroids.rows(); ++c) {
      const auto count = a.counts[static_cast<std::size_t>(c)];
      if (count == 0) continue;  // no point to move it to: keep the old centroid
      const Eigen::RowVectorXf mean = (a.sums.row(c) / static_cast<double>(count)).cast<float>();
      shift += (mean - result.centroids.row(c)).cast<double>().squaredNorm();
      result.centroids.row(c) = mean;
    }
    if (shift <= abs_tolerance) {
      result.converged = true;
      break;
    }
  }
  Assign(p, result.centroids, a);  // labels and inertia of the final centroids
  result.labels = std::move(a.labels);
  result.inertia = a.inertia;
  return result;
}

}  // namespace

KMeansResult KMeansDetailed(const DescriptorMatrix& points, const KMeansParams& params) {
  params.Validate();
  if (points.rows() < params.k) {
    throw std::invalid_argument("KMeans: " + std::to_string(points.rows()) +
                                " points for k = " + std::to_string(params.k));
  }
  if (!points.allFinite()) throw std::invalid_argument("KMeans: points contain NaN or Inf");
  const Points p{points, SquaredNorms(points)};
  const double abs_tolerance = params.tolerance * MeanVariance(points);
  KMeansResult best;
  for (int r = 0; r < params.restarts; ++r) {
    KMeansResult run = Lloyd(p, params, MixSeed(params.seed, static_cast<std::uint64_t>(r)),
                             abs_tolerance);
    if (r == 0 || run.inertia < best.inertia) best = std::move(run);
  }
  return best;
}

CentroidMatrix KMeans(const DescriptorMatrix& points, const KMeansParams& params) {
  return KMeansDetailed(points, params).centroids;
}

std::vector<int> NearestCentroid(const DescriptorMatrix& points, const CentroidMatrix& centroids) {
  return NearestRows(points, centroids);
}

}  // namespace dvpr

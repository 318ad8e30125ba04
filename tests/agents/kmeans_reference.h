#pragma once
// Two references for agents/algorithms/kmeans.cpp, written out here so the tests do not trust the code
// they check:
//   kPlain   Lloyd's algorithm without bounds: every iteration scores every point against every
//            centroid with the full pass's GEMM (blocks of 512 rows from row 0) and takes the
//            lowest score, ties to the lowest index.
//   kHamerly the implementation before the bounded pass was reorganised for speed (dvpr at
//            b3ce8c3), verbatim: Hamerly's bounds, the points they do not clear gathered and
//            re-measured in GEMM blocks of 512.
// Both share the seeding, the empty-cluster re-seed and the centroid update of KMeansDetailed
// (agents/algorithms/kmeans.h), and keep the per-cluster sums the way it does (summed afresh on a full
// pass, then the points that move subtracted and added in index order): a fresh sum rounds
// differently in double and could move a float centroid by one ulp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "agents/algorithms/kmeans.h"
#include "agents/algorithms/l2.h"
#include "sim/random_bits.h"

namespace dvpr::kmeans_reference {

enum class Variant { kPlain, kHamerly };

using Index = Eigen::Index;
using SumMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
inline constexpr Index kBlockRows = 512;

struct Points {
  const DescriptorMatrix& x;
  Eigen::VectorXf norms;
};

inline Index DrawWeighted(const std::vector<double>& weight, double total, Xoshiro256& rng) {
  const double target = rng.Uniform() * total;
  double cumulative = 0;
  Index last_positive = 0;
  for (std::size_t i = 0; i < weight.size(); ++i) {
    if (weight[i] <= 0) continue;
    cumulative += weight[i];
    last_positive = static_cast<Index>(i);
    if (cumulative > target) return last_positive;
  }
  return last_positive;
}

inline CentroidMatrix SeedPlusPlus(const Points& p, int k, Xoshiro256& rng) {
  const Index n = p.x.rows();
  CentroidMatrix centers(k, p.x.cols());
  std::vector<double> nearest(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  Index chosen = static_cast<Index>(rng.Below(static_cast<std::uint64_t>(n)));
  for (int c = 0; c < k; ++c) {
    centers.row(c) = p.x.row(chosen);
    if (c + 1 == k) break;
    const Eigen::RowVectorXf center = centers.row(c);
    const Eigen::VectorXf dots = p.x * center.transpose();
    const float cn = center.squaredNorm();
    for (Index i = 0; i < n; ++i) {
      const double d = std::max(0.0f, p.norms[i] - 2.0f * dots[i] + cn);
      nearest[static_cast<std::size_t>(i)] = std::min(nearest[static_cast<std::size_t>(i)], d);
    }
    const double total = std::accumulate(nearest.begin(), nearest.end(), 0.0);
    chosen = total > 0 ? DrawWeighted(nearest, total, rng)
                       : static_cast<Index>(rng.Below(static_cast<std::uint64_t>(n)));
  }
  return centers;
}

struct State {
  std::vector<int> labels;
  std::vector<float> distance;
  std::vector<double> upper;
  std::vector<double> lower;
  SumMatrix sums;
  std::vector<Index> counts;
  double inertia = 0;
  Index changed = 0;
};

// Lowest and second-lowest score of row r (cn[c] - 2 x.c), ties to the lowest index.
inline void Scores(const DistanceMatrix& dots, Index r, const Eigen::VectorXf& cn, int& best,
                   float& best_score, float& second_score) {
  best = 0;
  best_score = std::numeric_limits<float>::infinity();
  second_score = best_score;
  for (Index c = 0; c < cn.size(); ++c) {
    const float score = cn[c] - 2.0f * dots(r, c);
    if (score < best_score) {
      second_score = best_score, best_score = score, best = static_cast<int>(c);
    } else if (score < second_score) {
      second_score = score;
    }
  }
}

// Moves point i from its cluster to `best`, with its sums.
inline void Move(const Points& p, Index i, int best, State& a) {
  const auto ui = static_cast<std::size_t>(i);
  const int own = a.labels[ui];
  if (best == own) return;
  ++a.changed;
  a.sums.row(own) -= p.x.row(i).cast<double>();
  a.sums.row(best) += p.x.row(i).cast<double>();
  --a.counts[static_cast<std::size_t>(own)];
  ++a.counts[static_cast<std::size_t>(best)];
  a.labels[ui] = best;
}

// The full pass: every point, blocks of 512 rows, sums afresh.
inline void Assign(const Points& p, const CentroidMatrix& centers, State& a) {
  const Index n = p.x.rows();
  const Eigen::VectorXf cn = SquaredNorms(centers);
  a.sums.setZero(centers.rows(), p.x.cols());
  a.counts.assign(static_cast<std::size_t>(centers.rows()), 0);
  a.inertia = 0;
  a.changed = 0;
  DistanceMatrix dots;
  for (Index first = 0; first < n; first += kBlockRows) {
    const Index rows = std::min(kBlockRows, n - first);
    dots.resize(rows, centers.rows());
    dots.noalias() = p.x.middleRows(first, rows) * centers.transpose();
    for (Index r = 0; r < rows; ++r) {
      const Index i = first + r;
      const auto ui = static_cast<std::size_t>(i);
      int best = 0;
      float best_score = 0;
      float second_score = 0;
      Scores(dots, r, cn, best, best_score, second_score);
      a.changed += (a.labels[ui] != best);
      a.labels[ui] = best;
      const float dist = std::max(0.0f, p.norms[i] + best_score);
      a.distance[ui] = dist;
      a.upper[ui] = std::sqrt(static_cast<double>(dist));
      a.lower[ui] = std::sqrt(static_cast<double>(std::max(0.0f, p.norms[i] + second_score)));
      a.inertia += dist;
      a.sums.row(best) += p.x.row(i).cast<double>();
      ++a.counts[static_cast<std::size_t>(best)];
    }
  }
}

// Plain Lloyd's step: the full pass's scores for every point; the points that change cluster
// move with their sums, in index order.
inline void AssignPlain(const Points& p, const CentroidMatrix& centers, State& a) {
  const Index n = p.x.rows();
  const Eigen::VectorXf cn = SquaredNorms(centers);
  a.changed = 0;
  DistanceMatrix dots;
  for (Index first = 0; first < n; first += kBlockRows) {
    const Index rows = std::min(kBlockRows, n - first);
    dots.resize(rows, centers.rows());
    dots.noalias() = p.x.middleRows(first, rows) * centers.transpose();
    for (Index r = 0; r < rows; ++r) {
      int best = 0;
      float best_score = 0;
      float second_score = 0;
      Scores(dots, r, cn, best, best_score, second_score);
      Move(p, first + r, best, a);
    }
  }
}

inline std::vector<double> HalfGaps(const CentroidMatrix& centers) {
  const Index k = centers.rows();
  std::vector<double> gap(static_cast<std::size_t>(k), std::numeric_limits<double>::infinity());
  for (Index c = 0; c < k; ++c) {
    for (Index o = 0; o < k; ++o) {
      if (o == c) continue;
      const double d = std::sqrt(static_cast<double>((centers.row(c) - centers.row(o)).squaredNorm()));
      gap[static_cast<std::size_t>(c)] = std::min(gap[static_cast<std::size_t>(c)], 0.5 * d);
    }
  }
  return gap;
}

// The previous bounded pass: Hamerly's tests, then the points left gathered (a copy of their
// rows) and re-measured in GEMM blocks of 512.
inline void AssignHamerly(const Points& p, const CentroidMatrix& centers, State& a) {
  const std::vector<double> gap = HalfGaps(centers);
  a.changed = 0;
  std::vector<Index> todo;
  for (Index i = 0; i < p.x.rows(); ++i) {
    const auto ui = static_cast<std::size_t>(i);
    const int own = a.labels[ui];
    const double limit = std::max(gap[static_cast<std::size_t>(own)], a.lower[ui]);
    if (a.upper[ui] <= limit) continue;
    a.upper[ui] = std::sqrt(static_cast<double>((p.x.row(i) - centers.row(own)).squaredNorm()));
    if (a.upper[ui] <= limit) continue;
    todo.push_back(i);
  }
  const Eigen::VectorXf cn = SquaredNorms(centers);
  DescriptorMatrix block;
  DistanceMatrix dots;
  for (std::size_t first = 0; first < todo.size(); first += kBlockRows) {
    const auto rows = static_cast<Index>(std::min<std::size_t>(kBlockRows, todo.size() - first));
    block.resize(rows, p.x.cols());
    for (Index r = 0; r < rows; ++r) block.row(r) = p.x.row(todo[first + static_cast<std::size_t>(r)]);
    dots.resize(rows, centers.rows());
    dots.noalias() = block * centers.transpose();
    for (Index r = 0; r < rows; ++r) {
      const Index i = todo[first + static_cast<std::size_t>(r)];
      int best = 0;
      float best_score = 0;
      float second_score = 0;
      Scores(dots, r, cn, best, best_score, second_score);
      a.upper[static_cast<std::size_t>(i)] = std::sqrt(static_cast<double>(std::max(0.0f, p.norms[i] + best_score)));
      a.lower[static_cast<std::size_t>(i)] = std::sqrt(static_cast<double>(std::max(0.0f, p.norms[i] + second_score)));
      Move(p, i, best, a);
    }
  }
}

inline void MoveBounds(const std::vector<double>& moved, State& a) {
  std::size_t far = 0;
  for (std::size_t c = 1; c < moved.size(); ++c) far = moved[c] > moved[far] ? c : far;
  double second = 0;
  for (std::size_t c = 0; c < moved.size(); ++c) second = c == far ? second : std::max(second, moved[c]);
  for (std::size_t i = 0; i < a.labels.size(); ++i) {
    const auto own = static_cast<std::size_t>(a.labels[i]);
    a.upper[i] += moved[own];
    a.lower[i] -= own == far ? second : moved[far];
  }
}

// Empty clusters take the farthest points from their own centroids (exact distances).
inline int RelocateEmpty(const Points& p, const CentroidMatrix& centers, State& a) {
  for (Index i = 0; i < p.x.rows(); ++i) {
    a.distance[static_cast<std::size_t>(i)] =
        (p.x.row(i) - centers.row(a.labels[static_cast<std::size_t>(i)])).squaredNorm();
  }
  std::vector<int> empty;
  for (std::size_t c = 0; c < a.counts.size(); ++c) {
    if (a.counts[c] == 0) empty.push_back(static_cast<int>(c));
  }
  std::vector<Index> order(a.labels.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index l, Index r) {
    return a.distance[static_cast<std::size_t>(l)] > a.distance[static_cast<std::size_t>(r)];
  });
  std::size_t next = 0;
  for (int c : empty) {
    while (next < order.size() &&
           a.counts[static_cast<std::size_t>(a.labels[static_cast<std::size_t>(order[next])])] < 2) {
      ++next;
    }
    if (next == order.size()) break;
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

inline double MeanVariance(const DescriptorMatrix& x) {
  Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(x.cols());
  Eigen::RowVectorXd sum_sq = Eigen::RowVectorXd::Zero(x.cols());
  for (Index i = 0; i < x.rows(); ++i) {
    const Eigen::RowVectorXd row = x.row(i).cast<double>();
    sum += row;
    sum_sq += row.cwiseProduct(row);
  }
  const double n = static_cast<double>(x.rows());
  return (sum_sq / n - (sum / n).cwiseProduct(sum / n)).mean();
}

// Moves the centroids to their clusters' means; returns the summed squared shift.
inline double UpdateCentroids(const State& a, CentroidMatrix& centroids, std::vector<double>& moved) {
  double shift = 0;
  for (Index c = 0; c < centroids.rows(); ++c) {
    const auto count = a.counts[static_cast<std::size_t>(c)];
    moved[static_cast<std::size_t>(c)] = 0;
    if (count == 0) continue;
    const Eigen::RowVectorXf mean = (a.sums.row(c) / static_cast<double>(count)).cast<float>();
    const double step = (mean - centroids.row(c)).cast<double>().squaredNorm();
    shift += step;
    moved[static_cast<std::size_t>(c)] = std::sqrt(step);
    centroids.row(c) = mean;
  }
  return shift;
}

inline KMeansResult Lloyd(const Points& p, const KMeansParams& params, std::uint64_t seed,
                          double abs_tolerance, Variant variant) {
  Xoshiro256 rng(seed);
  KMeansResult result;
  result.centroids = SeedPlusPlus(p, params.k, rng);
  State a;
  const auto n = static_cast<std::size_t>(p.x.rows());
  a.labels.assign(n, -1);
  a.distance.assign(n, 0.0f);
  a.upper.assign(n, 0.0);
  a.lower.assign(n, 0.0);
  bool full = true;
  std::vector<double> moved(static_cast<std::size_t>(params.k));
  for (int it = 0; it < params.max_iterations; ++it) {
    if (full) {
      Assign(p, result.centroids, a);
    } else if (variant == Variant::kPlain) {
      AssignPlain(p, result.centroids, a);
    } else {
      AssignHamerly(p, result.centroids, a);
    }
    result.iterations = it + 1;
    if (it > 0 && a.changed == 0) {
      result.converged = true;
      break;
    }
    full = std::find(a.counts.begin(), a.counts.end(), 0) != a.counts.end();
    if (full) result.empty_cluster_reseeds += RelocateEmpty(p, result.centroids, a);
    if (UpdateCentroids(a, result.centroids, moved) <= abs_tolerance) {
      result.converged = true;
      break;
    }
    if (!full) MoveBounds(moved, a);
  }
  Assign(p, result.centroids, a);
  result.labels = std::move(a.labels);
  result.inertia = a.inertia;
  return result;
}

// KMeansDetailed's contract (valid params, N >= k, finite points) with the chosen variant.
inline KMeansResult KMeans(const DescriptorMatrix& points, const KMeansParams& params, Variant variant) {
  const Points p{points, SquaredNorms(points)};
  const double abs_tolerance = params.tolerance * MeanVariance(points);
  KMeansResult best;
  for (int r = 0; r < params.restarts; ++r) {
    KMeansResult run = Lloyd(p, params, MixSeed(params.seed, static_cast<std::uint64_t>(r)), abs_tolerance,
                             variant);
    if (r == 0 || run.inertia < best.inertia) best = std::move(run);
  }
  return best;
}

}  // namespace dvpr::kmeans_reference

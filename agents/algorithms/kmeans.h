#pragma once
// k-means clustering of descriptor space (docs/design.md section 1, step 1): k-means++ seeding,
// then Lloyd iterations. Full assignment passes use distances through matrix products (Eigen GEMM,
// ||x||^2 - 2 x.c + ||c||^2; on x86-64-v3 most entries come from agents/algorithms/kmeans_dots.h, which
// sums each one as the GEMM does); the passes in between skip the points that Hamerly's bounds
// prove cannot change cluster, which is most of them once the centroids settle. Deterministic for a
// seed: the random draws come from sim/random_bits.h (no std distributions), the arithmetic has a
// fixed order, and Eigen runs single-threaded, so a seed gives the same centroids with any standard
// library and any number of threads (float results may differ between CPUs with different SIMD widths).
#include <cstdint>
#include <vector>

#include "agents/algorithms/descriptors.h"

namespace dvpr {

struct KMeansParams {
  int k = 0;                  // clusters; required (>= 1)
  int max_iterations = 300;   // Lloyd iterations per restart (scikit-learn's default)
  // Stop when the summed squared centroid shift of an iteration is at most
  // tolerance x (mean per-dimension variance of the points): scikit-learn's convention, so the
  // same value means the same thing whatever the scale of the descriptors. 0: stop only when no
  // point changes cluster (or at max_iterations).
  double tolerance = 1e-4;
  int restarts = 1;           // independent seedings; the lowest inertia wins (sklearn n_init)
  std::uint64_t seed = 0;
  void Validate() const;      // throws std::invalid_argument naming the field
  bool operator==(const KMeansParams&) const = default;
};

struct KMeansResult {
  CentroidMatrix centroids;   // k x d
  std::vector<int> labels;    // nearest centroid of each point (float GEMM, ties to lowest)
  double inertia = 0;         // sum of squared distances of the points to their centroids
  int iterations = 0;         // Lloyd iterations of the winning restart
  bool converged = false;     // stopped by tolerance or by stable labels, not max_iterations
  int empty_cluster_reseeds = 0;
};

// Clusters the rows of `points` (N x d, N >= k). Empty clusters: whenever an iteration leaves a
// cluster without points, it is re-seeded at the point farthest from its own centroid (ties to
// the lowest index; never the only point of its cluster), which leaves its old cluster; several
// empty clusters take the farthest points in decreasing distance (scikit-learn's strategy).
// Throws std::invalid_argument on invalid params, fewer than k points, or non-finite values.
KMeansResult KMeansDetailed(const DescriptorMatrix& points, const KMeansParams& params);

// The centroids of KMeansDetailed, bit for bit, without its final pass that labels every point.
CentroidMatrix KMeans(const DescriptorMatrix& points, const KMeansParams& params);

// Index of the nearest centroid of every row of `points`, exact (ties to the lowest index); see
// NearestRows in agents/algorithms/l2.h.
std::vector<int> NearestCentroid(const DescriptorMatrix& points, const CentroidMatrix& centroids);

}  // namespace dvpr

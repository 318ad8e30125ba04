#pragma once
// Balanced (size-constrained) k-means (issue 8): every cluster gets floor(N/k) or ceil(N/k) of
// the N points, so that clusters of equal size carry equal load when the deployment looks like
// the points clustered.
//
// Formulation: Bradley, Bennett, Demiriz, "Constrained k-means clustering" (Microsoft Research
// TR-2000-65) and Malinen, Franti, "Balanced k-means for clustering" (S+SSPR 2014): Lloyd's
// iterations in which the assignment step is a minimum-cost assignment under the size
// constraints. The exact assignment (min-cost flow, or Hungarian on N x N in Malinen and Franti)
// costs O(N^2 k) or more per iteration; here it is the greedy on sorted (distance, point,
// cluster) pairs: the globally closest pair whose point is free and whose cluster has room is
// taken first, first up to floor(N/k) points per cluster, then the N mod k points left over
// go to distinct clusters by the same rule. O(N k log(N k)) per iteration.
//
// The greedy step does not always lower the cost, so the iterations stop when the assignment
// repeats, after 10 steps without a lower cost (the greedy can cycle), or at max_iterations, and
// the lowest-cost assignment seen is returned. The start is
// plain k-means (agents/algorithms/kmeans.h) with the same seed. Deterministic: distances are exact
// (double) and ties go to the lower point, then the lower cluster index.
#include <cstdint>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/kmeans.h"

namespace dvpr {

struct BalancedKMeansResult {
  CentroidMatrix centroids;  // k x d: the mean of each cluster's points
  std::vector<int> labels;   // cluster of each point under the size constraint (not nearest!)
  std::vector<int> sizes;    // points per cluster: floor(N/k) or ceil(N/k)
  double cost = 0;           // sum of squared distances of the points to their cluster's centroid
  int iterations = 0;        // constrained assignment steps run
  bool converged = false;    // the assignment repeated (not stopped by patience or max_iterations)
};

// `params` as for KMeansDetailed (k >= 1, N >= k); max_iterations bounds the constrained
// iterations too. Throws std::invalid_argument naming the problem.
BalancedKMeansResult BalancedKMeansDetailed(const DescriptorMatrix& points, const KMeansParams& params);

// The centroids of BalancedKMeansDetailed.
CentroidMatrix BalancedKMeans(const DescriptorMatrix& points, const KMeansParams& params);

// The constrained assignment step alone: labels of `points` given `centroids` (see above).
std::vector<int> BalancedAssignment(const DescriptorMatrix& points, const CentroidMatrix& centroids);

}  // namespace dvpr

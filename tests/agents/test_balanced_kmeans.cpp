// Balanced (size-constrained) k-means on hand-made point sets whose constrained optimum is
// worked out by hand in the comments.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/balanced_kmeans.h"
#include "agents/algorithms/kmeans.h"
#include "sim/random_bits.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Column;

std::vector<int> Sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(BalancedAssignment, GreedyTakesTheClosestPairsUpToTheCapacity) {
  // Points 0 1 2 10 11 100, centroids 4.8 and 100 (plain k-means' answer). Capacity 3 each.
  // Squared distances in increasing order: 100->c1 (0), 2->c0 (7.84), 1->c0 (14.44),
  // 0->c0 (23.04): c0 is full; 10->c0 and 11->c0 are skipped; 11->c1 (7921), 10->c1 (8100).
  CentroidMatrix c(2, 1);
  c << 4.8f, 100.0f;
  EXPECT_EQ(BalancedAssignment(Column({0, 1, 2, 10, 11, 100}), c), (std::vector<int>{0, 0, 0, 1, 1, 1}));
}

TEST(BalancedAssignment, LeftoverPointsGoOnePerCluster) {
  // 5 points, 2 clusters: floor 2 each, then the one left goes to the closest cluster with room.
  // Centroids 0 and 10; points 0 1 2 3 10. Pass 1 (capacity 2): 0->c0 (0), 10->c1 (0),
  // 1->c0 (1): c0 full; 2->c0 (4) and 3->c0 (9) skipped; 3->c1 (49): c1 full; 2->c1 (64)
  // skipped. Pass 2 (capacity 3): point 2 is left, its closest pair 2->c0 (4) has room.
  CentroidMatrix c(2, 1);
  c << 0.0f, 10.0f;
  EXPECT_EQ(BalancedAssignment(Column({0, 1, 2, 3, 10}), c), (std::vector<int>{0, 0, 0, 1, 1}));
}

TEST(BalancedKMeans, SplitsALopsidedSetIntoEqualHalves) {
  // Plain k-means on 0 1 2 10 11 100 with k = 2 puts the outlier alone (centroids 4.8, 100).
  // With 3 points per cluster the optimum is {0,1,2} + {10,11,100}: cost 2 + (30.33^2 + 29.33^2
  // + 59.67^2) = 2 + 5340.67, against e.g. {0,1,10} + {2,11,100} at 60.67 + 5867.67. From plain
  // k-means' centroids the greedy reaches it in one step (first test); the means 1 and 40.333
  // then give the same assignment again (0 1 2 nearest 1; 10 11 are the closest pairs of 40.3
  // once the first cluster is full).
  const DescriptorMatrix x = Column({0, 1, 2, 10, 11, 100});
  const BalancedKMeansResult r = BalancedKMeansDetailed(x, {.k = 2, .seed = 3});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.sizes, (std::vector<int>{3, 3}));
  EXPECT_EQ(r.labels[0], r.labels[1]);
  EXPECT_EQ(r.labels[1], r.labels[2]);
  EXPECT_EQ(r.labels[3], r.labels[4]);
  EXPECT_EQ(r.labels[4], r.labels[5]);
  EXPECT_NE(r.labels[0], r.labels[5]);
  std::vector<float> centres{r.centroids(0, 0), r.centroids(1, 0)};
  std::sort(centres.begin(), centres.end());
  EXPECT_NEAR(centres[0], 1.0, 1e-5);
  EXPECT_NEAR(centres[1], 121.0 / 3.0, 1e-4);
  EXPECT_NEAR(r.cost, 2.0 + (30.333333 * 30.333333 + 29.333333 * 29.333333 + 59.666667 * 59.666667), 1e-3);
}

TEST(BalancedKMeans, EqualSeparatedBlobsAreFoundAsPlainKMeansFindsThem) {
  // Four blobs of five points around (0,0), (10,0), (0,10), (10,10) in 2-D: the unconstrained
  // optimum is already balanced, so the constrained one is the same partition.
  DescriptorMatrix x(20, 2);
  const float centres[4][2] = {{0, 0}, {10, 0}, {0, 10}, {10, 10}};
  const float offsets[5][2] = {{0, 0}, {0.5f, 0}, {-0.5f, 0}, {0, 0.5f}, {0, -0.5f}};
  for (int b = 0; b < 4; ++b) {
    for (int o = 0; o < 5; ++o) x.row(b * 5 + o) << centres[b][0] + offsets[o][0], centres[b][1] + offsets[o][1];
  }
  const BalancedKMeansResult r = BalancedKMeansDetailed(x, {.k = 4, .seed = 11});
  EXPECT_EQ(Sorted(r.sizes), (std::vector<int>{5, 5, 5, 5}));
  for (int b = 0; b < 4; ++b) {
    for (int o = 1; o < 5; ++o) EXPECT_EQ(r.labels[static_cast<std::size_t>(b * 5 + o)], r.labels[static_cast<std::size_t>(b * 5)]);
  }
  EXPECT_NEAR(r.cost, 4 * 4 * 0.25, 1e-4);  // four offsets of 0.5 per blob
}

TEST(BalancedKMeans, SizesAreFloorOrCeilOnSkewedData) {
  // 103 points, 90 of them in one tight blob: plain k-means gives the 13 outliers clusters of
  // their own; balanced k-means must give every cluster 10 or 11 points (three of 11).
  Xoshiro256 rng(7);
  DescriptorMatrix x(103, 3);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const float spread = i < 90 ? 0.1f : 5.0f;
    for (Eigen::Index j = 0; j < x.cols(); ++j) x(i, j) = spread * static_cast<float>(rng.Uniform() - 0.5);
  }
  const BalancedKMeansResult r = BalancedKMeansDetailed(x, {.k = 10, .seed = 5});
  EXPECT_EQ(std::count(r.sizes.begin(), r.sizes.end(), 11), 3);
  EXPECT_EQ(std::count(r.sizes.begin(), r.sizes.end(), 10), 7);
  // The same seed gives the same centroids, bit for bit.
  EXPECT_EQ(BalancedKMeans(x, {.k = 10, .seed = 5}), r.centroids);
}

TEST(BalancedKMeans, RejectsBadInput) {
  EXPECT_THROW(BalancedKMeans(Column({1, 2}), {.k = 3}), std::invalid_argument);
  EXPECT_THROW(BalancedKMeans(Column({1, 2}), {.k = 0}), std::invalid_argument);
  CentroidMatrix c(1, 2);
  c << 0, 0;
  EXPECT_THROW(BalancedAssignment(Column({1, 2}), c), std::invalid_argument);  // dims differ
  EXPECT_THROW(BalancedAssignment(Column({1, std::nanf("")}), Column({0})), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr

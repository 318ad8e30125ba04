// k-means: finds well-separated blobs, is deterministic for a seed, handles empty clusters.
#include <algorithm>
#include <cstring>
#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

#include "agents/algorithms/kmeans.h"
#include "sim/random_bits.h"

namespace dvpr {
namespace {

// `per_blob` points around each of `blobs` centres at (100 * b) on every axis, with uniform
// jitter in [-1, 1): blobs are 100 * sqrt(d) apart, far more than their 2 * sqrt(d) diameter.
DescriptorMatrix Blobs(int blobs, int per_blob, int dim, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(blobs * per_blob, dim);
  for (int i = 0; i < x.rows(); ++i) {
    const int b = i % blobs;  // interleaved, so the blob of a point is not its position
    for (int j = 0; j < dim; ++j) {
      x(i, j) = static_cast<float>(100.0 * b + 2.0 * rng.Uniform() - 1.0);
    }
  }
  return x;
}

TEST(KMeans, FindsWellSeparatedBlobs) {
  const int blobs = 5;
  const DescriptorMatrix x = Blobs(blobs, 40, 8, 7);
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    const KMeansResult r = KMeansDetailed(x, {.k = blobs, .seed = seed});
    EXPECT_TRUE(r.converged);
    // Every centroid lies within its blob (|jitter| < 1 per axis), one centroid per blob.
    std::set<int> found;
    for (int c = 0; c < blobs; ++c) {
      const int b = static_cast<int>(std::lround(r.centroids(c, 0) / 100.0));
      found.insert(b);
      for (int j = 0; j < x.cols(); ++j) EXPECT_NEAR(r.centroids(c, j), 100.0 * b, 1.0);
    }
    EXPECT_EQ(found.size(), static_cast<std::size_t>(blobs)) << "seed " << seed;
    // Points of the same blob share a label, points of different blobs do not.
    for (int i = 0; i < x.rows(); ++i) {
      EXPECT_EQ(r.labels[static_cast<std::size_t>(i)], r.labels[static_cast<std::size_t>(i % blobs)]);
    }
  }
}

// KMeans skips the final labelling pass that KMeansDetailed makes; its centroids must not
// change, with one restart or several (whose inertia picks the winner).
TEST(KMeans, CentroidsAreThoseOfKMeansDetailed) {
  const DescriptorMatrix x = Blobs(4, 60, 16, 13) + DescriptorMatrix::Constant(240, 16, 0.25f);
  for (const int restarts : {1, 3}) {
    const KMeansParams p{.k = 9, .restarts = restarts, .seed = 5};
    const CentroidMatrix a = KMeans(x, p);
    const CentroidMatrix b = KMeansDetailed(x, p).centroids;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(float) * static_cast<std::size_t>(a.size())))
        << "restarts " << restarts;
  }
}

TEST(KMeans, SameSeedGivesIdenticalBytes) {
  const DescriptorMatrix x = Blobs(3, 100, 16, 11) + DescriptorMatrix::Constant(300, 16, 0.5f);
  const KMeansParams p{.k = 7, .seed = 42};  // more clusters than blobs: the seed matters
  const CentroidMatrix a = KMeans(x, p);
  const CentroidMatrix b = KMeans(x, p);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(float) * static_cast<std::size_t>(a.size())));
  KMeansParams other = p;
  other.seed = 43;
  EXPECT_FALSE(KMeans(x, other).isApprox(a)) << "the seed should change the seeding";
}

TEST(KMeans, RestartsKeepTheLowestInertia) {
  const DescriptorMatrix x = Blobs(4, 30, 4, 3);
  double worst_single = 0;
  for (int r = 0; r < 4; ++r) {  // restart r of a 4-restart run uses MixSeed(seed, r)
    KMeansParams single{.k = 6, .seed = MixSeed(9, static_cast<std::uint64_t>(r))};
    worst_single = std::max(worst_single, KMeansDetailed(x, single).inertia);
  }
  const KMeansResult best = KMeansDetailed(x, {.k = 6, .restarts = 4, .seed = 9});
  for (int r = 0; r < 4; ++r) {
    KMeansParams single{.k = 6, .seed = MixSeed(9, static_cast<std::uint64_t>(r))};
    EXPECT_LE(best.inertia, KMeansDetailed(x, single).inertia);
  }
  EXPECT_LE(best.inertia, worst_single);
}

TEST(KMeans, EmptyClusterIsReseededAtTheFarthestPoint) {
  // Ten copies of A and one B, k = 3: k-means++ must pick a duplicate centre, whose cluster is
  // empty (ties go to the lower centroid). The farthest point from its own centroid that is not
  // alone in its cluster is a copy of A (distance 0), so the hole is filled with A: centroids
  // {A, B, A} in some order, inertia 0, no NaN.
  DescriptorMatrix x = DescriptorMatrix::Zero(11, 2);
  x(10, 0) = 10.0f;  // B = (10, 0), A = (0, 0)
  const KMeansResult r = KMeansDetailed(x, {.k = 3, .seed = 1});
  EXPECT_TRUE(r.centroids.allFinite());
  EXPECT_GE(r.empty_cluster_reseeds, 1);
  EXPECT_DOUBLE_EQ(r.inertia, 0.0);
  int copies_of_a = 0;
  int copies_of_b = 0;
  for (int c = 0; c < 3; ++c) {
    copies_of_a += r.centroids.row(c).isZero();
    copies_of_b += r.centroids(c, 0) == 10.0f && r.centroids(c, 1) == 0.0f;
  }
  EXPECT_EQ(copies_of_a, 2);
  EXPECT_EQ(copies_of_b, 1);
}

TEST(KMeans, MoreClustersThanDistinctValues) {
  // 0 x 5, 1, 9 (1-D) with k = 4: k-means++ picks the three distinct values first (a chosen
  // value has weight 0), then a duplicate, whose cluster is empty. The re-seed never takes the
  // only point of a cluster (that would move the hole), so it takes a 0: centroids {0, 0, 1, 9}
  // for every seed.
  DescriptorMatrix x = DescriptorMatrix::Zero(7, 1);
  x(5, 0) = 1.0f;
  x(6, 0) = 9.0f;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const KMeansResult r = KMeansDetailed(x, {.k = 4, .seed = seed});
    std::vector<float> c(r.centroids.data(), r.centroids.data() + 4);
    std::sort(c.begin(), c.end());
    EXPECT_EQ(c, (std::vector<float>{0, 0, 1, 9})) << "seed " << seed;
  }
}

TEST(KMeans, RejectsBadInput) {
  const DescriptorMatrix x = DescriptorMatrix::Ones(3, 2);
  try {
    KMeans(x, {.k = 0});
    FAIL() << "k = 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("KMeansParams.k"), std::string::npos);
  }
  EXPECT_THROW(KMeans(x, {.k = 4}), std::invalid_argument);  // fewer points than clusters
  EXPECT_THROW(KMeans(x, {.k = 2, .max_iterations = 0}), std::invalid_argument);
  EXPECT_THROW(KMeans(x, {.k = 2, .tolerance = -1}), std::invalid_argument);
  DescriptorMatrix bad = x;
  bad(1, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(KMeans(bad, {.k = 2}), std::invalid_argument);
}

TEST(NearestCentroid, ExactTiesGoToTheLowestIndex) {
  // x = (1, 0) is at squared distance 1 from both (0, 0) and (2, 0), and 4 from (3, 0).
  CentroidMatrix c(3, 2);
  c << 3, 0, 2, 0, 0, 0;
  DescriptorMatrix x(2, 2);
  x << 1, 0, 2.9f, 0;
  EXPECT_EQ(NearestCentroid(x, c), (std::vector<int>{1, 0}));
}

}  // namespace
}  // namespace dvpr

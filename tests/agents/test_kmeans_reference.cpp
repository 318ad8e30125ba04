// k-means against the references of tests/agents/kmeans_reference.h: bit for bit the same
// centroids, labels, iteration counts and inertia as the previous implementation on every input
// (random data, near-ties, exact ties, duplicates, empty clusters, k = 1..25, block edges), and
// the same as plain Lloyd where no score falls within a rounding of another.
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/kmeans.h"
#include "sim/random_bits.h"
#include "tests/agents/kmeans_reference.h"

namespace dvpr {
namespace {

using kmeans_reference::Variant;

// Uniform values in [0, 1) (d = 128 like the sweep's descriptors, or fewer).
DescriptorMatrix RandomPoints(Eigen::Index n, Eigen::Index d, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(n, d);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < d; ++j) x(i, j) = static_cast<float>(rng.Uniform());
  }
  return x;
}

// Small integers (0..levels-1) on few axes: many duplicate points and exactly tied distances,
// and more clusters than distinct points once k is large (empty clusters, re-seeds).
DescriptorMatrix LatticePoints(Eigen::Index n, Eigen::Index d, int levels, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(n, d);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < d; ++j) x(i, j) = static_cast<float>(rng.Below(static_cast<std::uint64_t>(levels)));
  }
  return x;
}

// Lattice points moved by a few ulps: distances that differ only in their last bits, where the
// rounding of each product decides the label.
DescriptorMatrix NearTiePoints(Eigen::Index n, Eigen::Index d, std::uint64_t seed) {
  DescriptorMatrix x = LatticePoints(n, d, 3, seed);
  Xoshiro256 rng(MixSeed(seed, 1));
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    x.data()[i] += static_cast<float>(static_cast<double>(rng.Below(5)) * 0x1.0p-22);
  }
  return x;
}

// Random points far from the origin: the scores ||c||^2 - 2 x.c cancel most of their bits, so
// the rounding of each product (which depends on where its row falls in Eigen's GEMM blocks)
// decides many labels.
DescriptorMatrix FarPoints(Eigen::Index n, Eigen::Index d, std::uint64_t seed) {
  return (RandomPoints(n, d, seed).array() + 3000.0f).matrix();
}

void ExpectSame(const KMeansResult& got, const KMeansResult& want, const std::string& what) {
  ASSERT_EQ(got.centroids.rows(), want.centroids.rows()) << what;
  ASSERT_EQ(got.centroids.cols(), want.centroids.cols()) << what;
  EXPECT_EQ(0, std::memcmp(got.centroids.data(), want.centroids.data(),
                           sizeof(float) * static_cast<std::size_t>(want.centroids.size())))
      << what << ": centroids differ";
  EXPECT_EQ(got.labels, want.labels) << what;
  EXPECT_EQ(got.iterations, want.iterations) << what;
  EXPECT_EQ(got.converged, want.converged) << what;
  EXPECT_EQ(got.empty_cluster_reseeds, want.empty_cluster_reseeds) << what;
  EXPECT_EQ(got.inertia, want.inertia) << what;
}

// Runs KMeansDetailed and the reference for every k of `ks` (up to the number of points), with
// the default tolerance and with 0 (which runs to stable labels), on x.
void CompareKs(const DescriptorMatrix& x, const std::vector<int>& ks, Variant variant, const std::string& name) {
  for (const int k : ks) {
    if (k > x.rows()) continue;
    for (const double tolerance : {1e-4, 0.0}) {
      const KMeansParams p{.k = k, .tolerance = tolerance, .seed = MixSeed(17, static_cast<std::uint64_t>(k))};
      const std::string what = name + " k=" + std::to_string(k) + " tol=" + std::to_string(tolerance);
      ExpectSame(KMeansDetailed(x, p), kmeans_reference::KMeans(x, p, variant), what);
    }
  }
}

// k = 1..25, and a spread of them where a fit of all 25 would make the test slow.
const std::vector<int> kAllK = [] {
  std::vector<int> k(25);
  std::iota(k.begin(), k.end(), 1);
  return k;
}();
const std::vector<int> kSomeK{1, 2, 3, 5, 8, 11, 16, 20, 25};

TEST(KMeansReference, RandomDataAsThePreviousImplementation) {
  // 1300 rows: two full GEMM blocks and a partial one; 128 and 5 columns (Eigen's kernels
  // treat a width without a SIMD tail and one with differently).
  CompareKs(RandomPoints(1300, 128, 1), kSomeK, Variant::kHamerly, "random 1300x128");
  CompareKs(RandomPoints(1300, 5, 2), kAllK, Variant::kHamerly, "random 1300x5");
}

TEST(KMeansReference, FewPointsAsThePreviousImplementation) {
  for (const Eigen::Index n : {1, 2, 3, 9, 25, 26}) {
    CompareKs(RandomPoints(n, 7, static_cast<std::uint64_t>(n)), kAllK, Variant::kHamerly,
                "random " + std::to_string(n) + "x7");
  }
}

TEST(KMeansReference, TiesAndEmptyClustersAsThePreviousImplementation) {
  CompareKs(LatticePoints(1100, 2, 3, 4), kAllK, Variant::kHamerly, "lattice 1100x2, 9 distinct");
  CompareKs(LatticePoints(700, 3, 4, 5), kAllK, Variant::kHamerly, "lattice 700x3");
  CompareKs(NearTiePoints(1100, 16, 6), kSomeK, Variant::kHamerly, "near ties 1100x16");
}

TEST(KMeansReference, RoundingDecidedLabelsAsThePreviousImplementation) {
  // Labels keep changing here, so the runs are capped at 40 iterations to keep the test fast.
  for (const auto& [x, name] : {std::pair{FarPoints(1300, 12, 10), "far 1300x12"},
                                std::pair{FarPoints(1100, 128, 9), "far 1100x128"}}) {
    for (const int k : {2, 5, 10, 11, 17, 25}) {  // 10 on 1300x12 catches a change of block size
      const KMeansParams p{.k = k, .max_iterations = 40, .seed = MixSeed(3, static_cast<std::uint64_t>(k))};
      ExpectSame(KMeansDetailed(x, p), kmeans_reference::KMeans(x, p, Variant::kHamerly),
                 std::string(name) + " k=" + std::to_string(k));
    }
  }
}

TEST(KMeansReference, RestartsAsThePreviousImplementation) {
  const DescriptorMatrix x = RandomPoints(900, 16, 8);
  const KMeansParams p{.k = 9, .restarts = 3, .seed = 5};
  ExpectSame(KMeansDetailed(x, p), kmeans_reference::KMeans(x, p, Variant::kHamerly), "restarts");
}

TEST(KMeansReference, RandomDataAsPlainLloyd) {
  // Continuous data: no two scores of a point within a rounding of each other on these inputs,
  // so the bounds and the gathered blocks change nothing.
  CompareKs(RandomPoints(1300, 128, 1), kSomeK, Variant::kPlain, "random 1300x128");
  CompareKs(RandomPoints(1300, 5, 2), kAllK, Variant::kPlain, "random 1300x5");
}

TEST(KMeansReference, TiesAndEmptyClustersAsPlainLloyd) {
  CompareKs(LatticePoints(1100, 2, 3, 4), kAllK, Variant::kPlain, "lattice 1100x2, 9 distinct");
  CompareKs(LatticePoints(700, 3, 4, 5), kAllK, Variant::kPlain, "lattice 700x3");
}

}  // namespace
}  // namespace dvpr

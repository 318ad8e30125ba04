// GroupDots against Eigen's own product (points x centroids^T, row-major, as k-means calls it):
// every entry of every point in a full group of 4 columns bit for bit, with both kernels (AVX and,
// where the CPU has it, AVX-512), for every chain order (k = 2..21 puts centroid rows in panels
// of 16, 8, 4 and single rows), widths 16..128, products of 4 to 512 points, random values and
// values far from the origin (whose products round differently in each order).
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/kmeans_dots.h"
#include "agents/algorithms/l2.h"
#include "sim/random_bits.h"

namespace dvpr {
namespace {

using Index = Eigen::Index;

DescriptorMatrix Random(Index n, Index d, float offset, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(n, d);
  for (Index i = 0; i < x.size(); ++i) x.data()[i] = offset + static_cast<float>(rng.Uniform() - 0.5);
  return x;
}

std::vector<DotsKernel> Kernels() {
  std::vector<DotsKernel> kernels{DotsKernel::kAvx2};
  if (HasAvx512Dots()) kernels.push_back(DotsKernel::kAvx512);
  return kernels;
}

TEST(KMeansDots, ChainOrdersFollowEigensPanels) {
  // Hand-worked from gebp_kernel's peeling: 24s, 16s, 8s, 4s, then single rows.
  EXPECT_EQ(ChainOf(0, 2), DotChain::kEight);
  EXPECT_EQ(ChainOf(3, 4), DotChain::kEvenOdd);
  EXPECT_EQ(ChainOf(7, 11), DotChain::kEvenOdd);
  EXPECT_EQ(ChainOf(8, 11), DotChain::kEight);
  EXPECT_EQ(ChainOf(11, 13), DotChain::kEvenOdd);
  EXPECT_EQ(ChainOf(12, 13), DotChain::kEight);
  EXPECT_EQ(ChainOf(15, 20), DotChain::kOne);
  EXPECT_EQ(ChainOf(16, 20), DotChain::kEvenOdd);
  EXPECT_EQ(ChainOf(16, 17), DotChain::kEight);
  EXPECT_EQ(ChainOf(23, 24), DotChain::kOne);
  EXPECT_EQ(ChainOf(40, 44), DotChain::kEvenOdd);
  EXPECT_FALSE(DotsReplicable(1, 128));   // a 1-column product is Eigen's GEMV
  EXPECT_FALSE(DotsReplicable(11, 100));  // not a multiple of 8
  EXPECT_FALSE(DotsReplicable(22, 128));  // the centroids could be cut into row blocks
  EXPECT_EQ(DotsReplicable(20, 128), DVPR_KMEANS_DOTS != 0);
}

TEST(KMeansDots, TransposeGroupPutsPointsInLanes) {
  if (!DVPR_KMEANS_DOTS) GTEST_SKIP() << "no AVX/FMA kernel in this build";
  const DescriptorMatrix x = Random(13, 24, 0.0f, 3);
  const float* rows[kGroupPoints];
  for (int lane = 0; lane < 13; ++lane) rows[lane] = x.row(lane).data();
  alignas(64) float xt[24 * kGroupPoints];
  std::fill(std::begin(xt), std::end(xt), 1.0f);
  TransposeGroup(rows, 13, 24, xt);
  for (int p = 0; p < 24; ++p) {
    for (int lane = 0; lane < kGroupPoints; ++lane) {
      EXPECT_EQ(xt[kGroupPoints * p + lane], lane < 13 ? x(lane, p) : 0.0f) << p << " " << lane;
    }
  }
}

// Every point of `x` in a full group of 4 columns against the Eigen product, bit for bit.
int Mismatches(const DescriptorMatrix& x, const CentroidMatrix& c, DotsKernel kernel) {
  const Index d = x.cols();
  const Index k = c.rows();
  DistanceMatrix want(x.rows(), k);
  want.noalias() = x * c.transpose();
  alignas(64) float xt[kMaxDotsDim * kGroupPoints];
  std::vector<float> got(static_cast<std::size_t>(k * kGroupPoints));
  int mismatches = 0;
  const Index grouped = x.rows() / 4 * 4;
  for (Index first = 0; first < grouped; first += kGroupPoints) {
    const int count = static_cast<int>(std::min<Index>(kGroupPoints, grouped - first));
    const float* rows[kGroupPoints];
    for (int lane = 0; lane < count; ++lane) rows[lane] = x.row(first + lane).data();
    TransposeGroup(rows, count, d, xt);
    GroupDots(xt, d, c.data(), k, got.data(), kernel);
    for (Index j = 0; j < k; ++j) {
      for (int lane = 0; lane < count; ++lane) {
        const float w = want(first + lane, j);
        mismatches += std::memcmp(&got[static_cast<std::size_t>(kGroupPoints * j + lane)], &w, sizeof(float)) != 0;
      }
    }
  }
  return mismatches;
}

TEST(KMeansDots, EveryChainAsEigensProduct) {
  if (!DVPR_KMEANS_DOTS) GTEST_SKIP() << "no AVX/FMA kernel in this build";
  int cases = 0;
  for (const DotsKernel kernel : Kernels()) {
    for (const Index d : {16, 64, 128}) {
      for (Index k = 2; k <= 21; ++k) {
        if (!DotsReplicable(k, d)) continue;
        for (const float offset : {0.0f, 3000.0f}) {
          const auto seed = static_cast<std::uint64_t>(d * 100 + k);
          const DescriptorMatrix x = Random(39, d, offset, seed);
          const CentroidMatrix c = Random(k, d, offset, MixSeed(seed, 1));
          EXPECT_EQ(Mismatches(x, c, kernel), 0) << "kernel " << static_cast<int>(kernel) << " d=" << d
                                                 << " k=" << k << " offset=" << offset;
          ++cases;
        }
      }
    }
  }
  EXPECT_GE(cases, 2 * 3 * 20);
}

// The products k-means makes: blocks of up to 512 points of width 128, k up to 20; the entries
// must not depend on how many points share the product.
TEST(KMeansDots, KMeansProductsAsEigensProduct) {
  if (!DVPR_KMEANS_DOTS) GTEST_SKIP() << "no AVX/FMA kernel in this build";
  for (const DotsKernel kernel : Kernels()) {
    for (const Index k : {2, 5, 11, 16, 20}) {
      for (const Index n : {4, 7, 17, 100, 511, 512}) {
        const auto seed = static_cast<std::uint64_t>(n * 100 + k);
        const DescriptorMatrix x = Random(n, 128, 0.25f, seed);
        const CentroidMatrix c = Random(k, 128, 0.25f, MixSeed(seed, 2));
        EXPECT_EQ(Mismatches(x, c, kernel), 0) << "kernel " << static_cast<int>(kernel) << " k=" << k << " n=" << n;
      }
    }
  }
}

}  // namespace
}  // namespace dvpr

// The centroid-to-robot table and the batched exact L2 it routes with.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "agents/algorithms/centroid_table.h"
#include "agents/algorithms/l2.h"
#include "sim/random_bits.h"

namespace dvpr {
namespace {

DescriptorMatrix Uniform(int rows, int cols, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(rows, cols);
  for (int i = 0; i < x.size(); ++i) x.data()[i] = static_cast<float>(rng.Uniform() * 2 - 1);
  return x;
}

TEST(CentroidTable, RoundRobinOwnersAndLookups) {
  // 6 centroids, 3 robots: owners 0 1 2 0 1 2.
  const CentroidTable t = CentroidTable::RoundRobin(Uniform(6, 4, 1), 3);
  EXPECT_EQ(t.num_centroids(), 6);
  EXPECT_EQ(t.OwnerOf(4), RobotId(1));
  EXPECT_EQ(t.CentroidsOf(RobotId(2)), (std::vector<int>{2, 5}));
  EXPECT_THROW(t.OwnerOf(6), std::out_of_range);
  EXPECT_THROW(t.CentroidsOf(RobotId(3)), std::out_of_range);
}

TEST(CentroidTable, RoutesToTheOwnerOfTheNearestCentroid) {
  // Centroids on a line at 0, 10, 20, 30, owned by robots 1, 0, 1, 0 (two each).
  CentroidMatrix c(4, 1);
  c << 0, 10, 20, 30;
  const CentroidTable t(c, {RobotId(1), RobotId(0), RobotId(1), RobotId(0)}, 2);
  DescriptorMatrix x(5, 1);
  x << -3, 6, 14, 26, 5;  // nearest: 0, 10, 10, 30, tie 0|10 -> 0
  const std::vector<RobotId> expected{RobotId(1), RobotId(0), RobotId(0), RobotId(0), RobotId(1)};
  EXPECT_EQ(t.RouteAll(x), expected);
  for (int i = 0; i < x.rows(); ++i) EXPECT_EQ(t.RouteOf(x.row(i)), expected[i]) << i;
  EXPECT_EQ(t.NearestCentroidOf(x.row(2).data()), 1);
}

TEST(CentroidTable, RouteAllAgreesWithRouteOf) {
  const CentroidTable t = CentroidTable::RoundRobin(Uniform(12, 32, 2), 5);
  const DescriptorMatrix x = Uniform(300, 32, 3);
  const std::vector<RobotId> all = t.RouteAll(x);
  for (int i = 0; i < x.rows(); ++i) ASSERT_EQ(all[static_cast<std::size_t>(i)], t.RouteOf(x.row(i)));
}

TEST(CentroidTable, RejectsInconsistentInput) {
  const CentroidMatrix c = Uniform(2, 3, 4);
  EXPECT_THROW(CentroidTable(c, {RobotId(0)}, 1), std::invalid_argument);
  EXPECT_THROW(CentroidTable(c, {RobotId(0), RobotId(2)}, 2), std::invalid_argument);
  EXPECT_THROW(CentroidTable(c, {RobotId(0), RobotId(0)}, 0), std::invalid_argument);
  EXPECT_THROW(CentroidTable(CentroidMatrix(0, 3), {}, 1), std::invalid_argument);
  const CentroidTable t(c, {RobotId(0), RobotId(0)}, 2);  // robot 1 owns nothing: allowed
  EXPECT_TRUE(t.CentroidsOf(RobotId(1)).empty());
  EXPECT_THROW(t.RouteOf(DescriptorMatrix::Zero(1, 2).row(0)), std::invalid_argument);
}

TEST(SquaredL2, MatchesDoubleWithinTheErrorBound) {
  const DescriptorMatrix a = Uniform(20, 128, 5);
  const DescriptorMatrix b = Uniform(30, 128, 6);
  const DistanceMatrix d = SquaredL2(a, b);
  const Eigen::VectorXf na = SquaredNorms(a);
  const Eigen::VectorXf nb = SquaredNorms(b);
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 30; ++j) {
      const double exact = (a.row(i).cast<double>() - b.row(j).cast<double>()).squaredNorm();
      EXPECT_NEAR(d(i, j), exact, GemmErrorBound(na[i], nb[j], 128));
      EXPECT_NEAR(ExactSquaredL2(a.row(i).data(), b.row(j).data(), 128), exact, 1e-12 * exact);
    }
  }
  EXPECT_THROW(SquaredL2(a, Uniform(2, 3, 1)), std::invalid_argument);
}

TEST(NearestRows, EqualsBruteForceInDouble) {
  // Near-duplicate references (differing by 1e-6) make float GEMM unable to tell them apart.
  DescriptorMatrix refs = Uniform(40, 64, 7);
  for (int j = 20; j < 40; ++j) refs.row(j) = refs.row(j - 20).array() + 1e-6f;
  const DescriptorMatrix q = Uniform(200, 64, 8);
  const std::vector<int> got = NearestRows(q, refs);
  for (int i = 0; i < q.rows(); ++i) {
    int best = 0;
    double best_d = 1e300;
    for (int j = 0; j < refs.rows(); ++j) {
      const double dd = (q.row(i).cast<double>() - refs.row(j).cast<double>()).squaredNorm();
      if (dd < best_d) best_d = dd, best = j;
    }
    ASSERT_EQ(got[static_cast<std::size_t>(i)], best) << "query " << i;
  }
}

// The nearest centroid by a plain scan in double, ties to the lowest index (written here).
int NearestByDoubleScan(const DescriptorMatrix& centroids, const float* x) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int c = 0; c < centroids.rows(); ++c) {
    double d = 0.0;
    for (int j = 0; j < centroids.cols(); ++j) d += std::pow(double{centroids(c, j)} - double{x[j]}, 2);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

TEST(CentroidTable, ScreenedNearestCentroidEqualsTheDoubleScan) {
  // Random values (widths with and without a tail of 8) and small integers (exact, full of
  // ties: the lowest index must win), 1000 centroids as in the large benchmarks.
  for (int dim : {3, 13, 128, 130}) {
    DescriptorMatrix random = Uniform(1000, dim, 7 + static_cast<std::uint64_t>(dim));
    DescriptorMatrix ints = (Uniform(1000, dim, 9) * 2.0f).array().round();
    for (const DescriptorMatrix* centroids : {&random, &ints}) {
      const CentroidTable t = CentroidTable::RoundRobin(*centroids, 10);
      const DescriptorMatrix queries = centroids == &ints ? DescriptorMatrix((Uniform(200, dim, 3) * 2.0f).array().round())
                                                          : Uniform(200, dim, 3);
      for (int i = 0; i < queries.rows(); ++i) {
        ASSERT_EQ(t.NearestCentroidOf(queries.row(i).data()), NearestByDoubleScan(*centroids, queries.row(i).data()))
            << "dim " << dim << " query " << i;
      }
    }
  }
}

TEST(CentroidTable, CentroidsHalfPrecisionCannotTellApartEqualTheDoubleScan) {
  // The screen keeps centroids in half precision (5e-4 apart at magnitude 1): centroids nudged
  // by less than that look alike to it, and values above 65504 (no finite half) or below 6e-5
  // (subnormal halves) stretch its error bound. The double scan decides every case.
  const int dim = 128;
  DescriptorMatrix near = Uniform(1000, dim, 21);
  for (int c = 500; c < 1000; ++c) near.row(c) = near.row(c % 50).array() + 1e-4f * Uniform(1, dim, 22 + c).row(0).array();
  const DescriptorMatrix huge = Uniform(1000, dim, 23) * 1e5f;
  const DescriptorMatrix tiny = Uniform(1000, dim, 24) * 1e-6f;
  for (const DescriptorMatrix* centroids : std::vector<const DescriptorMatrix*>{&near, &huge, &tiny}) {
    const CentroidTable t = CentroidTable::RoundRobin(*centroids, 10);
    const float scale = centroids->cwiseAbs().maxCoeff();
    DescriptorMatrix queries = centroids->topRows(100) + 3e-4f * scale * Uniform(100, dim, 25);  // next to a centroid
    queries.bottomRows(50) = Uniform(50, dim, 26) * scale;                                      // anywhere
    for (int i = 0; i < queries.rows(); ++i) {
      ASSERT_EQ(t.NearestCentroidOf(queries.row(i).data()), NearestByDoubleScan(*centroids, queries.row(i).data()))
          << "set " << (centroids == &near ? "near" : centroids == &huge ? "huge" : "tiny") << " query " << i;
    }
  }
}

}  // namespace
}  // namespace dvpr

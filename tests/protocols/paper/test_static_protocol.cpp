// The paper's static protocol: exact restricted best matches and one robot's evaluation. The
// whole sweep as `dvpr run` drives it (determinism, seeds, centroid files, agreement with the
// numpy implementation in tests/tools/paper_eval.py) is checked in tests/sweep/test_paper_sweep.cpp.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "sim/random_bits.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "tests/kitti_every_tenth.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

using testing_support::UniformMatrix;

// Brute force in double: argmin over j outside the window with pool[j] == pool[i], ties lowest.
MatchOutcome BruteForce(const DescriptorMatrix& x, const std::vector<RobotId>& pool, int window,
                        int i) {
  MatchOutcome out{FrameId(i), std::nullopt, 0};
  for (int j = 0; j < x.rows(); ++j) {
    if (std::abs(i - j) <= window || pool[static_cast<std::size_t>(j)] != pool[static_cast<std::size_t>(i)]) continue;
    const double d = (x.row(i).cast<double>() - x.row(j).cast<double>()).squaredNorm();
    if (!out.match || d < out.score) out = {FrameId(i), FrameId(j), d};
  }
  return out;
}

TEST(WindowedNeighbours, EqualsBruteForceForAnyListSize) {
  DescriptorMatrix x = UniformMatrix(150, 8, 1);
  for (int i = 100; i < 150; i += 7) x.row(i) = x.row(i - 90);  // exact ties in distance
  Xoshiro256 rng(2);
  std::vector<RobotId> pool;
  for (int i = 0; i < 150; ++i) pool.emplace_back(static_cast<int>(rng.Below(4)));
  pool[149] = RobotId(7);  // alone in its pool: no candidate
  for (int list_size : {1, 3, 200}) {
    const WindowedNeighbours nn(x, 5, list_size, 2);
    std::int64_t fallbacks = 0;
    const std::vector<MatchOutcome> got = nn.BestMatches(pool, &fallbacks);
    for (int i = 0; i < 150; ++i) {
      const MatchOutcome want = BruteForce(x, pool, 5, i);
      ASSERT_EQ(got[static_cast<std::size_t>(i)].match, want.match) << "list " << list_size << " query " << i;
      if (want.match) {
        EXPECT_NEAR(got[static_cast<std::size_t>(i)].score, want.score, 1e-12 * want.score);
      }
    }
    if (list_size == 1) {
      EXPECT_GT(fallbacks, 0);  // the fallback path was exercised
    }
    if (list_size == 200) {
      EXPECT_EQ(fallbacks, 0);
    }
  }
  EXPECT_FALSE(WindowedNeighbours(x, 5, 8, 1).BestMatches(pool)[149].match.has_value());
}

class PaperProtocolTest : public ::testing::Test {
 protected:
  static constexpr int kDim = 16;
  static constexpr int kWindow = 25;
  Dataset data_ = testing_support::KittiEveryTenth(kDim);
};

TEST_F(PaperProtocolTest, OneRobotReproducesTheCentralizedResult) {
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = kWindow}, 16, 1);
  EXPECT_EQ(evaluator.relevant(), 167);  // numpy on every 10th KITTI 00 pose, window 25
  const PaperRunResult r = evaluator.Evaluate(CentroidTable::RoundRobin(UniformMatrix(3, kDim, 6), 1), true);
  EXPECT_EQ(r.row.auc, evaluator.centralized().auc);
  EXPECT_EQ(r.row.relative_auc, 1.0);
  EXPECT_EQ(r.row.worst_balance_ratio, 1.0);
  EXPECT_EQ(r.curve.precision, evaluator.centralized().precision);
  EXPECT_GT(evaluator.centralized().auc, 0.3);  // smooth descriptors: revisits are found
}

TEST(ExpandCentroidPattern, ReplacesEveryPlaceholder) {
  EXPECT_EQ(ExpandCentroidPattern("c/{robots}/n{robots}_r{run}.npy", 12, 3), fs::path("c/12/n12_r3.npy"));
}

}  // namespace
}  // namespace dvpr

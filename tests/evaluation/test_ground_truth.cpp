// Ground truth: the suppression window, the strict radius, and KITTI 00's 1706 relevant queries.
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "experiments/domain/evaluation/ground_truth.h"
#include "tests/evaluation/evaluation_test_support.h"

namespace dvpr {
namespace {

using testing_support::OnLine;

TEST(GroundTruth, WindowExcludesNeighboursInTheSequence) {
  // Frame i at x = 10 i, except frame 6 back at x = 0.5 (a revisit of frame 0) and frame 1 at
  // x = 0.1, right next to frame 0 but inside its window. Window 3: |i - j| <= 3 excluded.
  //   g(0): candidates 4..7 -> frame 6 at 0.5 m -> 0.25
  //   g(1): candidates 5..7 -> frame 6 at 0.4 m -> 0.16
  //   g(3): candidate 7 only (frames 0 and 6 are exactly 3 away: excluded) -> 40 m -> 1600
  //   g(6): candidates 0..2 -> frame 1 at 0.4 m -> 0.16
  const Positions p = OnLine({0, 0.1, 20, 30, 40, 50, 0.5, 70});
  const std::vector<double> g = NearestOutsideWindowSquared(p, 3);
  EXPECT_NEAR(g[0], 0.25, 1e-12);
  EXPECT_NEAR(g[1], 0.16, 1e-12);
  EXPECT_NEAR(g[3], 1600.0, 1e-9);
  EXPECT_NEAR(g[6], 0.16, 1e-12);
  const auto relevant = RelevantFlags(p, {.radius_m = 1, .suppression_frames = 3});
  EXPECT_EQ(relevant, (std::vector<std::uint8_t>{1, 1, 0, 0, 0, 0, 1, 0}));
}

TEST(GroundTruth, ATeamPlansWindowStaysInsideEachRobotsFrames) {
  // The same eight frames as two robots' streams, robot 1 from frame 4 (a team plan). Window 3 now
  // stops at frame 3 | 4:
  //   g(3): its own 0..2 are within 3 frames; robot 1's 4..7 all count -> frame 4 at 10 m -> 100
  //   g(4): candidates 0..3 (robot 0's) and 7 -> frame 3 at 10 m -> 100
  //   g(6): candidates 0..3 and none of its own (4, 5, 7 within 3) -> frame 1 at 0.4 m -> 0.16
  //   g(0): 4..7 as before and nothing of its own beyond 3 -> frame 6 -> 0.25
  const Positions p = OnLine({0, 0.1, 20, 30, 40, 50, 0.5, 70});
  const FrameWindow streams(3, {FrameId(4)});
  const std::vector<double> g = NearestOutsideWindowSquared(p, streams);
  EXPECT_NEAR(g[3], 100.0, 1e-9);
  EXPECT_NEAR(g[4], 100.0, 1e-9);
  EXPECT_NEAR(g[6], 0.16, 1e-12);
  EXPECT_NEAR(g[0], 0.25, 1e-12);
  // Frame 2 (x = 20): its own 0, 1, 3 are within 3 frames; robot 1's 4..7 at 40, 50, 0.5, 70 ->
  // 19.5 m. Frame 5 (x = 50): its own are within 3; robot 0's 0..3 -> 20 m at frame 3.
  EXPECT_NEAR(g[2], 19.5 * 19.5, 1e-9);
  EXPECT_NEAR(g[5], 400.0, 1e-9);
  EXPECT_EQ(CountRelevant(p, 1.0, streams), 3);  // frames 0, 1 and 6, as with one stream
  // Radius 10.001 m: frames 3 and 4 (10 m apart across the streams' seam) become relevant too,
  // which the one-stream window (|3 - 4| = 1) never lets them be.
  EXPECT_EQ(RelevantFlags(p, 10.001, streams), (std::vector<std::uint8_t>{1, 1, 0, 1, 1, 0, 1, 0}));
  EXPECT_EQ(RelevantFlags(p, 10.001, FrameWindow(3)), (std::vector<std::uint8_t>{1, 1, 0, 0, 0, 0, 1, 0}));
}

TEST(GroundTruth, WindowBoundaryAndStrictRadius) {
  // Two frames 5 m apart. Window 1: |0 - 1| = 1 is inside, so no candidate at all (+inf).
  // Window 0: they are candidates, but 5 m is not < r = 5 m; r = 5.001 m makes both relevant.
  const Positions p = OnLine({0, 5});
  EXPECT_EQ(NearestOutsideWindowSquared(p, 1)[0], std::numeric_limits<double>::infinity());
  EXPECT_EQ(CountRelevant(p, {.radius_m = 5, .suppression_frames = 0}), 0);
  EXPECT_EQ(CountRelevant(p, {.radius_m = 5.001, .suppression_frames = 0}), 2);
  EXPECT_TRUE(IsCorrectMatch(p, 0, 1, 5.001));
  EXPECT_FALSE(IsCorrectMatch(p, 0, 1, 5.0));
  EXPECT_THROW(IsCorrectMatch(p, 0, 2, 5.0), std::out_of_range);
}

TEST(GroundTruth, RejectsBadParams) {
  EXPECT_THROW(RelevantFlags(OnLine({0}), {.radius_m = 0}), std::invalid_argument);
  EXPECT_THROW(RelevantFlags(OnLine({0}), {.suppression_frames = -1}), std::invalid_argument);
}

// Positions of a KITTI pose file: values 4, 8, 12 (1-based) of each row. Parsed here rather than
// with the loader so that this check depends on nothing but the file.
Positions KittiPositions(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<double> xyz;
  for (std::string line; std::getline(in, line);) {
    std::istringstream row(line);
    double v[12];
    for (double& x : v) row >> x;
    if (!row) throw std::runtime_error("short row in " + path);
    xyz.insert(xyz.end(), {v[3], v[7], v[11]});
  }
  return Eigen::Map<const Positions>(xyz.data(), static_cast<Eigen::Index>(xyz.size() / 3), 3);
}

TEST(GroundTruth, Kitti00Has1706RelevantQueries) {
  // The number the issue states; an independent numpy computation on the same file agrees:
  //   p = np.loadtxt(f)[:, [3, 7, 11]]; d = ((p[:, None] - p[None]) ** 2).sum(-1)
  //   i = np.arange(len(p)); d[abs(i[:, None] - i[None]) <= 250] = inf; (d.min(1) < 25).sum()
  const Positions p = KittiPositions(DVPR_SOURCE_DIR "/data/kitti/00_poses.txt");
  ASSERT_EQ(p.rows(), 4541);
  EXPECT_EQ(CountRelevant(p, {.radius_m = 5, .suppression_frames = 250}), 1706);
}

}  // namespace
}  // namespace dvpr

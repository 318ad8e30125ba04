// Many robots on the synthetic appearance model (the scaling benchmark's inputs, shrunk): every
// match the decentralized simulation reports is the exact nearest neighbour that a brute force
// in double precision, written here, finds among the frames the responder can have stored.
// The model's descriptors are far from each other and close to many (docs/performance.md), the
// hard case for the responders' pruned search; the team sizes give stores of ~200 and ~20 frames.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "agents/algorithms/kmeans.h"
#include "agents/placement/decentralized_placement.h"
#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/synthetic.h"
#include "experiments/protocols/sim/simulation.h"

namespace dvpr {
namespace {

constexpr int kFrames = 4000;
// The agents' distances are float (|x|^2 - 2 x.q + |q|^2 of unit-scale vectors); the brute force
// is double.
constexpr double kFloatTolerance = 1e-5;

Dataset Kitti00Prefix() {
  const Trajectory all = LoadKittiPoses(std::string(DVPR_SOURCE_DIR) + "/data/kitti/00_poses.txt");
  Dataset d;
  d.name = "kitti00_prefix";
  d.trajectory.positions = all.positions.topRows(kFrames);
  d.trajectory.headings = all.headings.topRows(kFrames);
  d.descriptors = SyntheticDeployment(d.trajectory, SyntheticParams{}, 1);
  return d;
}

// Trained on the deployment's own environment (other places): stores of similar size.
std::shared_ptr<const CentroidTable> DeploymentTrainedTable(int robots) {
  KMeansParams p;
  p.k = robots;
  p.seed = 3;
  p.max_iterations = 10;
  const DescriptorMatrix training =
      SyntheticTrainingDeploymentLike(SyntheticParams{}, SyntheticTrainingParams{.samples = 4000}, 1);
  return std::make_shared<CentroidTable>(CentroidTable::RoundRobin(KMeans(training, p), robots));
}

struct Nearest {
  int frame = -1;
  double distance = std::numeric_limits<double>::infinity();
};

class LargeTeamTest : public ::testing::TestWithParam<int> {
 protected:
  static const Dataset& Data() {
    static const Dataset data = Kitti00Prefix();
    return data;
  }
};

TEST_P(LargeTeamTest, EveryMatchIsTheExactNearestTheResponderCanHaveStored) {
  const int robots = GetParam();
  const Dataset& data = Data();
  const auto table = DeploymentTrainedTable(robots);
  const DecentralizedPlacement routing(table);
  SimRunParams params;
  params.scenario.robots = robots;
  params.scenario.network.model = LinkModelKind::kIdeal;  // a frame is stored at its capture time
  params.scenario.agent.service.fixed = SimTime::Zero();
  params.scenario.agent.service.per_comparison = SimTime::Zero();
  const SimRunLog log = RunSimulation(data, routing, params);
  ASSERT_EQ(log.queries.size(), static_cast<std::size_t>(kFrames));

  std::vector<RobotId> owner(kFrames);
  for (int f = 0; f < kFrames; ++f) owner[static_cast<std::size_t>(f)] = table->RouteOf(data.descriptors.row(f).data());
  const int window = params.scenario.agent.suppression_frames;
  int exact = 0;
  int with_match = 0;
  for (const QueryRecord& q : log.queries) {
    const int i = q.frame.value;
    const SimTime t = log.capture_time[static_cast<std::size_t>(i)];
    // Stored before i for certain (captured earlier), and possibly (captured at the same instant
    // by another robot, served first).
    Nearest earlier;
    Nearest same_instant;
    for (int j = 0; j < kFrames; ++j) {
      if (j == i || owner[static_cast<std::size_t>(j)] != owner[static_cast<std::size_t>(i)]) continue;
      if (std::abs(i - j) <= window) continue;
      const SimTime tj = log.capture_time[static_cast<std::size_t>(j)];
      if (tj > t) continue;
      const double d = (data.descriptors.row(i).cast<double>() - data.descriptors.row(j).cast<double>()).squaredNorm();
      Nearest& best = tj < t ? earlier : same_instant;
      if (d < best.distance) best = {j, d};
    }
    if (!q.best) {
      EXPECT_EQ(earlier.frame, -1) << "frame " << i << " got no match";
      continue;
    }
    ++with_match;
    const int m = q.best->frame.value;
    if (log.capture_time[static_cast<std::size_t>(m)] < t) {
      EXPECT_EQ(m, earlier.frame) << "frame " << i;
      EXPECT_NEAR(q.best->distance, earlier.distance, kFloatTolerance) << "frame " << i;
      ++exact;
    } else {
      // The match was captured at the same instant: it beat every earlier frame.
      EXPECT_LE(q.best->distance, earlier.distance + kFloatTolerance) << "frame " << i;
      EXPECT_GE(q.best->distance, same_instant.distance - kFloatTolerance) << "frame " << i;
    }
  }
  EXPECT_GT(with_match, kFrames / 2);
  EXPECT_GT(exact, with_match / 2);
}

INSTANTIATE_TEST_SUITE_P(TeamSizes, LargeTeamTest, ::testing::Values(20, 200),
                         [](const auto& info) { return std::to_string(info.param) + "Robots"; });

}  // namespace
}  // namespace dvpr

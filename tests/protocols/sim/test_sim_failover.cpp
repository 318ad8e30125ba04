// Failover in the simulation on a team whose every query can be followed by hand: three robots,
// every frame routed to robot 2, robot 2 dropped mid-run (docs/failover.md).
#include <gtest/gtest.h>

#include <memory>

#include "agents/placement/decentralized_placement.h"
#include "agents/placement/failover_placement.h"
#include "agents/placement/probe_placement.h"
#include "experiments/protocols/sim/simulation.h"

namespace dvpr {
namespace {

constexpr int kRobots = 3, kFramesEach = 20;

// 60 frames at 10 fps, 20 per robot (frame k of a robot at k x 100 ms). Descriptor of frame f:
// (6 + 0.001 f, 9). Centroids (0, 0), (10, 0), (0, 10) of robots 0, 1, 2: the distances to them
// are about 10.8, 9.8 and 6.1, so every frame goes to robot 2 and, robot 2 lost, to robot 1.
// Distinct descriptors keep every match distance above verification.max_distance = 0.
Dataset ThreeRobotDataset() {
  Dataset d;
  d.name = "failover";
  d.fps = 10.0;
  const int frames = kRobots * kFramesEach;
  d.trajectory.positions.resize(frames, 3);
  d.trajectory.headings.resize(frames, 3);
  d.descriptors.resize(frames, 2);
  for (int f = 0; f < frames; ++f) {
    d.trajectory.positions.row(f) << f, 0.0, 0.0;
    d.trajectory.headings.row(f) << 1.0, 0.0, 0.0;
    d.descriptors.row(f) << static_cast<float>(6.0 + 0.001 * f), 9.0f;
  }
  return d;
}

std::shared_ptr<const CentroidTable> ThreeCentroids() {
  CentroidMatrix c(3, 2);
  c << 0, 0, 10, 0, 0, 10;
  return std::make_shared<const CentroidTable>(c, std::vector<RobotId>{RobotId(0), RobotId(1), RobotId(2)}, kRobots);
}

// Ideal network (no delay), free service; robot 2 drops at 1.05 s, after its frame 10 (1.0 s).
SimRunParams Params() {
  SimRunParams p;
  p.scenario.robots = kRobots;
  p.scenario.network.model = LinkModelKind::kIdeal;
  p.scenario.agent.suppression_frames = 0;
  p.scenario.agent.service.fixed = SimTime::Zero();
  p.scenario.agent.service.per_comparison = SimTime::Zero();
  p.scenario.agent.verification.max_distance = 0.0;
  p.scenario.dropouts.push_back({RobotId(2), SimTime::Millis(1050)});
  return p;
}

// Heartbeats every 40 ms, lost after 100 ms of silence. Robot 2's last heartbeat goes out at
// 1.04 s; robots 0 and 1 check at 1.08 s (40 ms silent), 1.12 s (80 ms) and 1.16 s (120 ms):
// lost at 1.16 s. The team's last frame is at 1.9 s.
FailoverParams Failover() {
  FailoverParams f;
  f.enabled = true;
  f.heartbeat_period = SimTime::Millis(40);
  f.timeout = SimTime::Millis(100);
  return f;
}

struct Counts {
  std::int64_t taken = 0, incomplete = 0;
};

Counts CountQueries(const SimRunLog& log) {
  Counts c;
  for (const QueryRecord& q : log.queries) {
    ++c.taken;
    c.incomplete += q.Complete() ? 0 : 1;
  }
  return c;
}

// Robot 2 takes frames 0..10 (0 to 1.0 s) and serves them itself. Robots 0 and 1 take 20 each:
// frames 0..10 reach robot 2 before it drops and are answered; frame 11 (1.1 s) goes to robot 2,
// offline, before it is declared lost (1.16 s): lost, one per robot; frames 12..19 (1.2 s on) go
// to robot 1, robot 0's over the network and robot 1's own locally: answered.
TEST(SimFailover, QueriesToALostRobotsClustersAreServedByItsSuccessorAfterDetection) {
  const Dataset data = ThreeRobotDataset();
  const auto table = ThreeCentroids();
  const FailoverTeam team(std::make_unique<DecentralizedPlacement>(table), table, Failover(), SimTime::Millis(1900));
  const SimRunLog log = RunSimulation(data, team, Params());
  const Counts c = CountQueries(log);
  EXPECT_EQ(c.taken, 20 + 20 + 11);
  EXPECT_EQ(c.incomplete, 2);
  // Loads: robot 2 served its 11 and the 2 x 11 of the others; robot 1 its own 8 and robot 0's 8.
  EXPECT_EQ(log.loads[2].searches, 33);
  EXPECT_EQ(log.loads[1].searches, 16);
  EXPECT_EQ(log.loads[0].searches, 0);
  ASSERT_EQ(log.dropouts.size(), 1u);
  EXPECT_EQ(log.dropouts[0].robot, RobotId(2));
  EXPECT_EQ(log.dropouts[0].detected, SimTime::Millis(1160));
  EXPECT_EQ(log.dropouts[0].stored, 33);  // what robot 2 stored: gone, no replica
  EXPECT_EQ(log.dropouts[0].kept, 0);
}

// The same team without failover: robots 0 and 1 lose frames 11..19 each (9 + 9), robot 1
// serves nothing, and no robot declares robot 2 lost.
TEST(SimFailover, WithoutFailoverEveryLaterQueryToTheLostRobotIsLost) {
  const Dataset data = ThreeRobotDataset();
  const DecentralizedPlacement routing(ThreeCentroids());
  const SimRunLog log = RunSimulation(data, routing, Params());
  const Counts c = CountQueries(log);
  EXPECT_EQ(c.taken, 51);
  EXPECT_EQ(c.incomplete, 18);
  EXPECT_EQ(log.loads[1].searches, 0);
  ASSERT_EQ(log.dropouts.size(), 1u);
  EXPECT_EQ(log.dropouts[0].detected, std::nullopt);
  EXPECT_EQ(log.dropouts[0].stored, 33);
}

// Boundary replication over the two nearest centroids stores every frame at robot 2 and a copy
// at robot 1 (the next nearest, and the successor): of robot 2's 33 descriptors all 33 survive.
TEST(SimFailover, AReplicaKeepsWhatTheLostRobotStored) {
  const Dataset data = ThreeRobotDataset();
  const auto table = ThreeCentroids();
  ReplicationParams replicate;
  replicate.epsilon = 1.0;  // 9.8 < 2 x 6.1: robot 1's centroid is within, robot 0's (10.8) too
  replicate.max_replicas = 2;  // but only two centroids: robots 2 and 1
  const FailoverTeam team(std::make_unique<BoundaryReplicationPlacement>(table, replicate), table, Failover(),
                          SimTime::Millis(1900));
  const SimRunLog log = RunSimulation(data, team, Params());
  EXPECT_EQ(CountQueries(log).incomplete, 2);
  ASSERT_EQ(log.dropouts.size(), 1u);
  EXPECT_EQ(log.dropouts[0].stored, 33);
  EXPECT_EQ(log.dropouts[0].kept, 33);
}

}  // namespace
}  // namespace dvpr

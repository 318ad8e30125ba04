// The simulation run on small hand-checkable cases: message counts and sizes on
// the ideal network, agreement with a brute-force causal reference, service
// queueing, dropout and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <utility>

#include "agents/algorithms/kmeans.h"
#include "agents/placement/decentralized_placement.h"
#include "experiments/domain/data/split.h"
#include "experiments/protocols/sim/simulation.h"
#include "sim/random.h"
#include "sim/random_bits.h"

namespace dvpr {
namespace {

// A straight-line trajectory that passes the same places twice (a loop), with
// random unit descriptors: enough to exercise routing and matching.
Dataset MakeDataset(int frames, int dim, std::uint64_t seed) {
  Dataset d;
  d.name = "test";
  d.fps = 10.0;
  d.trajectory.positions.resize(frames, 3);
  d.trajectory.headings.resize(frames, 3);
  d.descriptors.resize(frames, dim);
  RandomStream rng(seed, ComponentId("test-dataset"));
  for (int i = 0; i < frames; ++i) {
    const double s = (i % (frames / 2)) * 1.0;  // second half revisits the first
    d.trajectory.positions.row(i) << s, 0.0, 0.0;
    d.trajectory.headings.row(i) << 1.0, 0.0, 0.0;
    for (int c = 0; c < dim; ++c) d.descriptors(i, c) = static_cast<float>(rng.Normal());
    d.descriptors.row(i).normalize();
  }
  return d;
}

std::shared_ptr<const CentroidTable> TrainTable(const Dataset& d, int robots) {
  KMeansParams p;
  p.k = robots;
  p.seed = 7;
  return std::make_shared<CentroidTable>(CentroidTable::RoundRobin(KMeans(d.descriptors, p), robots));
}

SimRunParams IdealParams(int robots) {
  SimRunParams p;
  p.scenario.robots = robots;
  p.scenario.network.model = LinkModelKind::kIdeal;
  p.scenario.agent.suppression_frames = 10;
  p.scenario.agent.service.fixed = SimTime::Zero();
  p.scenario.agent.service.per_comparison = SimTime::Zero();
  p.scenario.agent.verification.max_distance = 0.0;  // random descriptors: no verification traffic
  p.outputs.record_messages = true;
  return p;
}

std::map<std::string, std::int64_t> CountByType(const SimRunLog& log) {
  std::map<std::string, std::int64_t> counts;
  for (const auto& m : log.messages) ++counts[m.type];
  return counts;
}

class SimulationTest : public ::testing::Test {
 protected:
  static constexpr int kRobots = 4;
  Dataset data_ = MakeDataset(240, 16, 3);
  std::shared_ptr<const CentroidTable> table_ = TrainTable(data_, kRobots);
};

// Frames routed by construction: frame f's descriptor is the unit vector e_(f mod 4) plus noise
// below 0.1 per coordinate, and centroid c is e_c, owned by robot c (round robin). Then
// |x - e_c|^2 = |x|^2 + 1 - 2 x_c is smallest for c = f mod 4 (x_c > 0.9 there, < 0.1 elsewhere),
// so frame f goes to robot f mod 4 whatever the distance code does.
Dataset HandRoutedDataset(int frames, int dim) {
  Dataset d = MakeDataset(frames, dim, 5);  // its trajectory; the descriptors are replaced
  Xoshiro256 rng(11);
  for (int f = 0; f < frames; ++f) {
    for (int c = 0; c < dim; ++c) d.descriptors(f, c) = static_cast<float>(0.1 * (2 * rng.Uniform() - 1));
    d.descriptors(f, f % 4) += 1.0f;
  }
  return d;
}

std::shared_ptr<const CentroidTable> AxisTable(int robots, int dim) {
  CentroidMatrix c = CentroidMatrix::Zero(robots, dim);
  for (int r = 0; r < robots; ++r) c(r, r) = 1.0f;
  return std::make_shared<CentroidTable>(CentroidTable::RoundRobin(c, robots));
}

TEST(SimulationHandRouted, DecentralizedSendsOneQueryAndOneReplyPerRemoteFrame) {
  const Dataset data = HandRoutedDataset(240, 16);
  const DecentralizedPlacement routing(AxisTable(4, 16));
  const SimRunLog log = RunSimulation(data, routing, IdealParams(4));
  // Robot r takes frames 60r .. 60r + 59 and sends frame f to robot f mod 4: in each block of
  // 60, the 15 frames with f mod 4 = r stay home, 45 go out, one to each robot per 4 frames
  // (15 to each of the 3 others). 4 x 45 = 180 queries, each answered by one match_t.
  const auto counts = CountByType(log);
  EXPECT_EQ(counts.at("query_t"), 180);
  EXPECT_EQ(counts.at("match_t"), 180);
  EXPECT_EQ(counts.size(), 2u);
  EXPECT_EQ(log.queries.size(), 240u);
  std::map<std::pair<int, int>, int> queries;  // (src, dst) -> query_t messages
  for (const auto& m : log.messages) {
    // query_t with 16 floats: 8 fingerprint + 8 + 2 + 4 + 8 + 2 + 64 = 96; match_t: 35 (see test_messages).
    EXPECT_EQ(m.payload_bytes, m.type == "query_t" ? 96 : 35);
    EXPECT_FALSE(m.dropped);
    EXPECT_EQ(m.delivered_ns, m.sent_ns);  // ideal network: no delay
    if (m.type == "query_t") ++queries[{m.src, m.dst}];
  }
  ASSERT_EQ(queries.size(), 12u);  // every ordered pair of 4 robots
  for (const auto& [pair, n] : queries) EXPECT_EQ(n, 15) << pair.first << " -> " << pair.second;
}

TEST_F(SimulationTest, BroadcastSendsToEveryOtherRobot) {
  const BroadcastPlacement routing(kRobots);
  const SimRunLog log = RunSimulation(data_, routing, IdealParams(kRobots));
  const auto counts = CountByType(log);
  EXPECT_EQ(counts.at("query_t"), data_.size() * (kRobots - 1));
  EXPECT_EQ(counts.at("match_t"), data_.size() * (kRobots - 1));
  for (const auto& l : log.loads) {
    EXPECT_EQ(l.searches, data_.size());  // every robot searches every query
    EXPECT_EQ(l.stored, data_.size() / kRobots);  // and keeps only its own frames
  }
}

// Brute force: the best frame among those the owner of i's cluster stored
// earlier, in double precision.
struct Reference {
  int frame = -1;
  double distance = std::numeric_limits<double>::infinity();
};

TEST_F(SimulationTest, DecentralizedMatchesEqualTheCausalStaticReference) {
  const DecentralizedPlacement routing(table_);
  const SimRunParams params = IdealParams(kRobots);
  const SimRunLog log = RunSimulation(data_, routing, params);
  std::vector<RobotId> owner(static_cast<std::size_t>(data_.size()));
  for (int f = 0; f < data_.size(); ++f) owner[static_cast<std::size_t>(f)] = table_->RouteOf(data_.descriptors.row(f).data());
  int compared = 0;
  for (const QueryRecord& q : log.queries) {
    const int i = q.frame.value;
    const SimTime t = log.capture_time[static_cast<std::size_t>(i)];
    Reference ref;
    for (int j = 0; j < data_.size(); ++j) {
      if (owner[j] != owner[i] || std::abs(i - j) <= params.scenario.agent.suppression_frames) continue;
      if (!(log.capture_time[static_cast<std::size_t>(j)] < t)) continue;
      const double d = (data_.descriptors.row(i).cast<double>() - data_.descriptors.row(j).cast<double>()).squaredNorm();
      if (d < ref.distance) ref = {j, d};
    }
    if (!q.best) {
      EXPECT_EQ(ref.frame, -1) << "frame " << i;
      continue;
    }
    const SimTime t_match = log.capture_time[static_cast<std::size_t>(q.best->frame.value)];
    if (t_match < t) {
      EXPECT_EQ(q.best->frame.value, ref.frame) << "frame " << i;
      EXPECT_NEAR(q.best->distance, ref.distance, 1e-5);
      ++compared;
    } else {
      // A frame taken at the same instant by another robot may have reached
      // the store first: it can only be better than the reference.
      EXPECT_EQ(t_match, t);
      EXPECT_LE(q.best->distance, ref.distance + 1e-5);
    }
  }
  EXPECT_GT(compared, data_.size() / 2);
}

TEST_F(SimulationTest, SameSeedSameLogAndBusyRobotsQueue) {
  const BroadcastPlacement routing(kRobots);
  SimRunParams p = IdealParams(kRobots);
  p.scenario.agent.service.fixed = SimTime::Millis(30);  // 3 robots' queries per 100 ms frame: 90 ms of work
  const SimRunLog a = RunSimulation(data_, routing, p);
  const SimRunLog b = RunSimulation(data_, routing, p);
  ASSERT_EQ(a.queries.size(), b.queries.size());
  for (std::size_t i = 0; i < a.queries.size(); ++i) {
    EXPECT_EQ(a.queries[i].latency, b.queries[i].latency);
    ASSERT_EQ(a.queries[i].best.has_value(), b.queries[i].best.has_value());
    if (a.queries[i].best) {
      EXPECT_EQ(a.queries[i].best->frame, b.queries[i].best->frame);
    }
  }
  // Four searches per frame period (own + 3 remote) of 30 ms each: 120 ms of
  // work every 100 ms, so the queue grows and latency exceeds one service time.
  const LatencyStats lat = ComputeLatency(a.queries);
  EXPECT_GT(lat.mean_ms, 30.0);
  for (const auto& l : a.loads) EXPECT_GT(l.max_queue, 1);
}

TEST_F(SimulationTest, DroppedRobotLosesItsMessagesAndOthersFinish) {
  const BroadcastPlacement routing(kRobots);
  SimRunParams p = IdealParams(kRobots);
  p.scenario.dropouts.push_back({RobotId(2), SimTime::Seconds(3.0)});
  const SimRunLog log = RunSimulation(data_, routing, p);
  // Robot 2 took frames at 0.0 .. 2.9 s: 30 of its 60.
  std::int64_t robot2 = 0, incomplete = 0;
  for (const auto& q : log.queries) {
    robot2 += q.robot == RobotId(2) ? 1 : 0;
    incomplete += q.latency ? 0 : 1;
  }
  EXPECT_EQ(robot2, 30);
  // The other three robots' queries from t = 3 s on miss robot 2's reply: 30 frames each.
  EXPECT_EQ(incomplete, 3 * 30);
  std::int64_t dropped = 0;
  for (const auto& m : log.messages) dropped += m.dropped ? 1 : 0;
  EXPECT_EQ(dropped, 3 * 30);
}

// Bytes by role (issue 16) against the network's own counters, on a saturated shared medium
// (drops) with verification traffic: every role is counted once, offered and delivered apart.
TEST_F(SimulationTest, BytesByRoleSumToTheNetworksTotals) {
  const BroadcastPlacement routing(kRobots);
  SimRunParams p = IdealParams(kRobots);
  p.scenario.network.model = LinkModelKind::kSharedMedium;
  p.scenario.network.bandwidth = DataRate::Kbps(100);
  p.scenario.network.queue_packets = 4;
  p.scenario.agent.verification.max_distance = 1e9;  // every match is verified
  const SimRunLog log = RunSimulation(data_, routing, p);
  const SimRunSummary s = SummarizeSimRun(log, data_.trajectory.positions, 5.0, 10);
  CopyBytes copies;
  std::int64_t medium = 0;
  for (int r = 0; r < kMessageRoles; ++r) {
    copies += log.roles.copies[static_cast<std::size_t>(r)];
    medium += log.roles.medium[static_cast<std::size_t>(r)];
  }
  EXPECT_EQ(copies.payload, s.payload_bytes);
  EXPECT_EQ(copies.wire, s.wire_bytes);
  EXPECT_EQ(medium, s.medium_bytes);
  EXPECT_LT(copies.delivered_wire, copies.wire);  // the medium saturated and dropped
  EXPECT_GT(s.dropped, 0);
  EXPECT_GT(log.roles.copies[static_cast<std::size_t>(MessageRole::kVerifyRequest)].payload, 0);
  // Per pair, the roles sum to links.csv's columns; by role, messages.csv's rows sum to the run's.
  ASSERT_TRUE(log.has_roles);
  ASSERT_FALSE(log.links.empty());
  for (const PairTraffic& link : log.links) {
    CopyBytes pair;
    for (const CopyBytes& c : link.roles) pair += c;
    EXPECT_GT(link.counters.messages, 0u);  // only pairs that carried something are listed
    EXPECT_EQ(pair.payload, link.counters.payload_bytes);
    EXPECT_EQ(pair.wire, link.counters.wire_bytes);
  }
  std::map<std::string, CopyBytes> by_role;
  for (const MessageRow& m : log.messages) {
    CopyBytes& c = by_role[m.role];
    c.payload += m.payload_bytes;
    c.wire += m.wire_bytes;
    if (m.delivered_ns) c.delivered_wire += m.wire_bytes;
  }
  for (int r = 0; r < kMessageRoles; ++r) {
    const CopyBytes& want = log.roles.copies[static_cast<std::size_t>(r)];
    const CopyBytes got = by_role[kMessageRoleNames[static_cast<std::size_t>(r)]];
    EXPECT_EQ(got.payload, want.payload) << kMessageRoleNames[static_cast<std::size_t>(r)];
    EXPECT_EQ(got.wire, want.wire);
    EXPECT_EQ(got.delivered_wire, want.delivered_wire);
  }
}

}  // namespace
}  // namespace dvpr

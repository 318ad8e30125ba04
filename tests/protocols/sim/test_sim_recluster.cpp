// Adaptive re-clustering in the simulation (agents/recluster/recluster_agent.h): on the ideal
// network, a hand-worked 1-D toy (which robot searches and stores each frame before and after the
// new table, message counts and bytes), a random team checked against the static planner (same
// tables, every descriptor at its owner under the final table), determinism and dropout.
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/kmeans.h"
#include "agents/messages/sim_transport.h"
#include "agents/recluster/recluster_agent.h"
#include "agents/recluster/recluster_messages.h"
#include "agents/robot_agent.h"
#include "experiments/domain/data/split.h"
#include "experiments/protocols/paper/static_recluster.h"
#include "experiments/protocols/sim/message_rows.h"
#include "experiments/protocols/sim/simulation.h"
#include "sim/random.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

AgentParams QuietAgent(int window) {
  AgentParams p;
  p.suppression_frames = window;
  p.service.fixed = SimTime::Zero();
  p.service.per_comparison = SimTime::Zero();
  p.verification.max_distance = 0.0;
  return p;
}

ReclusterPlan MakePlan(const DescriptorMatrix& x, int robots, std::shared_ptr<const CentroidTable> initial,
                       const ReclusterParams& params) {
  ReclusterPlan plan;
  plan.params = params;
  plan.initial = std::move(initial);
  const SequenceSplit split = SplitSequence(static_cast<int>(x.rows()), robots);
  int longest = 0;
  for (const FrameRange& r : split.ranges) {
    plan.stream_first.push_back(r.begin);
    longest = std::max(longest, r.size());
  }
  plan.epochs = ReclusterEpochs(longest, params);
  plan.sample_timeout = SimTime::Millis(500);
  return plan;
}

// A team on the ideal network, agents and their re-clustering components kept for inspection (as
// RunSimulation, which hides them).
struct Team {
  Team(const DescriptorMatrix& x, const ReclusterPlacement& routing, const AgentParams& agent) {
    const int n = routing.num_robots();
    NetworkModelParams net;
    net.model = LinkModelKind::kIdeal;
    network = std::make_unique<Network>(sim, n, MakeLinkModel(net, n, 1), net.wire);
    messages_subscription = network->Subscribe(messages);
    const SequenceSplit split = SplitSequence(static_cast<int>(x.rows()), n);
    for (int r = 0; r < n; ++r) {
      const FrameRange range = split.ranges[static_cast<std::size_t>(r)];
      transports.push_back(std::make_unique<SimTransport>(*network, NodeId(r)));
      auto component = std::make_unique<ReclusterAgentPlacement>(routing.plan());
      routings.push_back(component.get());
      const AgentSetup setup{RobotId(r), n, agent, FrameStream{&x, range.begin, range.size(), 10.0}};
      agents.push_back(std::make_unique<RobotAgent>(setup, *transports.back(), std::move(component),
                                                    [](FrameId, FrameId) { return VerifyVerdict{}; }));
    }
    for (auto& a : agents) a->Start();
    sim.Run();
  }
  struct Traffic {
    std::int64_t messages = 0, bytes = 0, wire_bytes = 0;
  };
  // By channel family (DVPR_SAMPLE, DVPR_MIGRATE, DVPR_TABLE) or type (query_t, match_t).
  std::map<std::string, Traffic> ByKind() const {
    std::map<std::string, Traffic> out;
    for (const MessageRow& r : messages.Rows()) {
      const std::string& channel = r.channel;
      std::string kind = r.type;
      if (channel.rfind("DVPR_SAMPLE", 0) == 0) kind = "sample";
      if (channel.rfind("DVPR_MIGRATE", 0) == 0) kind = "migrate";
      if (channel == channels::kTable) kind = "table";
      ++out[kind].messages;
      out[kind].bytes += r.payload_bytes;
      out[kind].wire_bytes += r.wire_bytes;
    }
    return out;
  }
  Simulator sim;
  std::unique_ptr<Network> network;
  MessageRowRecorder messages;
  ObserverSubscription messages_subscription;
  std::vector<std::unique_ptr<SimTransport>> transports;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  std::vector<const ReclusterAgentPlacement*> routings;  // robot by robot, owned by the agents
};

std::shared_ptr<const CentroidTable> Table1D(float a, int owner_a, float b, int owner_b) {
  CentroidMatrix c(2, 1);
  c << a, b;
  return std::make_shared<const CentroidTable>(c, std::vector<RobotId>{RobotId(owner_a), RobotId(owner_b)}, 2);
}

std::set<int> StoredFrames(const RobotAgent& a) {
  std::set<int> frames;
  for (const IndexEntry& e : a.index().entries()) frames.insert(e.frame.value);
  return frames;
}

// The robot that holds descriptor x under `table`: the owner of its nearest centroid, by brute
// force in double precision (ties: the lowest centroid).
int NearestOwner(const CentroidTable& table, const Eigen::Ref<const Eigen::RowVectorXf>& x) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int c = 0; c < table.num_centroids(); ++c) {
    const double d = (table.centroids().row(c).cast<double>() - x.cast<double>()).squaredNorm();
    if (d < best_d) {
      best = c;
      best_d = d;
    }
  }
  return table.OwnerOf(best).value;
}

// Wire bytes of one message by docs/design.md section 4, for messages below LCM's 64 kB
// fragmenting: one LCM datagram (8-byte header, channel, NUL, payload), UDP 8, IPv4 fragments of at
// most 1480 data bytes (MTU 1500) with 20 header bytes each, 2 bytes of framing per IP packet.
std::int64_t WireBytes(std::int64_t payload, const std::string& channel) {
  const std::int64_t ip_data = 8 + static_cast<std::int64_t>(channel.size()) + 1 + payload + 8;
  const std::int64_t packets = (ip_data + 1479) / 1480;
  return ip_data + packets * (20 + 2);
}

// Two robots of eight frames (0.1 s apart), values near 0 or near 100:
//   robot 0, frames 0-7:  0  1  0 99  2 98  3 97
//   robot 1, frames 8-15: 0  1 100 101 2 99  3 102
// Initial table T0: near 0 -> robot 1, near 100 -> robot 0. Period 4, sample stride 2, one
// cluster per robot: one re-clustering at t = 0.4 s; its sample is steps 0 and 2 = frames 0, 2, 8,
// 10 = 0 0 0 100, so T1 has centroids 0 (load 4 -> robot 0) and 100 (load 2 -> robot 1): the
// owners swap. Window 20: no matches, no verification traffic.
class SimReclusterToy : public ::testing::Test {
 protected:
  SimReclusterToy() : x_(16, 1) {
    x_.col(0) << 0, 1, 0, 99, 2, 98, 3, 97, 0, 1, 100, 101, 2, 99, 3, 102;
    params_.clusters_per_robot = 1;
    params_.period = 4;
    params_.sample_stride = 2;
  }
  DescriptorMatrix x_;
  ReclusterParams params_;
};

TEST_F(SimReclusterToy, RoutesByTheTableOfTheMomentAndMovesWhatChangedOwner) {
  const ReclusterPlacement routing(MakePlan(x_, 2, Table1D(0, 1, 100, 0), params_));
  const Team team(x_, routing, QuietAgent(20));
  // Before the boundary (T0): frames 0 1 2 of robot 0 go to robot 1, 10 11 of robot 1 to robot
  // 0: 5 remote queries. At t = 0.4 s the frames 4 and 12 are taken before the samples arrive
  // (still T0): frame 4 goes to robot 1, 12 stays local. Then the leader has both samples, sends
  // T1 and moves frames 3 10 11 to robot 1 (one batch); robot 1 gets T1 and moves 0 1 2 8 9 12 to
  // robot 0 (one batch); robot 1 then finishes searching frame 4 and, T1 giving it to robot 0,
  // forwards it (a third batch). After (T1): 5 and 7 go to robot 1, 14 to robot 0: 3 more.
  const auto kinds = team.ByKind();
  EXPECT_EQ(kinds.at("query_t").messages, 9);
  EXPECT_EQ(kinds.at("match_t").messages, 9);
  // Sample: robot 1 holds frames 0 2 8 of the sample: 28 + 3 x (6 + 4) = 58 bytes.
  EXPECT_EQ(kinds.at("sample").messages, 1);
  EXPECT_EQ(kinds.at("sample").bytes, 58);
  // Table: k = 2, dim 1: 26 + 2 x (4 + 2) = 38 bytes, one copy to robot 1.
  EXPECT_EQ(kinds.at("table").messages, 1);
  EXPECT_EQ(kinds.at("table").bytes, 38);
  // Migrations: 3 descriptors (58) + 6 (28 + 60 = 88) + 1 forwarded (38) = 184 bytes.
  EXPECT_EQ(kinds.at("migrate").messages, 3);
  EXPECT_EQ(kinds.at("migrate").bytes, 184);
  EXPECT_EQ(kinds.size(), 5u);
  // Everything at its owner under T1: near 0 at robot 0, near 100 at robot 1.
  for (const auto* r : team.routings) EXPECT_EQ(r->epoch(), 1);
  EXPECT_EQ(StoredFrames(*team.agents[0]), (std::set<int>{0, 1, 2, 4, 6, 8, 9, 12, 14}));
  EXPECT_EQ(StoredFrames(*team.agents[1]), (std::set<int>{3, 5, 7, 10, 11, 13, 15}));
  EXPECT_EQ(team.agents[0]->load().stored, 9);
  EXPECT_EQ(team.agents[1]->load().stored, 7);
  // Searches (the robot a query was sent to): robot 0 its own 3 and 6, remote 10 11 14 = 5;
  // robot 1 remote 0 1 2 4 5 7, its own 8 9 12 13 15 = 11.
  EXPECT_EQ(team.agents[0]->load().searches, 5);
  EXPECT_EQ(team.agents[1]->load().searches, 11);
}

TEST_F(SimReclusterToy, SameInputsSameMessages) {
  const ReclusterPlacement routing(MakePlan(x_, 2, Table1D(0, 1, 100, 0), params_));
  const Team a(x_, routing, QuietAgent(20));
  const Team b(x_, routing, QuietAgent(20));
  const std::vector<MessageRow> ra = a.messages.Rows();
  const std::vector<MessageRow> rb = b.messages.Rows();
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i) {
    const MessageRow& r = ra[i];
    const MessageRow& s = rb[i];
    EXPECT_EQ(r.sent_ns, s.sent_ns);
    EXPECT_EQ(r.src, s.src);
    EXPECT_EQ(r.dst, s.dst);
    EXPECT_EQ(r.payload_bytes, s.payload_bytes);
  }
}

// A random team: 4 robots x 60 frames of 16-D unit descriptors, initial table k-means (8
// clusters) on the data, round robin. Two clusters per robot, period 15, stride 4: re-clusterings
// at 1.5, 3.0 and 4.5 s ((60 - 1) / 15 = 3).
class SimReclusterTeam : public ::testing::Test {
 protected:
  SimReclusterTeam() : x_(240, 16) {
    RandomStream rng(3, ComponentId("recluster-test"));
    for (Eigen::Index i = 0; i < x_.rows(); ++i) {
      for (Eigen::Index c = 0; c < x_.cols(); ++c) x_(i, c) = static_cast<float>(rng.Normal());
      x_.row(i).normalize();
    }
    KMeansParams k;
    k.k = 8;
    k.seed = 7;
    initial_ = std::make_shared<const CentroidTable>(CentroidTable::RoundRobin(KMeans(x_, k), 4));
    params_.clusters_per_robot = 2;
    params_.period = 15;
    params_.seed = 11;
  }
  DescriptorMatrix x_;
  std::shared_ptr<const CentroidTable> initial_;
  ReclusterParams params_;
};

TEST_F(SimReclusterTeam, EveryDescriptorEndsAtItsOwnerUnderTheStaticPlannersLastTable) {
  const ReclusterPlacement routing(MakePlan(x_, 4, initial_, params_));
  const Team team(x_, routing, QuietAgent(10));
  // On the ideal network with instant service every sample frame is stored by its boundary, so the
  // leader clusters exactly the static planner's sample: the same tables.
  const StaticReclusterPlan plan = PlanStaticRecluster(x_, initial_, params_);
  ASSERT_EQ(plan.epochs(), 3);
  std::vector<int> seen(240, 0);
  for (std::size_t r = 0; r < team.agents.size(); ++r) {
    const RobotAgent* a = team.agents[r].get();
    const ReclusterAgentPlacement& routing = *team.routings[r];
    EXPECT_EQ(routing.epoch(), 3);
    EXPECT_EQ(routing.table().centroids(), plan.tables[3]->centroids());
    for (int c = 0; c < plan.tables[3]->num_centroids(); ++c) {
      EXPECT_EQ(routing.table().OwnerOf(c), plan.tables[3]->OwnerOf(c));
    }
    for (std::size_t i = 0; i < a->index().size(); ++i) {
      const FrameId f = a->index().entries()[i].frame;
      ++seen[static_cast<std::size_t>(f.value)];
      EXPECT_EQ(plan.FinalOwner(static_cast<std::size_t>(f.value)), a->id()) << "frame " << f.value;
      EXPECT_EQ(routing.table().RouteOf(a->index().Descriptor(i)), a->id());
    }
    EXPECT_EQ(a->load().stored, static_cast<std::int64_t>(a->index().size()));
  }
  for (int f = 0; f < 240; ++f) EXPECT_EQ(seen[static_cast<std::size_t>(f)], 1) << "frame " << f;
  // Per epoch: 3 sample uploads (robots 1-3) and 3 table copies; 3 epochs.
  const auto kinds = team.ByKind();
  EXPECT_EQ(kinds.at("sample").messages, 9);
  EXPECT_EQ(kinds.at("table").messages, 9);
  // A table of k = min(2 clusters x 4 robots, sample rows) = 8 centroids of 16 floats (LCM
  // centroid_table_t: 26 + k x (4 x 16 + 2) = 554 bytes), one copy to each of the 3 others.
  EXPECT_EQ(kinds.at("table").bytes, 9 * 554);
  EXPECT_EQ(kinds.at("table").wire_bytes, 9 * WireBytes(554, "DVPR_TABLE"));
  // A sample batch (LCM descriptor_batch_t) is 28 + m x (6 + 4 x 16) = 28 + 70 m bytes for m
  // descriptors. At the boundary of epoch e (step 15e) a robot holds the sample frames that
  // are its under table e - 1 (routed there, or migrated there at the previous boundary); the
  // sample is every 4th step before the boundary: 4 robots x (4, 8, 12) = 96 frames, and the
  // leader (robot 0) does not send its own.
  int sample_frames = 0;
  std::int64_t sample_bytes = 0, sample_wire = 0;
  for (int e = 1; e <= 3; ++e) {
    int held[4] = {0, 0, 0, 0};
    for (int r = 0; r < 4; ++r) {
      for (int step = 0; step < 15 * e; step += 4) {
        ++sample_frames;
        ++held[NearestOwner(*plan.tables[static_cast<std::size_t>(e - 1)], x_.row(60 * r + step))];
      }
    }
    for (int r = 1; r < 4; ++r) {
      sample_bytes += 28 + 70 * held[r];
      sample_wire += WireBytes(28 + 70 * held[r], "DVPR_SAMPLE_0");
    }
  }
  ASSERT_EQ(sample_frames, 96);
  EXPECT_EQ(kinds.at("sample").bytes, sample_bytes);
  EXPECT_EQ(kinds.at("sample").wire_bytes, sample_wire);
}

TEST_F(SimReclusterTeam, LeaderStopsWaitingForADroppedRobotAndGivesItNoClusters) {
  params_.seed = 5;
  const ReclusterPlacement routing(MakePlan(x_, 4, initial_, params_));
  Dataset data;
  data.descriptors = x_;
  data.fps = 10.0;
  data.trajectory.positions = Positions::Zero(240, 3);
  data.trajectory.headings = Positions::Zero(240, 3);
  SimRunParams p;
  p.scenario.robots = 4;
  p.scenario.network.model = LinkModelKind::kIdeal;
  p.scenario.agent = QuietAgent(10);
  p.outputs.record_messages = true;
  p.scenario.dropouts.push_back({RobotId(2), SimTime::Seconds(2.0)});
  const SimRunLog log = RunSimulation(data, routing, p);
  // Samples: 3 at 1.5 s; robots 1 and 3 only at 3.0 and 4.5 s: 7. The leader waits its 0.5 s
  // timeout at the last two, so those tables go out at 3.5 and 5.0 s; their copies to robot 2 drop.
  int samples = 0, tables = 0, tables_dropped = 0, late_queries_to_2 = 0;
  std::set<std::int64_t> table_times;
  for (const MessageRow& m : log.messages) {
    if (m.channel == "DVPR_SAMPLE_0") ++samples;
    if (m.channel == channels::kTable) {
      ++tables;
      tables_dropped += m.dropped ? 1 : 0;
      table_times.insert(m.sent_ns);
    }
    // Once robots hold the 3.5 s table (which gives robot 2 nothing), no query goes to robot 2.
    if (m.type == "query_t" && m.dst == 2 && m.sent_ns > SimTime::Seconds(3.5).ns()) ++late_queries_to_2;
  }
  EXPECT_EQ(samples, 7);
  EXPECT_EQ(tables, 9);
  EXPECT_EQ(tables_dropped, 2);
  EXPECT_EQ(table_times, (std::set<std::int64_t>{SimTime::Seconds(1.5).ns(), SimTime::Seconds(3.5).ns(),
                                                 SimTime::Seconds(5.0).ns()}));
  EXPECT_EQ(late_queries_to_2, 0);
}

}  // namespace
}  // namespace dvpr

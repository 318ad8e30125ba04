// The per-robot routing component of the stateless strategies and the query roles on the wire:
// on centroids on a line (0, 10, 20, 30 owned by robots 0, 1, 2, 0), where every decision can be
// read off by hand, which channel each remote robot gets; and robot agents on an ideal network
// doing what the channel of a query says, not what their own routing would say.
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/messages/channels.h"
#include "agents/messages/sim_transport.h"
#include "agents/placement/decentralized_placement.h"
#include "agents/placement/probe_placement.h"
#include "agents/robot_agent.h"
#include "net_models/medium/ideal_link.h"
#include "sim/simulator.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Column;
using dvpr::testing_support::Robots;

using Channels = std::vector<std::string>;

class AgentPlacementTest : public ::testing::Test {
 protected:
  AgentPlacementTest() {
    CentroidMatrix c(4, 1);
    c << 0, 10, 20, 30;
    table_ = std::make_shared<const CentroidTable>(c, Robots({0, 1, 2, 0}), 3);
  }
  std::shared_ptr<const CentroidTable> table_;
};

TEST_F(AgentPlacementTest, RoleChannelsHaveEqualLengthsSoTheRoleCostsNoByte) {
  EXPECT_EQ(channels::QueryTo(RobotId(7), QueryRole::kSearchAndStore), "DVPR_QUERY_7");
  EXPECT_EQ(channels::QueryTo(RobotId(7), QueryRole::kSearch), "DVPR_PROBE_7");
  EXPECT_EQ(channels::QueryTo(RobotId(7), QueryRole::kStore), "DVPR_STORE_7");
  EXPECT_EQ(channels::Probe(RobotId(123)).size(), channels::Query(RobotId(123)).size());
  EXPECT_EQ(channels::Store(RobotId(123)).size(), channels::Query(RobotId(123)).size());
}

TEST_F(AgentPlacementTest, DecentralizedAsksTheOwnerToSearchAndStore) {
  const DecentralizedPlacement r(table_);
  const float x = 4;  // nearest centroid 0: robot 0
  const QueryPlan from_2 = PlanOf(r.Route(RobotId(2), &x), RobotId(2), false);
  EXPECT_EQ(from_2.channels, Channels{"DVPR_QUERY_0"});
  EXPECT_EQ(from_2.searches, 1);
  EXPECT_FALSE(from_2.search_here);
  EXPECT_FALSE(from_2.store_here);
  // The owner's own frame goes nowhere: it searches and stores it itself.
  const QueryPlan from_0 = PlanOf(r.Route(RobotId(0), &x), RobotId(0), false);
  EXPECT_TRUE(from_0.channels.empty());
  EXPECT_EQ(from_0.searches, 1);
  EXPECT_TRUE(from_0.search_here);
  EXPECT_TRUE(from_0.store_here);
}

TEST_F(AgentPlacementTest, MultiProbeStoresAtTheNearestOwnerAndProbesTheOthers) {
  const MultiProbePlacement r(table_, {.probes = 2, .epsilon = -1});
  const float x = 4;  // distances 4 (robot 0), 6 (robot 1): search at 0 and 1, store at 0
  EXPECT_EQ(PlanOf(r.Route(RobotId(2), &x), RobotId(2), false).channels, (Channels{"DVPR_QUERY_0", "DVPR_PROBE_1"}));
  // Robot 1's own frame: it probes itself locally and sends the store to robot 0.
  const QueryPlan from_1 = PlanOf(r.Route(RobotId(1), &x), RobotId(1), false);
  EXPECT_EQ(from_1.channels, Channels{"DVPR_QUERY_0"});
  EXPECT_EQ(from_1.searches, 2);
  EXPECT_TRUE(from_1.search_here);
  EXPECT_FALSE(from_1.store_here);
}

TEST_F(AgentPlacementTest, BroadcastIsOnePublicationAndOnlyAsksToSearch) {
  const BroadcastPlacement r(3);
  const float x = 4;
  const QueryPlan from_1 = PlanOf(r.Route(RobotId(1), &x), RobotId(1), r.UsesBroadcastChannel());
  EXPECT_EQ(from_1.channels, Channels{"DVPR_QUERY_ALL"});
  EXPECT_EQ(from_1.searches, 3);
  EXPECT_TRUE(from_1.search_here);
  EXPECT_TRUE(from_1.store_here);
  // A decision that asks a remote robot to store cannot go on the broadcast channel.
  EXPECT_THROW(PlanOf(PlacementDecision{Robots({0, 1}), Robots({1})}, RobotId(0), true), std::logic_error);
  EXPECT_THROW(PlanOf(PlacementDecision{Robots({0}), Robots({2})}, RobotId(0), true), std::logic_error);
}

TEST_F(AgentPlacementTest, EachRemoteRobotGetsTheQueryOnceOnTheChannelOfItsRole) {
  // Searchers first in the decision's order, then store-only robots; self and repeats skipped.
  const PlacementDecision d{Robots({2, 0, 1, 2}), Robots({1, 0, 3})};
  const QueryPlan plan = PlanOf(d, RobotId(0), false);
  EXPECT_EQ(plan.channels, (Channels{"DVPR_PROBE_2", "DVPR_QUERY_1", "DVPR_STORE_3"}));
  EXPECT_EQ(plan.searches, 4);
  EXPECT_TRUE(plan.search_here);
  EXPECT_TRUE(plan.store_here);
}

AgentParams Instant() {
  AgentParams p;
  p.suppression_frames = 0;
  p.service.fixed = SimTime::Zero();
  p.service.per_comparison = SimTime::Zero();
  p.verification.max_distance = 0.0;
  return p;
}

// Robots on an ideal network plus one more node, the observer, that counts the messages on the
// channels it is told to watch.
struct IdealTeam {
  IdealTeam(int robots, const DescriptorMatrix& x, const TeamPlacement& routing, std::vector<FrameStream> streams)
      : network(sim, robots + 1, std::make_unique<IdealLink>()), observer(network, NodeId(robots)) {
    for (int r = 0; r < robots; ++r) {
      transports.push_back(std::make_unique<SimTransport>(network, NodeId(r)));
      FrameStream frames = streams.empty() ? FrameStream{&x, FrameId(0), 0, 10.0} : streams[static_cast<std::size_t>(r)];
      agents.push_back(std::make_unique<RobotAgent>(AgentSetup{RobotId(r), robots, Instant(), frames}, *transports.back(),
                                                    routing.MakeAgentPlacement(),
                                                    [](FrameId, FrameId) { return VerifyVerdict{}; }));
    }
  }
  void Watch(const std::string& channel) {
    watches.push_back(observer.Subscribe<query_t>(channel, [this, channel](const query_t&) { ++seen[channel]; }));
  }
  void WatchMatches(const std::string& channel) {
    watches.push_back(observer.Subscribe<match_t>(channel, [this, channel](const match_t&) { ++seen[channel]; }));
  }
  std::set<int> Stored(int robot) const {
    std::set<int> frames;
    for (const IndexEntry& e : agents[static_cast<std::size_t>(robot)]->index().entries()) frames.insert(e.frame.value);
    return frames;
  }
  Simulator sim;
  Network network;
  SimTransport observer;
  std::vector<std::unique_ptr<SimTransport>> transports;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  std::vector<Subscription> watches;
  std::map<std::string, int> seen;
};

TEST_F(AgentPlacementTest, AReceiverDoesWhatTheChannelSaysNotWhatItsOwnRoutingWould) {
  // Robot 1's own routing gives every descriptor to robot 0 (the nearest centroid, 0, is robot
  // 0's here): re-deriving the role from it, robot 1 would do nothing with any of these queries.
  const DescriptorMatrix x = Column({1});
  const DecentralizedPlacement routing(table_);
  IdealTeam team(2, x, routing, {});
  for (auto& a : team.agents) a->Start();
  int replies = 0;
  Subscription sub = team.transports[0]->Subscribe<match_t>(channels::Match(RobotId(0)), [&](const match_t&) { ++replies; });
  const auto query = [](int frame) {
    query_t q{};
    q.robot = 0;
    q.frame = frame;
    q.dim = 1;
    q.descriptor = {1.0f};
    return q;
  };
  SimTransport& sender = *team.transports[0];
  sender.Publish(channels::Store(RobotId(1)), query(5));  // keep, no search, no reply
  sender.Publish(channels::Probe(RobotId(1)), query(6));  // search and reply, do not keep
  sender.Publish(channels::Query(RobotId(1)), query(7));  // search, reply, keep
  sender.Publish(channels::kQueryAll, query(8));          // broadcast: search and reply
  team.sim.Run();
  const RobotLoad load = team.agents[1]->load();
  EXPECT_EQ(load.searches, 3);
  EXPECT_EQ(load.remote_queries, 3);
  EXPECT_EQ(load.stored, 2);
  EXPECT_EQ(team.Stored(1), (std::set<int>{5, 7}));
  EXPECT_EQ(replies, 3);
}

TEST_F(AgentPlacementTest, BoundaryReplicaIsKeptWithoutASearch) {
  // Robot r takes frame r: robot 0 x = 1 (inside centroid 0: its own), robot 1 x = 20 (exactly on
  // centroid 2: robot 2 only), robot 2 x = 4 (distances 4, 6: search and store at robot 0, a
  // replica at robot 1, as 6 <= 1.6 x 4).
  const DescriptorMatrix x = Column({1, 20, 4});
  const BoundaryReplicationPlacement routing(table_, {.epsilon = 0.6, .max_replicas = 3});
  std::vector<FrameStream> streams;
  for (int r = 0; r < 3; ++r) streams.push_back(FrameStream{&x, FrameId(r), 1, 10.0});
  IdealTeam team(3, x, routing, streams);
  for (int r = 0; r < 3; ++r) {
    for (const std::string& c : {channels::Query(RobotId(r)), channels::Probe(RobotId(r)), channels::Store(RobotId(r))}) {
      team.Watch(c);
    }
    team.WatchMatches(channels::Match(RobotId(r)));
  }
  for (auto& a : team.agents) a->Start();
  team.sim.Run();
  EXPECT_EQ(team.seen, (std::map<std::string, int>{{"DVPR_QUERY_0", 1}, {"DVPR_STORE_1", 1}, {"DVPR_QUERY_2", 1},
                                                   {"DVPR_MATCH_1", 1}, {"DVPR_MATCH_2", 1}}));
  EXPECT_EQ(team.Stored(0), (std::set<int>{0, 2}));
  EXPECT_EQ(team.Stored(1), (std::set<int>{2}));
  EXPECT_EQ(team.Stored(2), (std::set<int>{1}));
  // Robot 0: its own frame and robot 2's; robot 1 searched nothing; robot 2 robot 1's frame.
  EXPECT_EQ(team.agents[0]->load().searches, 2);
  EXPECT_EQ(team.agents[1]->load().searches, 0);
  EXPECT_EQ(team.agents[2]->load().searches, 1);
}

}  // namespace
}  // namespace dvpr

// A robot searches its queued queries ahead, while its store is in cache (RobotAgent::
// SearchAhead); a store that changes before a query is served must still count for it. Times
// and distances worked out by hand below.
#include <gtest/gtest.h>

#include <memory>
#include <utility>
#include <vector>

#include "agents/algorithms/descriptor_index.h"
#include "agents/messages/channels.h"
#include "agents/messages/sim_transport.h"
#include "agents/robot_agent.h"
#include "net_models/medium/ideal_link.h"
#include "sim/simulator.h"
#include "tests/agents/fixed_plan.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using testing_support::FixedPlan;

// Ideal network (delivery at the instant of sending), 1 ms per search, 1-D descriptors.
// Robot 0 takes frames 0, 1, 2 (values 11, 11, 21) at 0, 0.25 and 0.5 ms and asks robot 1 to
// search each. Robot 1 only stores its own frames, 3 (value 10) at 0 ms and 4 (value 20) at 2 ms.
// Robot 1: frame 3 stored at 0 (its frame event was scheduled before robot 0's query
// arrives), query 0 served 0..1 ms; at 1 ms it serves query 1 and searches query 2 ahead,
// both against {frame 3}; at 2 ms frame 4 is stored (its event was scheduled at 0, before query
// 1's end at 1 ms) and then query 2 is served, 2..3 ms: its answer is frame 4 at distance
// (21 - 20)^2 = 1, not frame 3 at (21 - 10)^2 = 121 as searched ahead.
TEST(SearchAhead, AStoreBeforeAQueuedQueryIsServedCountsForIt) {
  const DescriptorMatrix x = testing_support::Column({11, 11, 21, 10, 20});
  Simulator sim;
  Network network(sim, 2, std::make_unique<IdealLink>());
  AgentParams params;
  params.suppression_frames = 0;
  params.service.fixed = SimTime::Millis(1);
  params.service.per_comparison = SimTime::Zero();
  params.verification.max_distance = 0.0;  // every distance below is > 0: no verification
  QueryPlan ask;
  ask.searches = 1;
  ask.channels = {channels::Probe(RobotId(1))};
  QueryPlan keep;
  keep.store_here = true;
  std::vector<std::unique_ptr<SimTransport>> transports;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  const std::vector<FrameStream> streams{{&x, FrameId(0), 3, 4000.0}, {&x, FrameId(3), 2, 500.0}};
  for (int r = 0; r < 2; ++r) {
    transports.push_back(std::make_unique<SimTransport>(network, NodeId(r)));
    agents.push_back(std::make_unique<RobotAgent>(AgentSetup{RobotId(r), 2, params, streams[static_cast<std::size_t>(r)]},
                                                  *transports.back(), std::make_unique<FixedPlan>(r == 0 ? ask : keep),
                                                  [](FrameId, FrameId) { return VerifyVerdict{}; }));
  }
  for (auto& a : agents) a->Start();
  sim.Run();

  const auto& out = agents[0]->outcomes();
  ASSERT_EQ(out.size(), 3u);
  const std::vector<std::pair<int, float>> best{{3, 1.0f}, {3, 1.0f}, {4, 1.0f}};
  const std::vector<SimTime> latency{SimTime::Millis(1), SimTime::Micros(1750), SimTime::Micros(2500)};
  for (std::size_t k = 0; k < out.size(); ++k) {
    SCOPED_TRACE(k);
    ASSERT_TRUE(out[k].best.has_value());
    EXPECT_EQ(out[k].best->frame, FrameId(best[k].first));
    EXPECT_EQ(out[k].best->distance, best[k].second);
    EXPECT_EQ(out[k].latency, latency[k]);
  }
  EXPECT_EQ(agents[1]->load().searches, 3);
  EXPECT_EQ(agents[1]->load().comparisons, 1 + 1 + 2);
}

}  // namespace
}  // namespace dvpr

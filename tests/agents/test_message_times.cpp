// Message timestamps in simulation: every utime is the run's start instant (microseconds since
// the Unix epoch) + the virtual time of sending, and a query carries its frame's capture time.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "agents/messages/channels.h"
#include "agents/messages/sim_transport.h"
#include "agents/placement/placement.h"
#include "agents/robot_agent.h"
#include "net_models/medium/ideal_link.h"
#include "sim/simulator.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

// 2011-10-03T12:00:00Z (python3: datetime(2011, 10, 3, 12, tzinfo=timezone.utc).timestamp() * 1e6).
constexpr std::int64_t kStart = 1317643200000000;

// Two robots on an ideal network (delivery at the instant of sending) and an observer node;
// robot 0 takes frames 0..2 at 4 fps (0, 250 and 500 ms), robot 1 frame 3 at 0 ms; 1 ms
// searches. Broadcast: each query goes to the other robot, which replies after its 1 ms.
TEST(MessageTimes, UtimeIsStartPlusSendTimeAndQueriesCarryTheirCaptureTime) {
  const DescriptorMatrix x = testing_support::Column({1, 2, 3, 4});
  const BroadcastPlacement routing(2);
  Simulator sim;
  Network network(sim, 3, std::make_unique<IdealLink>());
  SimTransport observer(network, NodeId(2), kStart);
  std::vector<std::unique_ptr<SimTransport>> transports;
  std::vector<std::unique_ptr<RobotAgent>> agents;
  AgentParams params;
  params.suppression_frames = 0;
  params.service.fixed = SimTime::Millis(1);
  params.service.per_comparison = SimTime::Zero();
  params.verification.max_distance = 0.0;  // no verification: queries and matches only
  const std::vector<FrameStream> streams{{&x, FrameId(0), 3, 4.0}, {&x, FrameId(3), 1, 4.0}};
  for (int r = 0; r < 2; ++r) {
    transports.push_back(std::make_unique<SimTransport>(network, NodeId(r), kStart));
    agents.push_back(std::make_unique<RobotAgent>(AgentSetup{RobotId(r), 2, params, streams[static_cast<std::size_t>(r)]},
                                                  *transports.back(), routing.MakeAgentPlacement(),
                                                  [](FrameId, FrameId) { return VerifyVerdict{}; }));
  }
  std::vector<query_t> queries;
  std::vector<match_t> matches;
  Subscription q = observer.Subscribe<query_t>(channels::kQueryAll, [&](const query_t& m) { queries.push_back(m); });
  Subscription m0 = observer.Subscribe<match_t>(channels::Match(RobotId(0)), [&](const match_t& m) { matches.push_back(m); });
  for (auto& a : agents) a->Start();
  sim.Run();

  ASSERT_EQ(queries.size(), 4u);  // robot 0's three and robot 1's one, in order of sending
  const std::vector<std::pair<int, std::int64_t>> expected{{0, 0}, {3, 0}, {1, 250000}, {2, 500000}};
  for (std::size_t i = 0; i < queries.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(queries[i].frame, expected[i].first);
    EXPECT_EQ(queries[i].capture_utime, kStart + expected[i].second);
    EXPECT_EQ(queries[i].utime, kStart + expected[i].second);  // sent when taken
  }
  // Robot 1 answers robot 0's frames after its 1 ms search; at 0 ms it first searches its own
  // frame 3 (taken before robot 0's query arrives in the same instant), so frame 0 is answered
  // at 2 ms, frames 1 and 2 at 251 and 501 ms.
  ASSERT_EQ(matches.size(), 3u);
  const std::vector<std::int64_t> replied{2000, 251000, 501000};
  for (std::size_t i = 0; i < matches.size(); ++i) {
    EXPECT_EQ(matches[i].query_frame, static_cast<int>(i));
    EXPECT_EQ(matches[i].utime, kStart + replied[i]);
  }
}

}  // namespace
}  // namespace dvpr

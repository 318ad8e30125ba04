// What every robot does, whatever it matches with (agents/agent_core.h, agents/task_server.h):
// one scenario drives a RobotAgent and a BowRobotAgent alike and expects the same core
// behaviour of both: a duplicated reply is not a new responder, a message naming a robot outside
// the team is ignored and counted, the verification exchange both ways, and a dropout.
#include <gtest/gtest.h>

#include <dvpr/bow_match_t.hpp>
#include <dvpr/bow_query_t.hpp>
#include <dvpr/match_t.hpp>
#include <dvpr/query_t.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "agents/bow_robot_agent.h"
#include "agents/messages/bow_query.h"
#include "agents/messages/channels.h"
#include "agents/messages/reply_message.h"
#include "agents/messages/sim_transport.h"
#include "agents/messages/verify_messages.h"
#include "agents/robot_agent.h"
#include "net_models/medium/ideal_link.h"
#include "sim/simulator.h"
#include "tests/agents/fixed_plan.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using testing_support::FixedPlan;

// The descriptor method: robot 0's frame is searched here and by robot 1 (a probe).
struct DescriptorMethod {
  DescriptorMatrix x = testing_support::Column({1, 2, 3, 4, 5, 6});
  std::unique_ptr<TeamAgent> MakeRobot0(AgentParams params, Transport& transport, GeometricVerifier verifier) {
    QueryPlan plan;
    plan.search_here = true;
    plan.searches = 2;
    plan.channels = {channels::Probe(RobotId(1))};
    params.verification.max_distance = 0.6;
    return std::make_unique<RobotAgent>(AgentSetup{RobotId(0), 2, params, FrameStream{&x, FrameId(0), 2, 100.0}},
                                        transport, std::make_unique<FixedPlan>(plan), std::move(verifier));
  }
  Subscription OnQueryTo1(Transport& t, std::function<void()> fn) const {
    return t.Subscribe<query_t>(channels::Probe(RobotId(1)), [fn](const query_t&) { fn(); });
  }
  // A reply to robot 0's frame 0: match_robot's frame 5 at squared distance 0.25.
  void Reply(Transport& t, int responder, int match_robot) const {
    const std::optional<IndexMatch> match = IndexMatch{RobotId(match_robot), FrameId(5), 0.25f};
    match_t m = MakeReply<match_t>(0, RobotId(0), FrameId(0), RobotId(responder), match);
    m.distance = match->distance;
    t.Publish(channels::Match(RobotId(0)), m);
  }
  void QueryRobot0(Transport& t) const {
    query_t q;
    q.robot = 1;
    q.frame = 3;
    q.dim = 1;
    q.descriptor = {4.0f};
    t.Publish(channels::Probe(RobotId(0)), q);
  }
};

// The bag-of-words method: words w mod 2, robot 0's frame 0 {w0 .5, w1 .5}: w0 scored here, w1
// by robot 1.
struct BowMethod {
  std::vector<BowVector> vectors{{{0, 0.5f}, {1, 0.5f}}, {{0, 1.0f}}, {}, {{1, 1.0f}}, {}, {}};
  std::unique_ptr<TeamAgent> MakeRobot0(AgentParams params, Transport& transport, GeometricVerifier verifier) {
    params.verification.bow_max_distance = 0.6;
    const BowTeamPlan plan{2, std::make_shared<const WordOwners>(WordOwners::Modulo(2, 2))};
    return std::make_unique<BowRobotAgent>(AgentSetup{RobotId(0), 2, params, FrameStream{nullptr, FrameId(0), 2, 100.0}},
                                           transport, plan, vectors, std::move(verifier));
  }
  Subscription OnQueryTo1(Transport& t, std::function<void()> fn) const {
    return t.Subscribe<bow_query_t>(channels::BowQuery(RobotId(1)), [fn](const bow_query_t&) { fn(); });
  }
  // A reply to robot 0's frame 0: match_robot's frame 5 scoring 0.75, distance 1 - 0.75 = 0.25
  // once voted alone.
  void Reply(Transport& t, int responder, int match_robot) const {
    const std::optional<BowIndexMatch> match = BowIndexMatch{RobotId(match_robot), FrameId(5), 0.75};
    bow_match_t m = MakeReply<bow_match_t>(0, RobotId(0), FrameId(0), RobotId(responder), match);
    m.score = match->score;
    t.Publish(channels::BowMatch(RobotId(0)), m);
  }
  void QueryRobot0(Transport& t) const {
    t.Publish(channels::BowProbe(RobotId(0)), MakeBowQuery(RobotId(1), FrameId(3), {{1, 1.0f}}, SimTime::Zero()));
  }
};

// Robot 0 of a team of two takes frames 0 (at 0 ms) and 1 (at 10 ms); the test plays robot 1 on
// an ideal network (delivery at the instant of sending). 1 ms per search and per verification,
// nothing per comparison, no suppression window.
//   0 ms: robot 0 asks robot 1 about frame 0 and searches its own (empty) store, 0..1 ms.
//         Robot 1 answers four times at once: from responder 7 (not of the team: ignored,
//         counted), from itself with a match observed by robot 9 (ignored, counted), from itself
//         with robot 1's frame 5 at distance 0.25 (accepted: 1 of 2 replies), and that reply
//         again (a duplicate: not a second responder, so the query is not complete yet).
//         It also asks robot 0 to verify its frame 5 against robot 0's frame 0, and once more
//         for a querier 8 (not of the team: ignored, counted). The verification waits behind the
//         search (the longest wait line: 1).
//   1 ms: robot 0's own search ends without a match: 2 of 2 replies, latency 1 ms; the best,
//         robot 1's frame 5 at 0.25 <= 0.6, is verified with robot 1 (a request), which accepts.
//         Robot 0 serves robot 1's verification, 1..2 ms: its verifier accepts (5, 0).
//   5 ms: robot 0 goes offline. 6 ms: robot 1 asks it about a frame: not served.
//  10 ms: frame 1 is not taken.
// Load: 1 search (its own), 1 verification, 2 ms busy, 3 foreign ids.
template <class Method>
class AgentCoreScenario : public ::testing::Test {
 protected:
  void Run() {
    Network network(sim_, 2, std::make_unique<IdealLink>());
    SimTransport t0(network, NodeId(0));
    SimTransport t1(network, NodeId(1));
    AgentParams params;
    params.suppression_frames = 0;
    params.service.fixed = SimTime::Millis(1);
    params.service.per_comparison = SimTime::Zero();
    params.verification.request_bytes = Bytes(10);
    robot0_ = method_.MakeRobot0(params, t0, [](FrameId frame, FrameId match) {
      return VerifyVerdict{frame == FrameId(5) && match == FrameId(0), 0};
    });
    std::vector<Subscription> subs;
    subs.push_back(method_.OnQueryTo1(t1, [&] {
      ++queries_to_1_;
      method_.Reply(t1, 7, 1);
      method_.Reply(t1, 1, 9);
      method_.Reply(t1, 1, 1);
      method_.Reply(t1, 1, 1);
      verify_request_t r;
      FillVerifyRequest(r, 0, RobotId(1), FrameId(5), RobotId(0), FrameId(0), 10);
      t1.Publish(channels::VerifyRequest(RobotId(0)), r);
      FillVerifyRequest(r, 0, RobotId(8), FrameId(5), RobotId(0), FrameId(0), 10);
      t1.Publish(channels::VerifyRequest(RobotId(0)), r);
    }));
    subs.push_back(t1.Subscribe<verify_request_t>(channels::VerifyRequest(RobotId(1)), [&](const verify_request_t& r) {
      requests_to_1_.push_back({r.query_robot, r.query_frame, r.match_robot, r.match_frame, sim_.Now().ns()});
      t1.Publish(channels::VerifyResult(RobotId(0)),
                 MakeVerifyResult(0, RobotId(0), FrameId(r.query_frame), RobotId(1), FrameId(r.match_frame),
                                  VerifyVerdict{true, 0}));
    }));
    subs.push_back(t1.Subscribe<verify_result_t>(channels::VerifyResult(RobotId(1)), [&](const verify_result_t& r) {
      results_to_1_.push_back({r.query_robot, r.query_frame, r.match_robot, r.match_frame, sim_.Now().ns()});
      accepted_by_0_ = r.accepted;
    }));
    robot0_->Start();
    t1.ScheduleAfter(SimTime::Millis(5), [&] { robot0_->GoOffline(); });
    t1.ScheduleAfter(SimTime::Millis(6), [&] { method_.QueryRobot0(t1); });
    sim_.Run();
    outcomes_ = robot0_->outcomes();
    load_ = robot0_->load();
    robot0_.reset();  // its subscriptions end before the transports
  }

  // (query robot, query frame, match robot, match frame, when in ns)
  using Exchange = std::vector<std::vector<std::int64_t>>;
  Simulator sim_;
  Method method_;
  std::unique_ptr<TeamAgent> robot0_;
  std::vector<QueryRecord> outcomes_;
  RobotLoad load_;
  int queries_to_1_ = 0;
  Exchange requests_to_1_;
  Exchange results_to_1_;
  bool accepted_by_0_ = false;
};

using Methods = ::testing::Types<DescriptorMethod, BowMethod>;
TYPED_TEST_SUITE(AgentCoreScenario, Methods);

TYPED_TEST(AgentCoreScenario, DuplicatesForeignIdsVerificationAndDropout) {
  this->Run();
  ASSERT_EQ(this->outcomes_.size(), 2u);
  const QueryRecord& o = this->outcomes_[0];
  EXPECT_EQ(o.expected_replies, 2);
  EXPECT_EQ(o.received_replies, 2);
  EXPECT_EQ(o.latency, SimTime::Millis(1));  // not 0: the duplicate did not complete it
  ASSERT_TRUE(o.best);
  EXPECT_EQ(o.best->robot, RobotId(1));
  EXPECT_EQ(o.best->frame, FrameId(5));
  EXPECT_FLOAT_EQ(o.best->distance, 0.25f);
  EXPECT_TRUE(o.verify_requested);
  EXPECT_TRUE(o.verify_accepted);
  EXPECT_FALSE(this->outcomes_[1].Taken());  // after the dropout

  EXPECT_EQ(this->queries_to_1_, 1);
  const std::int64_t ms = SimTime::Millis(1).ns();
  EXPECT_EQ(this->requests_to_1_, (typename TestFixture::Exchange{{0, 0, 1, 5, 1 * ms}}));
  EXPECT_EQ(this->results_to_1_, (typename TestFixture::Exchange{{1, 5, 0, 0, 2 * ms}}));
  EXPECT_TRUE(this->accepted_by_0_);

  const RobotLoad& load = this->load_;
  EXPECT_EQ(load.searches, 1);  // the query after the dropout was not served
  EXPECT_EQ(load.remote_queries, 0);
  EXPECT_EQ(load.verifications, 1);
  EXPECT_EQ(load.busy, SimTime::Millis(2));
  EXPECT_EQ(load.max_queue, 1);
  EXPECT_EQ(load.foreign_ids, 3);
}

}  // namespace
}  // namespace dvpr

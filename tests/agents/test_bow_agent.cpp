// The bag-of-words robot agent (agents/bow_robot_agent.h) and its store (agents/algorithms/bow_index.h):
// the responder's partial scoring and storing, the reply's LCM size, and a three-robot team on
// an ideal network whose messages, sizes, votes and verifications are all worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "agents/algorithms/bow_index.h"
#include "agents/bow_robot_agent.h"
#include "agents/messages/channels.h"
#include "agents/messages/lcm_codec.h"
#include "agents/messages/sim_transport.h"
#include "agents/messages/verification_payload.h"
#include "net_models/medium/ideal_link.h"
#include "net_models/network/network_observer.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

// A responder stored three parts (weights exact in float):
//   frame 10 of robot 1: {w1: 0.25, w2: 0.5}
//   frame 20 of robot 2: {w2: 0.25, w3: 0.25}
//   frame 30 of robot 0: {w1: 0.125, w3: 0.5}
// Query part of frame 25, {w1: 0.5, w2: 0.125, w3: 0.25}, sum over shared words of min:
//   frame 10: min(.5, .25) + min(.125, .5) = 0.375
//   frame 20: min(.125, .25) + min(.25, .25) = 0.375
//   frame 30: min(.5, .125) + min(.25, .5) = 0.375
// All tie: the lowest frame id, 10, observed by robot 1. Postings visited: w1 2, w2 2, w3 2 = 6.
TEST(BowIndex, ScoresTheSumOfSharedMinimaAndBreaksTiesToTheLowerFrame) {
  BowIndex index;
  index.Add(RobotId(1), FrameId(10), {{1, 0.25f}, {2, 0.5f}});
  index.Add(RobotId(2), FrameId(20), {{2, 0.25f}, {3, 0.25f}});
  index.Add(RobotId(0), FrameId(30), {{1, 0.125f}, {3, 0.5f}});
  EXPECT_EQ(index.size(), 3u);
  EXPECT_EQ(index.postings(), 6);
  const BowVector query{{1, 0.5f}, {2, 0.125f}, {3, 0.25f}};
  const BowSearchResult r = index.Search(query, FrameId(25), 0);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(r.best->frame, FrameId(10));
  EXPECT_EQ(r.best->robot, RobotId(1));
  EXPECT_DOUBLE_EQ(r.best->score, 0.375);
  EXPECT_EQ(r.comparisons, 6);
}

// Window 5 around frame 25 hides frames 20 and 30 (|25 - 20| = 5): frame 10 alone, 0.375, and
// only its 2 postings count. Window 15 hides all three: no match, nothing visited.
TEST(BowIndex, NeverReturnsAFrameInsideTheSuppressionWindow) {
  BowIndex index;
  index.Add(RobotId(1), FrameId(10), {{1, 0.25f}, {2, 0.5f}});
  index.Add(RobotId(2), FrameId(20), {{2, 0.25f}, {3, 0.75f}});
  index.Add(RobotId(0), FrameId(30), {{1, 0.5f}, {3, 0.5f}});
  const BowVector query{{1, 0.5f}, {2, 0.125f}, {3, 0.25f}};
  const BowSearchResult r = index.Search(query, FrameId(25), 5);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(r.best->frame, FrameId(10));
  EXPECT_DOUBLE_EQ(r.best->score, 0.375);
  EXPECT_EQ(r.comparisons, 2);
  const BowSearchResult none = index.Search(query, FrameId(25), 15);
  EXPECT_FALSE(none.best);
  EXPECT_EQ(none.comparisons, 0);
}

// A higher score wins over a lower frame id; a second Add of a stored frame (a duplicated
// message) changes nothing; a part sharing no word finds nothing.
TEST(BowIndex, HighestScoreWinsAndADuplicateIsStoredOnce) {
  BowIndex index;
  index.Add(RobotId(0), FrameId(1), {{7, 0.25f}});
  index.Add(RobotId(1), FrameId(2), {{7, 0.5f}});
  index.Add(RobotId(1), FrameId(2), {{7, 0.5f}});
  EXPECT_EQ(index.size(), 2u);
  EXPECT_EQ(index.postings(), 2);
  const BowSearchResult r = index.Search({{7, 0.75f}}, FrameId(100), 0);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(r.best->frame, FrameId(2));
  EXPECT_DOUBLE_EQ(r.best->score, 0.5);  // min(.75, .5), once
  EXPECT_FALSE(index.Search({{8, 1.0f}}, FrameId(100), 0).best);
}

// bow_match_t by LCM's rules: fingerprint 8, utime int64 8, query_robot int16 2, query_frame
// int32 4, responder int16 2, has_match boolean 1, match_robot int16 2, match_frame int32 4,
// score double 8: 39 bytes, the score's 8 bytes big-endian IEEE 754 at the end.
TEST(BowMatchMessage, EncodesTo39BytesAndBack) {
  bow_match_t m;
  m.utime = 5;
  m.query_robot = 1;
  m.query_frame = 2;
  m.responder = 3;
  m.has_match = true;
  m.match_robot = 4;
  m.match_frame = 6;
  m.score = 0.375;  // 0x3FD8000000000000
  const std::vector<std::uint8_t> buf = Encode(m);
  ASSERT_EQ(buf.size(), 39u);
  EXPECT_EQ(std::vector<std::uint8_t>(buf.end() - 8, buf.end()),
            (std::vector<std::uint8_t>{0x3F, 0xD8, 0, 0, 0, 0, 0, 0}));
  const auto back = Decode<bow_match_t>(buf);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->match_frame, 6);
  EXPECT_EQ(back->score, 0.375);
  EXPECT_FALSE(Decode<bow_match_t>(std::span<const std::uint8_t>(buf.data(), 38)));
}

// Every message a team sent: (sent ns, channel, source, destination, payload bytes), and the
// verification exchange's messages decoded.
struct SentLog final : NetworkObserver {
  std::vector<std::tuple<std::int64_t, std::string, int, int, std::size_t>> sent;
  std::vector<verify_request_t> requests;
  std::vector<verify_result_t> results;
  void OnSent(const MessageCopy& c) override {
    sent.emplace_back(c.sent.ns(), std::string(c.channel_name), c.src.value, c.dst.value, c.payload.size());
    if (c.channel_name.starts_with("DVPR_VREQ_")) requests.push_back(Decode<verify_request_t>(c.payload).value());
    if (c.channel_name.starts_with("DVPR_VRES_")) results.push_back(Decode<verify_result_t>(c.payload).value());
  }
};

// Three robots, words w mod 3 (robot 0: w0 w3 w6, robot 1: w1 w4 w7, robot 2: w2 w5 w8), one
// frame a second (robot r takes frames 2r at 0 s and 2r + 1 at 1 s), window 0, 1 ms per search
// and per verification, no cost per posting, an ideal network (delivery at the instant of
// sending), verification of matches at distance <= 0.6 (bow_max_distance) with 100-byte
// requests; the verifier accepts only frame 4. Vectors (frames of one instant share no word, so the order of events
// within an instant cannot change an answer):
//   F0 (r0) {w0 .5, w1 .25, w2 .25}  parts r0 {w0}, r1 {w1}, r2 {w2}: queries to r1, r2
//   F2 (r1) {w4 .5, w7 .5}           all robot 1's: no message
//   F4 (r2) {w3 .5, w5 .5}           parts r0 {w3}, r2 {w5}: a query to r0
//   F1 (r0) {w0 .25, w1 .25, w4 .5}  parts r0 {w0}, r1 {w1, w4}: a query to r1
//   F3 (r1) {w2 .5, w8 .5}           all robot 2's: a query to r2, no local search
//   F5 (r2) {w3 .5, w5 .25, w6 .25}  parts r0 {w3, w6}, r2 {w5}: a query to r0
// At 0 s nothing is stored yet when the parts are scored (they share no word): every answer is
// empty. At 1 s:
//   F1: r0 scores {w0 .25} against F0 {w0 .5}: F0, .25; r1 scores {w1 .25, w4 .5} against
//       F0 {w1 .25}: .25 and F2 {w4 .5, w7 .5}: .5 -> F2, .5. One vote each: the larger score,
//       F2 (robot 1), distance 1 - .5 = .5 <= .6: verified with robot 1, rejected.
//       (Centralized, F0 and F2 both score .5 and F0 would win: the split changes the answer.)
//   F3: r2 scores {w2 .5, w8 .5} against F0 {w2 .25} and F4 {w5 .5}: F0, .25; one answer,
//       distance .75 > .6: no verification.
//   F5: r0 scores {w3 .5, w6 .25} against F4 {w3 .5} (F0 {w0} and F1 {w0} share nothing): .5;
//       r2 scores {w5 .25} against F4 {w5 .5}: .25. Two votes for F4: distance 1 - .75 = .25,
//       verified by robot 2 itself (no message), accepted.
// Messages: bow_query_t 26 + 8 x words: three of one word (34 B) at 0 s, three of two (42 B) at
// 1 s; a bow_match_t (39 B) back for each; one verify_request_t (8 + 8 + 2 + 4 + 2 + 4 + 4 +
// 100 = 132 B) r0 -> r1 and its verify_result_t (8 + 8 + 2 + 4 + 2 + 4 + 1 + 4 = 33 B) back.
class ThreeRobotBowTeam : public ::testing::Test {
 protected:
  void Run(BowTeamPlan plan) {
    network_ = std::make_unique<Network>(sim_, 3, std::make_unique<IdealLink>());
    const ObserverSubscription sub = network_->Subscribe(log_);
    AgentParams params;
    params.suppression_frames = 0;
    params.service.fixed = SimTime::Millis(1);
    params.service.per_comparison = SimTime::Zero();
    params.verification.max_distance = 0.0;  // the descriptors' threshold: not the one BoW uses
    params.verification.bow_max_distance = 0.6;
    params.verification.request_bytes = Bytes(100);
    const GeometricVerifier verifier = [](FrameId, FrameId match) { return VerifyVerdict{match == FrameId(4), 0}; };
    for (int r = 0; r < 3; ++r) {
      transports_.push_back(std::make_unique<SimTransport>(*network_, NodeId(r)));
      const AgentSetup setup{RobotId(r), 3, params, FrameStream{nullptr, FrameId(2 * r), 2, 1.0}};
      agents_.push_back(std::make_unique<BowRobotAgent>(setup, *transports_.back(), plan, vectors_, verifier));
    }
    for (auto& a : agents_) a->Start();
    sim_.Run();
  }
  const QueryRecord& Outcome(int frame) const {
    return agents_[static_cast<std::size_t>(frame / 2)]->outcomes()[static_cast<std::size_t>(frame % 2)];
  }

  std::vector<BowVector> vectors_{{{0, .5f}, {1, .25f}, {2, .25f}}, {{0, .25f}, {1, .25f}, {4, .5f}},
                                  {{4, .5f}, {7, .5f}},             {{2, .5f}, {8, .5f}},
                                  {{3, .5f}, {5, .5f}},             {{3, .5f}, {5, .25f}, {6, .25f}}};
  Simulator sim_;
  SentLog log_;
  std::unique_ptr<Network> network_;  // outlives the transports, which outlive the agents
  std::vector<std::unique_ptr<SimTransport>> transports_;
  std::vector<std::unique_ptr<BowRobotAgent>> agents_;
};

TEST_F(ThreeRobotBowTeam, SendsTheHandWorkedMessages) {
  Run(BowTeamPlan{3, std::make_shared<const WordOwners>(WordOwners::Modulo(9, 3))});
  auto sent = log_.sent;
  std::sort(sent.begin(), sent.end());
  const std::int64_t s = 1'000'000'000, ms = 1'000'000;
  const std::vector<std::tuple<std::int64_t, std::string, int, int, std::size_t>> expected{
      {0, "DVPR_BOWQ_0", 2, 0, 34},                 // F4's w3
      {0, "DVPR_BOWQ_1", 0, 1, 34},                 // F0's w1
      {0, "DVPR_BOWQ_2", 0, 2, 34},                 // F0's w2
      {2 * ms, "DVPR_BOWM_0", 1, 0, 39},            // F0 from r1 (after its own F2, 0-1 ms)
      {2 * ms, "DVPR_BOWM_0", 2, 0, 39},            // F0 from r2 (after its own F4)
      {2 * ms, "DVPR_BOWM_2", 0, 2, 39},            // F4 from r0 (after its own F0)
      {s, "DVPR_BOWQ_0", 2, 0, 42},                 // F5's w3 w6
      {s, "DVPR_BOWQ_1", 0, 1, 42},                 // F1's w1 w4
      {s, "DVPR_BOWQ_2", 1, 2, 42},                 // F3's w2 w8
      {s + ms, "DVPR_BOWM_0", 1, 0, 39},            // F1 from r1 (idle: 1 s to 1.001 s)
      {s + ms, "DVPR_VREQ_1", 0, 1, 132},           // F1 -> F2, when both answers are in
      {s + 2 * ms, "DVPR_BOWM_1", 2, 1, 39},        // F3 from r2 (after its own F5)
      {s + 2 * ms, "DVPR_BOWM_2", 0, 2, 39},        // F5 from r0 (after its own F1)
      {s + 2 * ms, "DVPR_VRES_0", 1, 0, 33},        // r1's verdict on F2
  };
  EXPECT_EQ(sent, expected);
}

// The one exchange over the network (see the fixture): robot 0 asks robot 1 at 1.001 s (utime
// in microseconds from 0) to verify its F1 against F2; robot 1 answers 1 ms later, rejected
// (the verifier accepts only F4; it counts no inliers). The request's 100 payload bytes stand
// for F1's keypoints: derived from its BoW weights in word order, .25 .25 .5
// (agents/messages/verification_payload.h).
TEST_F(ThreeRobotBowTeam, VerificationMessagesCarryTheQueryAndTheMatch) {
  Run(BowTeamPlan{3, std::make_shared<const WordOwners>(WordOwners::Modulo(9, 3))});
  ASSERT_EQ(log_.requests.size(), 1u);
  const verify_request_t& r = log_.requests[0];
  EXPECT_EQ(r.utime, 1'001'000);
  EXPECT_EQ(r.query_robot, 0);
  EXPECT_EQ(r.query_frame, 1);
  EXPECT_EQ(r.match_robot, 1);
  EXPECT_EQ(r.match_frame, 2);
  EXPECT_EQ(r.payload_size, 100);
  const std::vector<float> f1_weights{.25f, .25f, .5f};
  EXPECT_EQ(r.payload, VerificationPayload(FrameId(1), f1_weights, 100));

  ASSERT_EQ(log_.results.size(), 1u);
  const verify_result_t& v = log_.results[0];
  EXPECT_EQ(v.utime, 1'002'000);
  EXPECT_EQ(v.query_robot, 0);
  EXPECT_EQ(v.query_frame, 1);
  EXPECT_EQ(v.match_robot, 1);
  EXPECT_EQ(v.match_frame, 2);
  EXPECT_FALSE(v.accepted);
  EXPECT_EQ(v.inliers, 0);
}

TEST_F(ThreeRobotBowTeam, VotesAndVerifiesAsWorkedByHand) {
  Run(BowTeamPlan{3, std::make_shared<const WordOwners>(WordOwners::Modulo(9, 3))});
  for (const int f : {0, 2, 4}) {
    SCOPED_TRACE(f);
    EXPECT_TRUE(Outcome(f).Complete());
    EXPECT_FALSE(Outcome(f).best);
    EXPECT_FALSE(Outcome(f).verify_requested);
  }
  EXPECT_EQ(Outcome(0).expected_replies, 3);
  EXPECT_EQ(Outcome(2).expected_replies, 1);
  EXPECT_EQ(Outcome(4).expected_replies, 2);

  const QueryRecord& f1 = Outcome(1);
  ASSERT_TRUE(f1.best);
  EXPECT_EQ(f1.best->frame, FrameId(2));
  EXPECT_EQ(f1.best->robot, RobotId(1));
  EXPECT_FLOAT_EQ(f1.best->distance, 0.5f);
  EXPECT_EQ(f1.latency, SimTime::Millis(1));
  EXPECT_TRUE(f1.verify_requested);
  EXPECT_EQ(f1.verify_accepted, std::optional<bool>(false));

  const QueryRecord& f3 = Outcome(3);
  EXPECT_EQ(f3.expected_replies, 1);  // robot 1 owns none of F3's words: no local search
  ASSERT_TRUE(f3.best);
  EXPECT_EQ(f3.best->frame, FrameId(0));
  EXPECT_EQ(f3.best->robot, RobotId(0));
  EXPECT_FLOAT_EQ(f3.best->distance, 0.75f);
  EXPECT_FALSE(f3.verify_requested);

  const QueryRecord& f5 = Outcome(5);
  ASSERT_TRUE(f5.best);
  EXPECT_EQ(f5.best->frame, FrameId(4));
  EXPECT_EQ(f5.best->robot, RobotId(2));
  EXPECT_FLOAT_EQ(f5.best->distance, 0.25f);
  EXPECT_EQ(f5.latency, SimTime::Millis(2));
  EXPECT_EQ(f5.verify_accepted, std::optional<bool>(true));
}

// Searches served (own and remote parts; two remote at each robot), postings visited at 1 s (at 0 s no part shares a
// stored word), parts stored, verifications (see the fixture):
//   r0: F0, F4's, F1, F5's; visits F0 (for F1) and F4 (for F5): 2; stores F0 F4 F1 F5; none
//   r1: F2, F0's, F1's; visits F0 and F2 (for F1): 2; stores F2 F0 F1; verifies F1 -> F2
//   r2: F4, F0's, F3's, F5; visits F0 (for F3) and F4 (for F5): 2; stores F4 F0 F3 F5; verifies F5
TEST_F(ThreeRobotBowTeam, RecordsTheLoadOfEachRobot) {
  Run(BowTeamPlan{3, std::make_shared<const WordOwners>(WordOwners::Modulo(9, 3))});
  const std::vector<std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t, std::int64_t>> expected{
      {4, 2, 2, 4, 0}, {3, 2, 2, 3, 1}, {4, 2, 2, 4, 1}};
  for (int r = 0; r < 3; ++r) {
    const RobotLoad l = agents_[static_cast<std::size_t>(r)]->load();
    EXPECT_EQ(std::make_tuple(l.searches, l.remote_queries, l.comparisons, l.stored, l.verifications),
              expected[static_cast<std::size_t>(r)])
        << "robot " << r;
  }
}

// Broadcast: each frame's whole vector to both others on DVPR_BOWP_ (probes: scored, not kept);
// each robot keeps only its own frames. F1 (whole {w0 .25, w1 .25, w4 .5}) is scored by r0
// against F0: .25 + .25 = .5, by r1 against F2: .5, by r2 against F4: nothing. Two answers of
// one vote and .5 each: the lower frame, F0 (robot 0), distance .5: verified locally, rejected.
// F5 ({w3 .5, w5 .25, w6 .25}) is scored by r2 against F4: .5 + .25 = .75, the others share
// nothing with F0, F1, F2, F3: F4, distance .25.
TEST_F(ThreeRobotBowTeam, BroadcastSendsTheWholeVectorAndKeepsOwnFrames) {
  Run(BowTeamPlan{3, nullptr});
  std::size_t probes = 0;
  for (const auto& [t, channel, src, dst, bytes] : log_.sent) {
    if (channel.rfind("DVPR_BOWP_", 0) != 0) continue;
    ++probes;
    EXPECT_EQ(bytes, 26 + 8 * vectors_[static_cast<std::size_t>(src * 2 + (t > 0 ? 1 : 0))].size());
  }
  EXPECT_EQ(probes, 12u);  // 6 frames x 2 other robots
  for (int r = 0; r < 3; ++r) EXPECT_EQ(agents_[static_cast<std::size_t>(r)]->load().stored, 2) << r;
  ASSERT_TRUE(Outcome(1).best);
  EXPECT_EQ(Outcome(1).best->frame, FrameId(0));
  EXPECT_FLOAT_EQ(Outcome(1).best->distance, 0.5f);
  EXPECT_EQ(Outcome(1).expected_replies, 3);
  ASSERT_TRUE(Outcome(5).best);
  EXPECT_EQ(Outcome(5).best->frame, FrameId(4));
  EXPECT_FLOAT_EQ(Outcome(5).best->distance, 0.25f);
}

// A frame without words: no robot is asked, the robot searches its own store with nothing; the
// query is taken and complete, without a match.
TEST(BowRobotAgent, AFrameWithoutWordsIsStillAQuery) {
  Simulator sim;
  Network network(sim, 2, std::make_unique<IdealLink>());
  SimTransport t0(network, NodeId(0)), t1(network, NodeId(1));
  const std::vector<BowVector> vectors{{}, {{1, 1.0f}}};
  const BowTeamPlan plan{2, std::make_shared<const WordOwners>(WordOwners::Modulo(2, 2))};
  const GeometricVerifier verifier = [](FrameId, FrameId) { return VerifyVerdict{}; };
  BowRobotAgent a0(AgentSetup{RobotId(0), 2, AgentParams{}, FrameStream{nullptr, FrameId(0), 1, 10.0}}, t0, plan, vectors,
                   verifier);
  BowRobotAgent a1(AgentSetup{RobotId(1), 2, AgentParams{}, FrameStream{nullptr, FrameId(1), 1, 10.0}}, t1, plan, vectors,
                   verifier);
  a0.Start();
  a1.Start();
  sim.Run();
  ASSERT_TRUE(a0.outcomes()[0].Taken());
  EXPECT_TRUE(a0.outcomes()[0].Complete());
  EXPECT_FALSE(a0.outcomes()[0].best);
  EXPECT_EQ(a0.load().stored, 0);
}

}  // namespace
}  // namespace dvpr

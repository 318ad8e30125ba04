// The pieces of the real deployment that need no second process: the team
// barrier's state, the agent log round trip, LcmTransport's clock and timers
// over loopback multicast.
#include <chrono>
#include <fstream>

#include "agents/messages/team_sync.h"
#include "experiments/protocols/lcm/agent_log.h"
#include "agents/auth/message_auth.h"
#include "lcm_test_support.h"

namespace dvpr {
namespace {

using namespace lcm_test;

TEST(TeamSync, StartsAtTheLatestReadyInstantPlusMarginOnceAllAreHeard) {
  TeamSync a(RobotId(0), 3, 7), b(RobotId(2), 3, 7);
  const agent_status_t s0 = a.Announce(1, agent_status_t::READY, 1000, 0);
  const agent_status_t s1 = TeamSync(RobotId(1), 3, 7).Announce(1, agent_status_t::READY, 5000, 0);
  const agent_status_t s2 = b.Announce(1, agent_status_t::READY, 3000, 0);
  for (const auto& s : {s0, s1}) EXPECT_TRUE(a.OnStatus(s));
  EXPECT_FALSE(a.StartUtime(100));
  EXPECT_TRUE(a.OnStatus(s2));
  for (const auto& s : {s2, s1, s0}) b.OnStatus(s);  // another order, the same start
  EXPECT_EQ(a.StartUtime(100), 5100);
  EXPECT_EQ(b.StartUtime(100), 5100);
  EXPECT_FALSE(a.AllDone());
}

// Each robot's sender is the first one heard announcing it; another sender for the same robot
// (a second process started as robot 1, a copy of the team), or one sender speaking for two
// robots, is foreign, and messages are taken only from the robot's own sender.
TEST(TeamSync, ARobotsSenderIsTheFirstHeardAndNoOtherSpeaksForIt) {
  TeamSync a(RobotId(0), 3, 7);
  const agent_status_t s1 = TeamSync(RobotId(1), 3, 7).Announce(1, agent_status_t::READY, 10, 0);
  const agent_status_t s2 = TeamSync(RobotId(2), 3, 7).Announce(1, agent_status_t::READY, 20, 0);
  EXPECT_TRUE(a.OnStatus(s1, 1001));
  EXPECT_TRUE(a.OnStatus(s1, 1001));    // the same sender again
  EXPECT_FALSE(a.OnStatus(s1, 2002));   // another process claims robot 1
  EXPECT_FALSE(a.OnStatus(s2, 1001));   // robot 1's process claims robot 2
  EXPECT_TRUE(a.OnStatus(s2, 3003));
  EXPECT_TRUE(a.OnStatus(a.Announce(1, agent_status_t::READY, 5, 0)));  // our own, taken directly
  EXPECT_EQ(a.foreign(), 2u);
  EXPECT_EQ(a.HeardCount(), 3);
  EXPECT_TRUE(a.FromMember(RobotId(1), 1001));
  EXPECT_FALSE(a.FromMember(RobotId(1), 2002));
  EXPECT_FALSE(a.FromMember(RobotId(2), 1001));
  EXPECT_FALSE(a.FromMember(RobotId(0), 0));   // no sender is never a member
  EXPECT_FALSE(a.FromMember(RobotId(5), 1001));  // out of range
  EXPECT_FALSE(a.FromMember(RobotId(0), 4004));  // robot 0's own echo not heard yet
  EXPECT_TRUE(a.OnStatus(a.Announce(2, agent_status_t::READY, 5, 0), 4004));
  EXPECT_TRUE(a.FromMember(RobotId(0), 4004));
}

TEST(TeamSync, ForeignHeartbeatsAreCountedNotTaken) {
  TeamSync a(RobotId(0), 2, 7);
  agent_status_t s = TeamSync(RobotId(1), 2, 8).Announce(1, agent_status_t::DONE, 1, 0);  // other key
  EXPECT_FALSE(a.OnStatus(s));
  s.team_key = 7;
  s.robot = 5;  // out of range
  EXPECT_FALSE(a.OnStatus(s));
  s.robot = 1;
  s.state = 9;
  EXPECT_FALSE(a.OnStatus(s));
  EXPECT_EQ(a.foreign(), 3u);
  EXPECT_EQ(a.HeardCount(), 0);
  s.state = agent_status_t::DONE;
  EXPECT_TRUE(a.OnStatus(s));
  EXPECT_FALSE(a.AllDone());
  a.OnStatus(a.Announce(1, agent_status_t::DONE, 1, 0));
  EXPECT_TRUE(a.AllDone());
}

TEST(AgentLog, RoundTripsExactly) {
  AgentLog l;
  l.robot = 1;
  l.robots = 2;
  l.strategy = "decentralized";
  l.speedup = 2.5;
  l.start_utime = 1700000000000000;
  l.end_ns = 123;
  l.end_reason = "all_done";
  l.published = 5;
  l.malformed = 3;
  l.out_of_range = 8;
  l.unauthenticated = 11;
  l.held_dropped = 12;
  l.held_bytes_peak = 13;
  l.load.busy = SimTime::Nanos(77);
  l.sent = {{1, 2, 3}, {0, 0, 0}};
  l.received_from = {4, 0};
  QueryRecord q;
  q.robot = RobotId(1);
  q.frame = FrameId(10);
  q.sent = SimTime::Millis(100);
  q.best = IndexMatch{RobotId(0), FrameId(3), 0.1f + 1e-7f};  // needs every digit to read back the same
  q.latency = SimTime::Micros(250);
  q.expected_replies = q.received_replies = 1;
  q.verify_requested = true;
  q.verify_accepted = false;
  l.queries = {q, QueryRecord{}};
  l.queries[1].robot = RobotId(1);
  const fs::path path = fs::path(DVPR_TEST_TMP) / "agent_log_round_trip.log";
  WriteAgentLog(path, l);
  const AgentLog r = ReadAgentLog(path);
  EXPECT_EQ(r.speedup, 2.5);
  EXPECT_EQ(r.start_utime, l.start_utime);
  EXPECT_EQ(r.out_of_range, 8u);
  EXPECT_EQ(r.unauthenticated, 11u);
  EXPECT_EQ(r.held_dropped, 12u);
  EXPECT_EQ(r.held_bytes_peak, 13u);
  EXPECT_EQ(r.sent[0].wire_bytes, 3);
  EXPECT_EQ(r.received_from[0], 4);
  ASSERT_EQ(r.queries.size(), 2u);
  ASSERT_TRUE(r.queries[0].best);
  EXPECT_EQ(r.queries[0].best->robot, RobotId(0));
  EXPECT_EQ(r.queries[0].best->frame, FrameId(3));
  EXPECT_EQ(r.queries[0].best->distance, q.best->distance);
  EXPECT_EQ(r.queries[0].latency, q.latency);
  EXPECT_EQ(r.queries[0].verify_accepted, std::optional<bool>(false));
  EXPECT_FALSE(r.queries[1].best);
  EXPECT_FALSE(r.queries[1].latency);
}

TEST(AgentLog, RejectsATruncatedLine) {
  const fs::path path = fs::path(DVPR_TEST_TMP) / "agent_log_bad.log";
  std::ofstream(path) << "agent,0,2,0,broadcast,1,0,0,deadline,0,0,0,0,0,0,0\nquery,1,2\n";
  EXPECT_THROW(ReadAgentLog(path), std::runtime_error);
}

class LcmTransportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = IsolateNetwork();
    if (!why.empty()) GTEST_SKIP() << why;
  }
};

// Publish and receive through the loopback group; garbage is counted; timers
// run in order, a chain scheduled from timers keeps its period (no drift);
// a timer scheduled before the epoch counts from the epoch.
TEST_F(LcmTransportTest, DeliversCountsGarbageAndKeepsTimersOnSchedule) {
  LcmTransport t(Url(7710), 10.0);
  std::vector<std::int32_t> frames;
  Subscription sub = t.Subscribe<match_t>("DVPR_MATCH_0", [&](const match_t& m) { frames.push_back(m.query_frame); });
  match_t m;
  m.query_frame = 7;
  t.Publish("DVPR_MATCH_0", m);
  t.PublishRaw("DVPR_MATCH_0", std::vector<std::uint8_t>{1, 2, 3});
  // Five ticks, 100 ms of agent time (10 ms of wall time) apart. The transport runs in short
  // slices until the ticks have fired and both messages are in; the 60 s bound only ends a
  // broken transport. Nothing here depends on how much wall time a loaded machine gives us.
  std::vector<SimTime> fired;
  std::function<void()> tick = [&] {
    fired.push_back(t.Now());
    if (fired.size() < 5) t.ScheduleAfter(SimTime::Millis(100), tick);
  };
  t.ScheduleAfter(SimTime::Millis(100), tick);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((fired.size() < 5 || frames.empty() || t.MalformedCount() == 0) &&
         std::chrono::steady_clock::now() < give_up) {
    EXPECT_FALSE(t.Run(t.Now() + SimTime::Millis(100)));  // a slice ends at its deadline
  }
  EXPECT_EQ(frames, std::vector<std::int32_t>{7});
  EXPECT_EQ(t.MalformedCount(), 1u);
  ASSERT_EQ(fired.size(), 5u);
  for (std::size_t i = 0; i < fired.size(); ++i) {
    EXPECT_GE(fired[i], SimTime::Millis(100) * static_cast<std::int64_t>(i + 1));  // never early
  }
  // The epoch moves agent time 0 into the future (an hour: no scheduling delay reaches it); a
  // timer set before a nearer epoch fires after it, however late the loop runs.
  t.SetEpoch(std::chrono::system_clock::now() + std::chrono::hours(1));
  EXPECT_LT(t.Now(), SimTime::Zero());
  t.SetEpoch(std::chrono::system_clock::now() + std::chrono::milliseconds(30));
  bool after_epoch = false;
  t.ScheduleAfter(SimTime::Zero(), [&] { after_epoch = t.Now() >= SimTime::Zero(); t.Stop(); });
  EXPECT_TRUE(t.Run(SimTime::Seconds(10.0)));
  EXPECT_TRUE(after_epoch);
}

// utime is the wall clock: agent time t after the epoch is the epoch + t / speedup, in
// microseconds since 1970 (2 s of agent time at speedup 4 is 0.5 s of wall time).
TEST_F(LcmTransportTest, UtimeIsTheEpochPlusAgentTimeOverSpeedup) {
  LcmTransport t(Url(7712), 4.0);
  constexpr std::int64_t kEpoch = 1317643200000000;  // 2011-10-03T12:00:00Z
  t.SetEpoch(std::chrono::system_clock::time_point(std::chrono::microseconds(kEpoch)));
  EXPECT_EQ(t.UtimeAt(SimTime::Zero()), kEpoch);
  EXPECT_EQ(t.UtimeAt(SimTime::Seconds(2.0)), kEpoch + 500000);
  EXPECT_EQ(t.UtimeAt(SimTime::Micros(-8)), kEpoch - 2);
}

// A message that arrives on a held channel before anyone subscribed is kept and handled once a
// handler subscribes (in arrival order, counted once); an unheld channel without a subscriber
// keeps nothing. This is what lets a slow agent leave the start barrier after a teammate has
// already sent it its first queries.
TEST_F(LcmTransportTest, HeldChannelKeepsWhatArrivesBeforeTheSubscriber) {
  LcmTransport t(Url(7713), 1.0);
  t.HoldUntilSubscribed({"DVPR_MATCH_0"});
  // A second transport is the teammate; so the test also waits for the datagrams to arrive.
  LcmTransport other(Url(7713), 1.0);
  std::vector<std::int32_t> frames, early;
  Subscription listen = other.Subscribe<match_t>("DVPR_MATCH_0", [&](const match_t& m) { early.push_back(m.query_frame); });
  Subscription listen1 = other.Subscribe<match_t>("DVPR_MATCH_1", [&](const match_t& m) { early.push_back(m.query_frame); });
  for (std::int32_t f : {3, 4}) {
    match_t m;
    m.query_frame = f;
    other.Publish("DVPR_MATCH_0", m);
  }
  match_t lost;
  lost.query_frame = 9;
  other.Publish("DVPR_MATCH_1", lost);  // nobody in `t` holds or subscribes to it
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (early.size() < 3 && std::chrono::steady_clock::now() < give_up) {
    other.Run(other.Now() + SimTime::Millis(20));
    t.Run(t.Now() + SimTime::Millis(20));  // `t` reads the datagrams too, with no handler
  }
  ASSERT_EQ(early.size(), 3u);
  t.Run(t.Now() + SimTime::Millis(50));
  EXPECT_EQ(t.Received(), 0u);  // kept, not yet handled
  Subscription sub = t.Subscribe<match_t>("DVPR_MATCH_0", [&](const match_t& m) { frames.push_back(m.query_frame); });
  Subscription sub1 = t.Subscribe<match_t>("DVPR_MATCH_1", [&](const match_t& m) { frames.push_back(m.query_frame); });
  EXPECT_TRUE(frames.empty());  // not from inside Subscribe
  while (frames.size() < 2 && std::chrono::steady_clock::now() < give_up) t.Run(t.Now() + SimTime::Millis(20));
  t.Run(t.Now() + SimTime::Millis(50));
  EXPECT_EQ(frames, (std::vector<std::int32_t>{3, 4}));
  EXPECT_EQ(t.Received(), 2u);
}


// A team's transports (one secret) take each other's messages once, knowing the sender's robot;
// a message without a tag, one sealed with another secret, one changed in transit and a replay
// of a genuine one are counted and never handled. The test waits until all six have been seen.
TEST_F(LcmTransportTest, AuthenticatedTransportsTakeOnlyTheirTeamsMessagesOnce) {
  const auth::Secret secret = auth::DrawSecret();
  LcmTransport receiver(Url(7714), 1.0);
  receiver.Authenticate(auth::MessageAuth(secret, 0));
  LcmTransport teammate(Url(7714), 1.0);
  teammate.Authenticate(auth::MessageAuth(secret, 1));
  LcmTransport outsider(Url(7714), 1.0);
  outsider.Authenticate(auth::MessageAuth(auth::DrawSecret(), 1));
  std::vector<std::pair<int, int>> got;  // query_frame, robot of the authenticated sender
  Subscription sub = receiver.Subscribe<match_t>("DVPR_MATCH_0", [&](const match_t& m) {
    got.emplace_back(m.query_frame, auth::RobotOfSender(receiver.CurrentSender()));
  });
  match_t genuine{};
  genuine.query_frame = 1;
  std::vector<std::uint8_t> sealed = Encode(genuine);
  auth::MessageAuth robot1(secret, 1);
  robot1.Seal("DVPR_MATCH_0", sealed);
  teammate.PublishRaw("DVPR_MATCH_0", sealed);  // genuine: robot 1's tag
  teammate.PublishRaw("DVPR_MATCH_0", sealed);  // its replay
  std::vector<std::uint8_t> changed = sealed;
  changed[12] ^= 0x01;
  teammate.PublishRaw("DVPR_MATCH_0", changed);  // changed in transit
  match_t untagged{};
  untagged.query_frame = 2;
  teammate.PublishRaw("DVPR_MATCH_0", Encode(untagged));  // no tag at all
  match_t foreign{};
  foreign.query_frame = 3;
  outsider.Publish("DVPR_MATCH_0", foreign);  // another team's secret
  match_t last{};
  last.query_frame = 4;
  teammate.Publish("DVPR_MATCH_0", last);  // sealed by the teammate's transport
  const auto seen = [&] {
    const auto& c = receiver.auth_counts();
    return got.size() + c.unauthenticated + c.replayed;
  };
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (seen() < 6 && std::chrono::steady_clock::now() < give_up) receiver.Run(receiver.Now() + SimTime::Millis(20));
  EXPECT_EQ(got, (std::vector<std::pair<int, int>>{{1, 1}, {4, 1}}));
  EXPECT_EQ(receiver.auth_counts().unauthenticated, 3u);
  EXPECT_EQ(receiver.auth_counts().replayed, 1u);
  EXPECT_EQ(receiver.ReceiveCounts().duplicates, 0u);  // repeats are told after the tag
  // What the teammate published carries the 34-byte trailer; its observer saw the message alone.
  EXPECT_EQ(teammate.PublishedBytes(), 3 * sealed.size() + Encode(untagged).size() + Encode(last).size() + 34);
}

// Held channels keep at most their bound (a message's bytes and 64 bytes of bookkeeping each);
// what arrives past it is counted and dropped, and what was kept is handled once a handler
// subscribes. The test waits for the count of dropped messages, then for the kept ones.
TEST_F(LcmTransportTest, HeldChannelsKeepAtMostTheirBoundAndCountTheRest) {
  match_t m{};
  const std::size_t charge = Encode(m).size() + 64;
  LcmTransport t(Url(7715), 1.0);
  t.HoldUntilSubscribed({"DVPR_MATCH_0"}, 3 * charge);
  LcmTransport other(Url(7715), 1.0);
  for (std::int32_t f = 0; f < 5; ++f) {
    m.query_frame = f;
    other.Publish("DVPR_MATCH_0", m);
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (t.auth_counts().held_dropped < 2 && std::chrono::steady_clock::now() < give_up) t.Run(t.Now() + SimTime::Millis(20));
  EXPECT_EQ(t.auth_counts().held_dropped, 2u);
  EXPECT_EQ(t.auth_counts().held_bytes_peak, 3 * charge);
  std::vector<std::int32_t> frames;
  Subscription sub = t.Subscribe<match_t>("DVPR_MATCH_0", [&](const match_t& x) { frames.push_back(x.query_frame); });
  while (frames.size() < 3 && std::chrono::steady_clock::now() < give_up) t.Run(t.Now() + SimTime::Millis(20));
  EXPECT_EQ(frames, (std::vector<std::int32_t>{0, 1, 2}));
}

}  // namespace
}  // namespace dvpr

// Store-and-forward on the radio's hand-worked chain (tests/net_models/network/test_radio_chain.cpp):
// robots 0, 1, 2 at 0, 150 and 300 m on a line, a 200 m range, 1 Mbit/s radios with 2 ms of
// processing per hop, shortest_path routing. One hop of the 505-byte payload (a 547-byte frame)
// takes 6 376 500 ns. Robot 3 is far away (1000 m) until it drives to 450 m at `arrives`.
//
// With store_and_forward, robot 0 keeps its message for robot 3 and asks its routing again every
// 100 ms, at 0.1 s, 0.2 s, ...; the first retry at or after robot 3's arrival sends it along the
// three hops: delivered at that retry + 3 x 6 376 500 ns.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "net_models/medium/radio_link.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/range_propagation.h"
#include "net_models/routing/shortest_path_routing.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

constexpr std::int64_t kHopNs = 6'376'500;

// Robots 0..2 fixed on the line; robot 3 at 1000 m before `arrives`, at 450 m from then on.
class ArrivingFourth final : public MobilityModel {
 public:
  explicit ArrivingFourth(SimTime arrives) : arrives_(arrives) {}

 private:
  int DoNodes() const override { return 4; }
  Position DoPositionOf(NodeId node, SimTime at) const override {
    if (node.value < 3) return Position{150.0 * node.value, 0, 0};
    return Position{at < arrives_ ? 1000.0 : 450.0, 0, 0};
  }
  std::string_view DoName() const override { return "arriving"; }
  SimTime arrives_;
};

// Robots 0..2 fixed on the line; robot 3 at 450 m in [0.3 s, 0.4 s) and from 0.6 s on, at
// 1000 m otherwise: the route to it appears, goes while a copy is on its way, and comes back.
class ComingAndGoingFourth final : public MobilityModel {
 private:
  int DoNodes() const override { return 4; }
  Position DoPositionOf(NodeId node, SimTime at) const override {
    if (node.value < 3) return Position{150.0 * node.value, 0, 0};
    const bool near = (SimTime::Millis(300) <= at && at < SimTime::Millis(400)) || SimTime::Millis(600) <= at;
    return Position{near ? 450.0 : 1000.0, 0, 0};
  }
  std::string_view DoName() const override { return "coming_and_going"; }
};

struct Team {
  Team(SimTime arrives, DisconnectedParams disconnected)
      : Team(std::make_unique<ArrivingFourth>(arrives), SimTime::Millis(2), disconnected) {}
  // latency: each hop's processing delay.
  Team(std::unique_ptr<MobilityModel> mobility, SimTime latency, DisconnectedParams disconnected)
      : net(sim, 4, Stack(std::move(mobility), latency, disconnected)) {
    channel = net.InternChannel("ALL");
    type = net.InternType("dvpr.test_t");
  }
  static NetworkStack Stack(std::unique_ptr<MobilityModel> mobility, SimTime latency, DisconnectedParams disconnected) {
    NetworkStack s;
    s.mobility = std::move(mobility);
    s.propagation = std::make_unique<RangePropagation>(*s.mobility, 200.0);
    s.access = std::make_unique<RadioLink>(RadioLinkParams{DataRate::Mbps(1), latency, 100}, 4);
    s.next_hop = std::make_unique<ShortestPathNextHop>(*s.propagation, 4);
    s.disconnected = disconnected;
    return s;
  }
  void ToThree(int messages = 1) {
    const NodeId three[] = {NodeId(3)};
    for (int i = 0; i < messages; ++i) {
      net.SendTo(NodeId(0), three, channel, type, std::vector<std::uint8_t>(505, 1));
    }
  }
  std::uint64_t Dropped(DropReason reason) const { return net.Routes().dropped[static_cast<std::size_t>(reason)]; }
  Simulator sim;
  Network net;
  testing_support::CopyLog log;
  ObserverSubscription subscription = net.Subscribe(log);
  ChannelId channel{};
  MessageTypeId type{};
};

DisconnectedParams StoreAndForward(Bytes hold_bytes = Bytes(10'000'000), SimTime hold_time = SimTime::Seconds(60)) {
  return DisconnectedParams{.kind = DisconnectedKind::kStoreAndForward, .hold_bytes = hold_bytes, .hold_time = hold_time};
}

TEST(StoreAndForward, HeldUntilTheFirstRetryAfterTheRouteAppears) {
  // Robot 3 arrives at 1.05 s; the retries at 0.1 .. 1.0 s find no route, the one at 1.1 s does.
  Team t(SimTime::Millis(1050), StoreAndForward());
  t.ToThree();
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>3 delivered at " + std::to_string(1'100'000'000 + 3 * kHopNs) + "ns"}));
  EXPECT_EQ(t.log.delivered_hops, (std::vector<int>{3}));
  // The send at 0 s put nothing on the air (its report says 0 bytes); then one transmission
  // each, robot 0's at 1.1 s.
  EXPECT_EQ(t.log.senders, (std::vector<int>{0, 0, 1, 2}));
  EXPECT_EQ(t.net.Routes().held, 1u);                     // taken once, kept through ten retries
  EXPECT_EQ(t.net.Sender(NodeId(0)).relay_transmissions, 0u);  // its own message, sent late
  EXPECT_EQ(t.net.Sender(NodeId(1)).relay_transmissions, 1u);
  EXPECT_EQ(t.net.Sender(NodeId(2)).relay_bytes, 547);
  EXPECT_EQ(t.net.Routes().dropped, (std::array<std::uint64_t, kDropReasons>{}));
}

TEST(StoreAndForward, ACopyHeldAtTwoRobotsThroughSeveralRetriesCountsOnce) {
  // 60 ms of processing per hop: one hop takes 4 376 000 + 60 000 000 + 500 = 64 376 500 ns, so
  // a copy sent down the chain at a retry reaches robot 2 in the next 100 ms window. Robot 0
  // holds its message from 0 s; the retries at 0.1 and 0.2 s find no route, the one at 0.3 s
  // does (robot 3 is near in that window). The copy reaches robot 1 at 364 376 500 ns and
  // robot 2 at 428 753 000 ns, in the window of 0.4 s, when robot 3 is far again: robot 2 holds
  // it; its retry at 0.5 s finds no route, the one at 0.6 s sends it, delivered at
  // 600 000 000 + 64 376 500 = 664 376 500 ns after 3 transmissions. One copy, held by two
  // robots through three retries that kept it: held_copies 1 (it counted 2, once per robot).
  Team t(std::make_unique<ComingAndGoingFourth>(), SimTime::Millis(60), StoreAndForward());
  t.ToThree();
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>3 delivered at 664376500ns"}));
  EXPECT_EQ(t.log.delivered_hops, (std::vector<int>{3}));
  EXPECT_EQ(t.net.Routes().held, 1u);
  EXPECT_EQ(t.net.Sender(NodeId(2)).relay_transmissions, 1u);  // robot 2 sent it on once, at 0.6 s
  EXPECT_EQ(t.net.Routes().dropped, (std::array<std::uint64_t, kDropReasons>{}));
}

TEST(StoreAndForward, ARetryAtTheArrivalInstantSendsAtOnce) {
  // The graph of the window starting at 0.3 s already places robot 3 at 450 m.
  Team t(SimTime::Millis(300), StoreAndForward());
  t.ToThree();
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>3 delivered at " + std::to_string(300'000'000 + 3 * kHopNs) + "ns"}));
}

TEST(StoreAndForward, WithDropTheCopyIsLostAsUnreachable) {
  Team t(SimTime::Millis(1050), DisconnectedParams{});
  t.ToThree();
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>3 at 0ns: no_route"}));
  EXPECT_EQ(t.Dropped(DropReason::kNoRoute), 1u);
  EXPECT_EQ(t.net.Routes().held, 0u);
}

TEST(StoreAndForward, ACopyHeldHoldTimeExpiresAtThatRetry) {
  // Robot 3 never comes; held from 0 s for 0.5 s: the retry at 0.5 s drops it.
  Team t(SimTime::Max(), StoreAndForward(Bytes(10'000'000), SimTime::Millis(500)));
  t.ToThree();
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>3 at 500000000ns: expired"}));
  EXPECT_EQ(t.Dropped(DropReason::kExpired), 1u);
  EXPECT_EQ(t.net.Counters(NodeId(0), NodeId(3)).dropped, 1u);
  EXPECT_EQ(t.log.senders, (std::vector<int>{0}));  // the send's report (0 bytes); the retries sent nothing
  EXPECT_EQ(t.net.Sender(NodeId(0)).medium_bytes, 0);  // nothing went on the air
}

TEST(StoreAndForward, NothingIsHeldOrRetriedPastTheHoldHorizon) {
  // Robot 3 never comes; hold_time 100000 h, the horizon (the mission's end) at 0.25 s. The
  // retries at 0.1 and 0.2 s keep the copy; the one at 0.3 s, past the horizon, finds no way and
  // drops it as expired: the run ends there (it retried every 100 ms for 100000 h before). A
  // message sent after the horizon is not held at all: no_route at once, as with drop.
  Team t(SimTime::Max(), StoreAndForward(Bytes(10'000'000), SimTime::Seconds(360000000.0)));
  t.net.SetHoldHorizon(SimTime::Millis(250));
  t.ToThree();
  t.sim.ScheduleAt(SimTime::Millis(320), [&] { t.ToThree(); });
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>3 at 300000000ns: expired", "0>3 at 320000000ns: no_route"}));
  EXPECT_EQ(t.sim.Now(), SimTime::Millis(320));  // the last event: nothing scheduled after it
  EXPECT_EQ(t.Dropped(DropReason::kExpired), 1u);
  EXPECT_EQ(t.Dropped(DropReason::kNoRoute), 1u);
  EXPECT_EQ(t.net.Routes().held, 1u);
}

TEST(StoreAndForward, TheBufferHoldsWhatFitsTheRestIsDroppedBufferFull) {
  // Each held copy takes its message's 547 wire bytes: 1093 B hold one, 1094 B two.
  Team one(SimTime::Millis(1050), StoreAndForward(Bytes(1093)));
  one.ToThree(2);
  one.sim.Run();
  EXPECT_EQ(one.log.lines, (std::vector<std::string>{"0>3 at 0ns: buffer_full",
                                                     "0>3 delivered at " + std::to_string(1'100'000'000 + 3 * kHopNs) + "ns"}));
  EXPECT_EQ(one.Dropped(DropReason::kBufferFull), 1u);

  Team two(SimTime::Millis(1050), StoreAndForward(Bytes(1094)));
  two.ToThree(2);
  two.sim.Run();
  EXPECT_EQ(two.Dropped(DropReason::kBufferFull), 0u);
  EXPECT_EQ(two.net.Routes().delivered, 2u);
  // Both leave robot 0 at 1.1 s, one after the other: the second frame waits for the first
  // (4.376 ms on the air) at every hop.
  EXPECT_EQ(two.log.lines.back(), "0>3 delivered at " + std::to_string(1'100'000'000 + 3 * kHopNs + 4'376'000) + "ns");
}

TEST(StoreAndForward, BadParametersAreRefusedNamingTheField) {
  const auto error = [](DisconnectedParams d) {
    try {
      d.Validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(StoreAndForward(Bytes(0))), "hold_bytes: must be in [1B, 1024GiB], got 0B");
  EXPECT_EQ(error(StoreAndForward(Bytes(10), SimTime::Zero())).rfind("hold_time: must be in (0s, ", 0), 0u);
  EXPECT_EQ(error(StoreAndForward()), "");
}

}  // namespace
}  // namespace dvpr

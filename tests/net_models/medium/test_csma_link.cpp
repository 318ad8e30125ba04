// csma against hand-worked timelines of ns-3's CsmaNetDevice (csma_link.h). The numbers: a
// 544-byte query_t on "DVPR_QUERY_3" is one 611-byte Ethernet frame (test_wire_format.cpp), at
// 10 Mbit/s 611 x 8 / 10^7 s = 488.8 us on the bus; the interframe gap is 96 bits, 9.6 us.
#include "net_models/medium/csma_link.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "net_models/helper/link_factory.h"
#include "net_models/network/network.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

constexpr std::int64_t kQueryFrameNs = 488800;  // 611 B at 10 Mbit/s

struct Bus {
  // propagation: the network's (null: the full mesh).
  explicit Bus(int nodes, SimTime delay, int queue = 100, std::unique_ptr<PropagationModel> propagation = nullptr) {
    auto link = std::make_unique<CsmaLink>(CsmaParams{DataRate::Mbps(10), delay, queue}, nodes, 1);
    csma = link.get();
    NetworkStack stack;
    stack.access = std::move(link);
    stack.propagation = std::move(propagation);
    net = std::make_unique<Network>(sim, nodes, std::move(stack), LinkWire(WireParams{}, LinkFraming::kEthernetDix));
    subscription = net->Subscribe(log);
    channel = net->InternChannel("DVPR_QUERY_3");
    type = net->InternType("dvpr.query_t");
  }
  // A 544-byte query from src to dst at `at`.
  void QueryAt(SimTime at, int src, int dst, std::int64_t bytes = 544) {
    sim.ScheduleAt(at, [this, src, dst, bytes] {
      const NodeId to[] = {NodeId(dst)};
      net->SendTo(NodeId(src), to, channel, type, std::vector<std::uint8_t>(static_cast<std::size_t>(bytes), 7));
    });
  }
  Simulator sim;
  CsmaLink* csma = nullptr;
  std::unique_ptr<Network> net;
  testing_support::CopyLog log;
  ObserverSubscription subscription;
  ChannelId channel{};
  MessageTypeId type{};
};

TEST(CsmaLink, TheSecondOfTwoStationsBacksOffExactlyTheDrawnSlots) {
  // Robots 0 and 1 send at 0 ns, 0 first: 0 finds the bus idle and holds it 488.8 us, then it
  // propagates 10 us: idle again at 498.8 us. Robot 1 finds it busy and backs off; the test draws
  // the largest count ns-3 can give at each retry (bound 2^k - 1, truncated: 1 at k = 1, else
  // 2^k - 2): 1, 2, 6, 14, 30, 62, 126, 254 us - it looks at 1, 3, 9, 23, 53, 115, 241, 495 us,
  // busy each time - then 510 us, and at 1005 us it finds the bus idle. Its query arrives at
  // 1005 + 488.8 + 10 = 1503.8 us; robot 0's at 498.8 us.
  Bus bus(3, SimTime::Micros(10));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> bounds;
  bus.csma->SetSlotDraw([&](std::uint32_t lo, std::uint32_t hi) {
    bounds.emplace_back(lo, hi);
    return hi > 1 ? hi - 1 : 1;
  });
  bus.QueryAt(SimTime::Zero(), 0, 2);
  bus.QueryAt(SimTime::Zero(), 1, 2);
  bus.sim.Run();
  EXPECT_EQ(bus.log.lines, (std::vector<std::string>{"0>2 delivered at 498800ns", "1>2 delivered at 1503800ns"}));
  EXPECT_EQ(bounds, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{
                        {1, 1}, {1, 3}, {1, 7}, {1, 15}, {1, 31}, {1, 63}, {1, 127}, {1, 255}, {1, 511}}));
  const auto mac = bus.net->link().Mac();
  ASSERT_EQ(mac.size(), 3u);
  EXPECT_EQ(mac[0].backoffs, 0u);
  EXPECT_EQ(mac[1].backoffs, 9u);
  EXPECT_EQ(mac[1].attempts, 1u);
  EXPECT_EQ(mac[1].airtime, SimTime::Nanos(kQueryFrameNs));
  // The bus was busy for two frames and their propagation.
  EXPECT_EQ(bus.net->link().MediumBusy(), SimTime::Nanos(2 * (kQueryFrameNs + 10000)));
}

TEST(CsmaLink, TheGapAfterATransmissionDelaysOnlyItsSender) {
  // No channel delay: the bus is idle the moment a frame ends. Alone, robot 0's second query
  // waits the 9.6 us gap after its first: it starts at 498.4 us and arrives at 987.2 us.
  {
    Bus bus(3, SimTime::Zero());
    bus.QueryAt(SimTime::Zero(), 0, 2);
    bus.QueryAt(SimTime::Zero(), 0, 2);
    bus.sim.Run();
    EXPECT_EQ(bus.log.lines,
              (std::vector<std::string>{"0>2 delivered at 488800ns", "0>2 delivered at 987200ns"}));
  }
  // Robot 1 sends at 489 us, inside robot 0's gap: the bus is idle and it transmits at once
  // (arriving at 977.8 us); robot 0 ends its gap at 498.4 us to a busy bus and backs off (the
  // draws: 1, 2, 6, 14, 30, 62, 126, 254 us, 495 in all, until it looks at 993.4 us, the bus
  // idle since 977.8 us): its second query arrives at 993.4 + 488.8 = 1482.2 us.
  Bus bus(3, SimTime::Zero());
  bus.csma->SetSlotDraw([](std::uint32_t, std::uint32_t hi) { return hi > 1 ? hi - 1 : 1; });
  bus.QueryAt(SimTime::Zero(), 0, 2);
  bus.QueryAt(SimTime::Zero(), 0, 2);
  bus.QueryAt(SimTime::Micros(489), 1, 2);
  bus.sim.Run();
  EXPECT_EQ(bus.log.lines, (std::vector<std::string>{"0>2 delivered at 488800ns", "1>2 delivered at 977800ns",
                                                     "0>2 delivered at 1482200ns"}));
  EXPECT_EQ(bus.net->link().Mac()[1].backoffs, 0u);
  EXPECT_EQ(bus.net->link().Mac()[0].backoffs, 8u);
}

TEST(CsmaLink, AFrameThatFindsTheBusBusy1000TimesIsDropped) {
  // At 1 us per backoff (the test's draws) robot 1 looks 1000 times in the 1.2144 ms that robot
  // 0's 1518-byte frame holds the bus; at its 1001st look, at 1000 us, it gives the frame up.
  // Robot 0's 1470 bytes on "DVPR_QUERY_3": IP data 8 + 8 + 12 + 1 + 1470 = 1499 = 1480 + 19, two
  // frames: 1518 bytes and 19 + 20 = 39 padded to 46, + 18 = 64 bytes.
  Bus bus(3, SimTime::Zero());
  bus.csma->SetSlotDraw([](std::uint32_t lo, std::uint32_t) { return lo; });
  bus.QueryAt(SimTime::Zero(), 0, 2, 1470);  // two frames: 1518 + 64 bytes
  bus.QueryAt(SimTime::Zero(), 1, 2);
  bus.sim.Run();
  EXPECT_EQ(bus.log.lines, (std::vector<std::string>{"1>2 at 1000000ns: retry_limit",
                                                     // 1518 B (1214.4 us), gap 9.6 us, 64 B (51.2 us)
                                                     "0>2 delivered at 1275200ns"}));
  EXPECT_EQ(bus.net->link().Mac()[1].dropped_retry_limit, 1u);
  EXPECT_EQ(bus.net->link().Mac()[1].backoffs, 1000u);
  EXPECT_EQ(bus.net->Routes().dropped[static_cast<std::size_t>(DropReason::kRetryLimit)], 1u);
}

// A fixed draw outside ns-3's [min, max) - no slot at all, or one past the window - is a bug in
// the test that fixed it, not a backoff: refused at the draw.
TEST(CsmaLink, ADrawOutsideTheWindowIsRefused) {
  for (const std::uint32_t slots : {0u, 2u}) {
    Bus bus(2, SimTime::Zero());
    bus.csma->SetSlotDraw([slots](std::uint32_t, std::uint32_t) { return slots; });  // the first window is [1, 1]
    bus.QueryAt(SimTime::Zero(), 0, 1);
    bus.QueryAt(SimTime::Zero(), 1, 0);
    EXPECT_THROW(bus.sim.Run(), std::logic_error) << slots;
  }
}

TEST(CsmaLink, AFullQueueRefusesAFrameAtOnce) {
  // One packet of queue: the first query goes on the bus, the second waits, the third is refused
  // when it is sent (the frame on the bus is not in the queue, as in ns-3).
  Bus bus(2, SimTime::Zero(), 1);
  for (int i = 0; i < 3; ++i) bus.QueryAt(SimTime::Zero(), 0, 1);
  bus.sim.Run();
  EXPECT_EQ(bus.log.lines, (std::vector<std::string>{"0>1 at 0ns: queue_full", "0>1 delivered at 488800ns",
                                                     "0>1 delivered at 987200ns"}));
  EXPECT_EQ(bus.net->link().Mac()[0].dropped_queue_full, 1u);
}

TEST(CsmaLink, ABroadcastIsOneTransmissionThatEveryoneReceives) {
  Bus bus(4, SimTime::Micros(5));
  bus.sim.ScheduleAt(SimTime::Zero(), [&] {
    const NodeId all[] = {NodeId(1), NodeId(2), NodeId(3)};
    bus.net->SendTo(NodeId(0), all, bus.channel, bus.type, std::vector<std::uint8_t>(544, 1));
  });
  bus.sim.Run();
  EXPECT_EQ(bus.log.lines, (std::vector<std::string>{"0>1 delivered at 493800ns", "0>2 delivered at 493800ns",
                                                     "0>3 delivered at 493800ns"}));
  EXPECT_EQ(bus.net->Sender(NodeId(0)).transmissions, 1u);
  EXPECT_EQ(bus.net->Sender(NodeId(0)).medium_bytes, 611);
}

// Node 3 never hears node 0; node 2 hears it 1 us later than the bus delivers.
class TwoDeafOneLate final : public PropagationModel {
  void DoReach(NodeId, std::span<const NodeId> receivers, SimTime, std::span<Reception> out) override {
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      if (receivers[i].value == 3) out[i].reaches = false;
      if (receivers[i].value == 2) out[i].delay = SimTime::Micros(1);
    }
  }
  std::string_view DoName() const override { return "two_deaf_one_late"; }
};

// The bus asks the network's channel who hears each frame when its last bit is on the bus (the
// full mesh above: everyone). 611 B at 10 Mbit/s end at 488.8 us, delivered 5 us later.
TEST(CsmaLink, AStationTheChannelDoesNotLetHearLosesTheMessageOutOfRange) {
  Bus bus(4, SimTime::Micros(5), 100, std::make_unique<TwoDeafOneLate>());
  bus.sim.ScheduleAt(SimTime::Zero(), [&] {
    const NodeId all[] = {NodeId(1), NodeId(2), NodeId(3)};
    bus.net->SendTo(NodeId(0), all, bus.channel, bus.type, std::vector<std::uint8_t>(544, 1));
  });
  bus.sim.Run();
  // In time order: the loss is known when the frame's last bit is on the bus.
  EXPECT_EQ(bus.log.lines, (std::vector<std::string>{"0>3 at 488800ns: out_of_range", "0>1 delivered at 493800ns",
                                                     "0>2 delivered at 494800ns"}));
  EXPECT_EQ(bus.net->Sender(NodeId(0)).medium_bytes, 611);
}

TEST(CsmaLink, IsMadeFromTheNetworkSectionAndRefusesALossModel) {
  NetworkModelParams p;
  p.model = ParseLinkModelKind("csma");
  EXPECT_EQ(MakeLinkModel(p, 3, 1)->Name(), "csma");
  EXPECT_EQ(WireOf(p).link_framing, Bytes(18));
  EXPECT_EQ(WireOf(p).link_min_payload, Bytes(46));
  p.loss.model = LossModelKind::kBernoulli;
  try {
    p.Validate(3);
    FAIL() << "a loss model on csma was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "loss: a loss model needs a medium access that decides at send time, not model csma");
  }
}

}  // namespace
}  // namespace dvpr

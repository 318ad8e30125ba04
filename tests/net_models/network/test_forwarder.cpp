// How copies travel (net_models/network/forwarder.h), against a stand-in for the network that records what
// the forwarder tells it: a relay's own transmission, the hops and the arrival worked out by hand,
// one reference released for every copy taken, and store-and-forward's hold, retries and expiry.
//
// Three robots on a line at 0, 150 m and `far` m, range 200 m, shortest-path next hops, the radio
// with its defaults (10 Mbit/s, 2 ms per hop). A 100-byte frame is 80 us on the air; 150 m add
// 500 ns (150 / c = 500.3 ns, to the ns).
#include "net_models/network/forwarder.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "net_models/medium/radio_link.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/propagation/propagation_channel.h"
#include "net_models/propagation/range_propagation.h"
#include "net_models/routing/shortest_path_routing.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

struct Host final : ForwarderHost {
  explicit Host(Simulator& s) : sim(s) {}
  void Deliver(std::uint32_t slot, const PendingCopy& c) override {
    log.push_back("copy " + std::to_string(c.copy) + " at " + std::to_string(c.dst.value) + " after " +
                  std::to_string(c.hops) + " hops at " + std::to_string(sim.Now().ns()) + "ns");
    Release(slot);
  }
  void DropCopy(std::uint32_t, const PendingCopy& c, DropReason reason) override {
    log.push_back("copy " + std::to_string(c.copy) + " dropped " + std::string(ToString(reason)) + " at " +
                  std::to_string(sim.Now().ns()) + "ns");
  }
  void Release(std::uint32_t slot) override { ++released[slot]; }
  void AppendFrames(std::uint32_t, std::vector<Bytes>& frames) const override { frames.push_back(Bytes(100)); }
  void SentOn(std::uint32_t, NodeId sender, const LinkModel::MediumUse& use) override {
    log.push_back(std::to_string(sender.value) + " sent on " + std::to_string(use.transmissions) + " at " +
                  std::to_string(sim.Now().ns()) + "ns");
  }
  std::int64_t WireBytes(std::uint32_t) const override { return 100; }
  void FirstHeld() override { ++held; }

  Simulator& sim;
  std::vector<std::string> log;
  std::map<std::uint32_t, int> released;
  int held = 0;
};

struct Line {
  explicit Line(double far, DisconnectedParams disconnected = {}) : host(sim), availability(3) {
    stack.mobility = std::make_unique<FixedMobility>(
        std::vector<Position>{Position{0, 0, 0}, Position{150, 0, 0}, Position{far, 0, 0}});
    stack.propagation = std::make_unique<RangePropagation>(*stack.mobility, 200.0);
    stack.access = std::make_unique<RadioLink>(RadioLinkParams{}, 3);
    stack.next_hop = std::make_unique<ShortestPathNextHop>(*stack.propagation, 3);
    stack.disconnected = disconnected;
    stack.CompleteDefaults(3);
    channel = std::make_unique<PropagationChannel>(*stack.propagation);
    forwarder = std::make_unique<Forwarder>(sim, 3, stack, availability, host);
    forwarder->Bind(*channel);
  }
  // Robot 0 sends one 100-byte frame to dsts now, as message slot 0, copies numbered from 10.
  std::vector<DropReason> Send(std::vector<NodeId> dsts) {
    const Bytes frames[] = {Bytes(100)};
    forwarder->Transmit(NodeId(0), dsts, frames, /*routed=*/true);
    forwarder->Open(0);
    std::vector<DropReason> taken;
    for (std::size_t i = 0; i < dsts.size(); ++i) taken.push_back(forwarder->Take(0, i, NodeId(0), dsts[i], 10 + i));
    forwarder->Launch(0);
    return taken;
  }

  Simulator sim;
  Host host;
  Availability availability;
  NetworkStack stack;
  std::unique_ptr<PropagationChannel> channel;
  std::unique_ptr<Forwarder> forwarder;
};

// 0 -> 1 arrives at 80 us + 2 ms + 500 ns = 2 080 500 ns; robot 1 sends it on at once, its frame
// ending 80 us later and arriving 2 ms + 500 ns after that: 4 161 000 ns, after 2 hops.
TEST(Forwarder, ACopyForARobotOutOfRangeGoesOnFromTheRobotBetween) {
  Line line(300);
  EXPECT_EQ(line.Send({NodeId(2)}), std::vector<DropReason>{DropReason::kNone});
  line.sim.Run();
  EXPECT_EQ(line.host.log, (std::vector<std::string>{"1 sent on 1 at 2080500ns", "copy 10 at 2 after 2 hops at 4161000ns"}));
  EXPECT_EQ(line.host.released[0], 1);
}

// Both copies go to robot 1 in one transmission; there the one for 1 is delivered first, then the
// one for 2 goes on. One reference released per copy taken, the last after the last arrival.
TEST(Forwarder, EveryCopyTakenReleasesOneReference) {
  Line line(300);
  EXPECT_EQ(line.Send({NodeId(1), NodeId(2)}), (std::vector<DropReason>{DropReason::kNone, DropReason::kNone}));
  line.sim.Run();
  EXPECT_EQ(line.host.log, (std::vector<std::string>{"copy 10 at 1 after 1 hops at 2080500ns", "1 sent on 1 at 2080500ns",
                                                     "copy 11 at 2 after 2 hops at 4161000ns"}));
  EXPECT_EQ(line.host.released[0], 2);
}

// Robot 2 is out of everyone's reach: without store-and-forward the copy is dropped at its
// sender, no way (the forwarder releases nothing: the network never took a reference).
TEST(Forwarder, ACopyWithoutAWayIsDroppedAtItsSender) {
  Line line(1000);
  EXPECT_EQ(line.Send({NodeId(2)}), std::vector<DropReason>{DropReason::kNoRoute});
  line.sim.Run();
  EXPECT_TRUE(line.host.log.empty());
  EXPECT_EQ(line.host.released[0], 0);
}

// With store-and-forward, retry every 100 ms and a hold time of 250 ms, robot 0 holds it (counted
// held once), asks again at 100 and 200 ms (held 100 and 200 ms: offered to the routing, which
// still finds no way, so nothing goes on the air and it is held again) and at 300 ms (held
// 300 ms >= 250 ms) drops it expired, releasing its reference.
TEST(Forwarder, AHeldCopyIsRetriedUntilItsHoldTimeAndThenExpires) {
  DisconnectedParams saf;
  saf.kind = DisconnectedKind::kStoreAndForward;
  saf.hold_time = SimTime::Millis(250);
  saf.retry = SimTime::Millis(100);
  Line line(1000, saf);
  EXPECT_EQ(line.Send({NodeId(2)}), std::vector<DropReason>{DropReason::kNone});
  line.sim.Run();
  EXPECT_EQ(line.host.log, (std::vector<std::string>{"0 sent on 0 at 100000000ns", "0 sent on 0 at 200000000ns",
                                                     "copy 10 dropped expired at 300000000ns"}));
  EXPECT_EQ(line.host.held, 1);
  EXPECT_EQ(line.host.released[0], 1);
}

}  // namespace
}  // namespace dvpr

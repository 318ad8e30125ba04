#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "net_models/helper/link_factory.h"
#include "net_models/medium/ideal_link.h"
#include "net_models/medium/point_to_point_link.h"
#include "net_models/medium/radio_link.h"
#include "net_models/medium/shared_medium_link.h"

namespace dvpr {
namespace {

// 547-byte frames at 1 Mbit/s take 4376 bits / 1e6 bit/s = 4.376 ms each.
constexpr SimTime kTx547 = SimTime::Micros(4376);
constexpr SimTime kLatency = SimTime::Millis(5);

class LinkModelTest : public ::testing::Test {
 protected:
  std::vector<Bytes> frame547{Bytes(547)};
  LinkModel::MediumUse used;  // summed over the Sends of a test

  std::vector<LinkDelivery> Send(LinkModel& link, int src, std::vector<NodeId> dsts, SimTime now,
                                 const std::vector<Bytes>& frames) {
    std::vector<LinkDelivery> out(dsts.size());
    const LinkModel::MediumUse use = link.Transmit(LinkTransmission{NodeId(src), dsts, now, frames}, out);
    used.transmissions += use.transmissions;
    used.bytes += use.bytes;
    return out;
  }
  static PointToPointParams Mbit1(int queue = 100) {
    return PointToPointParams{DataRate::Mbps(1), kLatency, queue, {}};
  }
};

TEST_F(LinkModelTest, PointToPointFrameArrivesAfter9376Microseconds) {
  PointToPointLink link(Mbit1(), 2);
  const auto out = Send(link, 0, {NodeId(1)}, SimTime::Zero(), frame547);
  EXPECT_EQ(out[0].drop, DropReason::kNone);
  EXPECT_EQ(out[0].arrival, SimTime::Micros(9376));  // 4.376 ms + 5 ms, as ns-3.37
}

TEST_F(LinkModelTest, PointToPointSecondPacketWaitsForTheFirst) {
  PointToPointLink link(Mbit1(), 2);
  const auto a = Send(link, 0, {NodeId(1)}, SimTime::Zero(), frame547);
  const auto b = Send(link, 0, {NodeId(1)}, SimTime::Zero(), frame547);
  EXPECT_EQ(a[0].arrival, SimTime::Micros(9376));
  EXPECT_EQ(b[0].arrival, SimTime::Micros(4376 + 4376 + 5000));
  // The reverse direction is a separate (full-duplex) link: no wait.
  EXPECT_EQ(Send(link, 1, {NodeId(0)}, SimTime::Zero(), frame547)[0].arrival, SimTime::Micros(9376));
  // Once the link is idle again, no wait either.
  EXPECT_EQ(Send(link, 0, {NodeId(1)}, SimTime::Millis(20), frame547)[0].arrival,
            SimTime::Millis(20) + SimTime::Micros(9376));
}

TEST_F(LinkModelTest, PointToPointFullDropTailQueueDrops) {
  // Queue of 2 waiting frames: at t = 0 the first frame goes on the wire, two
  // wait, the 4th and 5th find the queue full.
  PointToPointLink link(Mbit1(2), 2);
  std::vector<DropReason> drops;
  for (int i = 0; i < 5; ++i) drops.push_back(Send(link, 0, {NodeId(1)}, SimTime::Zero(), frame547)[0].drop);
  EXPECT_EQ(drops, (std::vector<DropReason>{DropReason::kNone, DropReason::kNone, DropReason::kNone,
                                            DropReason::kQueueFull, DropReason::kQueueFull}));
  // At 4.376 ms the second frame starts transmitting and leaves the queue:
  // one place is free again, so one more frame is accepted, the next is not.
  const auto late = Send(link, 0, {NodeId(1)}, kTx547, frame547);
  EXPECT_EQ(late[0].drop, DropReason::kNone);
  EXPECT_EQ(late[0].arrival, kTx547 * 4 + kLatency);  // behind frames 1-3
  EXPECT_EQ(Send(link, 0, {NodeId(1)}, kTx547, frame547)[0].drop, DropReason::kQueueFull);
  EXPECT_EQ(used.transmissions, 7u);       // every attempt is counted ...
  EXPECT_EQ(used.bytes, Bytes(547 * 4));  // ... but only accepted frames use the wire
}

TEST_F(LinkModelTest, PointToPointMultiFrameMessageArrivesWithItsLastFrame) {
  PointToPointLink link(Mbit1(), 2);
  const std::vector<Bytes> frames{Bytes(1502), Bytes(1502), Bytes(450)};
  // (1502 + 1502 + 450) x 8 = 27 632 bits = 27.632 ms at 1 Mbit/s, + 5 ms.
  EXPECT_EQ(Send(link, 0, {NodeId(1)}, SimTime::Zero(), frames)[0].arrival, SimTime::Micros(32632));
}

TEST_F(LinkModelTest, PointToPointMessageLargerThanTheQueueIsDropped) {
  PointToPointLink link(Mbit1(1), 2);
  // Frame 1 transmits, frame 2 waits, frame 3 finds the one-place queue full.
  const std::vector<Bytes> frames(3, Bytes(100));
  EXPECT_EQ(Send(link, 0, {NodeId(1)}, SimTime::Zero(), frames)[0].drop, DropReason::kQueueFull);
}

TEST_F(LinkModelTest, PointToPointPerPairOverrides) {
  PointToPointParams p = Mbit1();
  p.overrides.push_back({NodeId(0), NodeId(2), DataRate::Mbps(2), SimTime::Millis(1)});
  p.overrides.push_back({NodeId(2), NodeId(0), std::nullopt, SimTime::Millis(7)});
  PointToPointLink link(p, 3);
  // 0 -> 2: 2.188 ms + 1 ms. 2 -> 0: default rate, 4.376 + 7 ms. 0 -> 1: defaults.
  EXPECT_EQ(Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547)[0].arrival, SimTime::Micros(3188));
  EXPECT_EQ(Send(link, 2, {NodeId(0)}, SimTime::Zero(), frame547)[0].arrival, SimTime::Micros(11376));
  EXPECT_EQ(Send(link, 0, {NodeId(1)}, SimTime::Zero(), frame547)[0].arrival, SimTime::Micros(9376));
  EXPECT_EQ(link.RateOf(NodeId(0), NodeId(2)), DataRate::Mbps(2));
}

TEST_F(LinkModelTest, PointToPointBroadcastIsACopyPerLink) {
  PointToPointLink link(Mbit1(), 4);
  const auto out = Send(link, 0, {NodeId(1), NodeId(2), NodeId(3)}, SimTime::Zero(), frame547);
  for (const auto& d : out) EXPECT_EQ(d.arrival, SimTime::Micros(9376));  // separate links, in parallel
  EXPECT_EQ(used.transmissions, 3u);
  EXPECT_EQ(used.bytes, Bytes(3 * 547));
}

TEST_F(LinkModelTest, SharedMediumSerializesTwoSenders) {
  SharedMediumLink link(SharedMediumParams{DataRate::Mbps(1), kLatency, 100}, 3);
  const auto a = Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547);
  const auto b = Send(link, 1, {NodeId(2)}, SimTime::Zero(), frame547);
  EXPECT_EQ(a[0].arrival, SimTime::Micros(9376));
  EXPECT_EQ(b[0].arrival, SimTime::Micros(4376 + 4376 + 5000));  // waited for robot 0's transmission
}

TEST_F(LinkModelTest, SharedMediumBroadcastIsOneTransmission) {
  SharedMediumLink link(SharedMediumParams{DataRate::Mbps(1), kLatency, 100}, 4);
  const auto out = Send(link, 0, {NodeId(1), NodeId(2), NodeId(3)}, SimTime::Zero(), frame547);
  for (const auto& d : out) EXPECT_EQ(d.arrival, SimTime::Micros(9376));
  EXPECT_EQ(used.transmissions, 1u);
  EXPECT_EQ(used.bytes, Bytes(547));
  // The channel was busy for one frame time only: the next sender starts at 4.376 ms.
  EXPECT_EQ(Send(link, 3, {NodeId(0)}, SimTime::Zero(), frame547)[0].arrival, SimTime::Micros(13752));
}

TEST_F(LinkModelTest, SharedMediumQueueIsPerSender) {
  SharedMediumLink link(SharedMediumParams{DataRate::Mbps(1), kLatency, 1}, 3);
  EXPECT_EQ(Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kNone);  // on air
  EXPECT_EQ(Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kNone);  // waits
  EXPECT_EQ(Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kQueueFull);
  EXPECT_EQ(Send(link, 1, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kNone);  // own queue
}

// The radio: each robot its own transmitter (two senders at once do not wait for each other,
// unlike the shared medium above), a broadcast one transmission, the queue per robot.
TEST_F(LinkModelTest, RadioSendersDoNotWaitForEachOther) {
  RadioLink link(RadioLinkParams{DataRate::Mbps(1), kLatency, 100}, 3);
  const auto a = Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547);
  const auto b = Send(link, 1, {NodeId(2)}, SimTime::Zero(), frame547);
  EXPECT_EQ(a[0].arrival, SimTime::Micros(9376));  // 4.376 ms on the air + 5 ms
  EXPECT_EQ(b[0].arrival, SimTime::Micros(9376));
  // Robot 0's second message waits for its first: 2 x 4.376 + 5 ms.
  EXPECT_EQ(Send(link, 0, {NodeId(1)}, SimTime::Zero(), frame547)[0].arrival, SimTime::Micros(13752));
  // Later, with the radio idle again: 10 ms + 4.376 + 5.
  EXPECT_EQ(Send(link, 1, {NodeId(0)}, SimTime::Millis(10), frame547)[0].arrival, SimTime::Micros(19376));
}

TEST_F(LinkModelTest, RadioBroadcastIsOneTransmission) {
  RadioLink link(RadioLinkParams{DataRate::Mbps(1), kLatency, 100}, 4);
  const std::vector<Bytes> two{Bytes(547), Bytes(100)};  // 4.376 ms + 0.8 ms
  const auto out = Send(link, 0, {NodeId(1), NodeId(2), NodeId(3)}, SimTime::Zero(), two);
  for (const auto& d : out) EXPECT_EQ(d.arrival, SimTime::Micros(4376 + 800 + 5000));
  EXPECT_EQ(used.transmissions, 1u);
  EXPECT_EQ(used.bytes, Bytes(647));
}

TEST_F(LinkModelTest, RadioQueueIsPerRobotAndAFullOneDropsForEveryDestination) {
  RadioLink link(RadioLinkParams{DataRate::Mbps(1), kLatency, 1}, 3);
  EXPECT_EQ(Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kNone);  // on air
  EXPECT_EQ(Send(link, 0, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kNone);  // waits
  const auto full = Send(link, 0, {NodeId(1), NodeId(2)}, SimTime::Zero(), frame547);
  EXPECT_EQ(full[0].drop, DropReason::kQueueFull);
  EXPECT_EQ(full[1].drop, DropReason::kQueueFull);
  EXPECT_EQ(Send(link, 1, {NodeId(2)}, SimTime::Zero(), frame547)[0].drop, DropReason::kNone);  // own queue
}

TEST_F(LinkModelTest, IdealDeliversAtOnce) {
  IdealLink link;
  const auto out = Send(link, 0, {NodeId(1), NodeId(2)}, SimTime::Millis(3), frame547);
  for (const auto& d : out) {
    EXPECT_EQ(d.arrival, SimTime::Millis(3));
    EXPECT_EQ(d.drop, DropReason::kNone);
  }
  EXPECT_EQ(used.transmissions, 2u);  // a copy per destination, as point-to-point
  EXPECT_EQ(used.bytes, Bytes(2 * 547));
}

// Every bad value raises std::invalid_argument whose message holds `needle`.
void ExpectInvalid(const std::function<void()>& f, const std::string& needle) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected an error mentioning " << needle;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(LinkParams, BadValuesNameTheFieldAndTheValue) {
  NetworkModelParams p;
  p.bandwidth = DataRate::BitsPerSecond(0);
  ExpectInvalid([&] { p.Validate(3); }, "bandwidth: a data rate must be positive, got 0bps");
  p.bandwidth = DataRate::BitsPerSecond(-5);
  ExpectInvalid([&] { p.Validate(3); }, "bandwidth: a data rate must be positive, got -5bps");
  p = NetworkModelParams{};
  p.latency = SimTime::Nanos(-1);
  ExpectInvalid([&] { p.Validate(3); }, "latency: must not be negative, got -1ns");
  p = NetworkModelParams{};
  p.wire.mtu = Bytes(0);
  ExpectInvalid([&] { p.Validate(3); }, "mtu: too small: an IPv4 packet needs 20 header bytes plus at least 8 data bytes, got 0B");
  p = NetworkModelParams{};
  p.loss.model = LossModelKind::kBernoulli;
  p.loss.bernoulli.p = 1.5;
  ExpectInvalid([&] { p.Validate(3); }, "loss.p: a probability must lie in [0, 1], got 1.5");
  p.loss.bernoulli.p = -0.1;
  ExpectInvalid([&] { p.Validate(3); }, "loss.p: a probability must lie in [0, 1], got -0.1");
  p = NetworkModelParams{};
  p.loss.model = LossModelKind::kGilbertElliott;
  p.loss.gilbert_elliott.p_bad_to_good = 2;
  ExpectInvalid([&] { p.Validate(3); }, "loss.p_bad_to_good: a probability must lie in [0, 1], got 2");
  p = NetworkModelParams{};
  p.queue_packets = -1;
  ExpectInvalid([&] { p.Validate(3); }, "queue_packets: must not be negative, got -1");
  p = NetworkModelParams{};
  p.links.push_back({NodeId(0), NodeId(5), DataRate::Mbps(1), std::nullopt, std::nullopt});
  ExpectInvalid([&] { p.Validate(3); }, "links[0]: 0->5 is not a link between two of the 3 robots");
  p = NetworkModelParams{};
  p.model = LinkModelKind::kSharedMedium;
  p.links.push_back({NodeId(0), NodeId(1), DataRate::Mbps(1), std::nullopt, std::nullopt});
  ExpectInvalid([&] { p.Validate(3); }, "links[0]: bandwidth/latency overrides need model point_to_point");
  ExpectInvalid([] { ParseLinkModelKind("token_ring"); }, "unknown value 'token_ring' (expected one of: ideal, point_to_point, shared_medium, radio, csma, wifi)");
  ExpectInvalid([] { ParseLossModelKind("sometimes"); }, "unknown value 'sometimes' (expected one of: none, bernoulli, gilbert_elliott)");
  ExpectInvalid([] { PointToPointLink(PointToPointParams{DataRate(), kLatency, 1, {}}, 2); }, "rate: a data rate must be positive");
  ExpectInvalid([] { SharedMediumLink(SharedMediumParams{DataRate(), kLatency, 1}, 2); }, "rate: a data rate must be positive");
}

// Each range's boundary, one inside and one outside: 24 h = 86'400'000'000'000 ns, 1 Tbit/s =
// 1'000'000'000'000 bit/s, an IPv4 packet at most 65'535 bytes.
TEST(LinkParams, RangesAcceptTheirBoundsAndRefuseOnePast) {
  NetworkModelParams p;
  p.bandwidth = DataRate::Kbps(1);
  p.latency = SimTime::Nanos(86'400'000'000'000);
  p.queue_packets = 1 << 30;
  p.wire.mtu = Bytes(65'535);
  p.links.push_back({NodeId(0), NodeId(1), DataRate::Gbps(1000), SimTime::Nanos(86'400'000'000'000), std::nullopt});
  EXPECT_NO_THROW(p.Validate(3));
  p.bandwidth = DataRate::BitsPerSecond(999);
  ExpectInvalid([&] { p.Validate(3); }, "bandwidth: must be in [1kbps, 1000Gbps], got 999bps");
  p.bandwidth = DataRate::BitsPerSecond(1'000'000'000'001);
  ExpectInvalid([&] { p.Validate(3); }, "bandwidth: must be in [1kbps, 1000Gbps], got 1000000000001bps");
  p.bandwidth = DataRate::Mbps(1);
  p.latency = SimTime::Nanos(86'400'000'000'001);
  ExpectInvalid([&] { p.Validate(3); }, "latency: must be in [0ns, 24h], got 86400000000001ns");
  p.latency = SimTime::Zero();
  p.queue_packets = (1 << 30) + 1;
  ExpectInvalid([&] { p.Validate(3); }, "queue_packets: must be in [1, 1073741824], got 1073741825");
  p.queue_packets = 1;
  p.wire.mtu = Bytes(65'536);
  ExpectInvalid([&] { p.Validate(3); }, "mtu: must be in [28B, 65535B], got 64KiB");
  p.wire.mtu = Bytes(1500);
  p.links[0].latency = SimTime::Nanos(9'223'369'200'000'000'000);  // 2562047 h: the case
  ExpectInvalid([&] { p.Validate(3); }, "links[0].latency: must be in [0ns, 24h], got 2562047h");
  p.links[0].latency = std::nullopt;
  p.links[0].bandwidth = DataRate::BitsPerSecond(999);
  ExpectInvalid([&] { p.Validate(3); }, "links[0].bandwidth: must be in [1kbps, 1000Gbps], got 999bps");
}

// Loss is the channel's (MakeNetworkStack, reception_loss.h): the medium is the named one alone.
TEST(LinkFactory, BuildsTheNamedModel) {
  NetworkModelParams p;
  EXPECT_EQ(MakeLinkModel(p, 3, 1)->Name(), "point_to_point");
  p.model = ParseLinkModelKind("shared_medium");
  EXPECT_EQ(MakeLinkModel(p, 3, 1)->Name(), "shared_medium");
  p.model = ParseLinkModelKind("radio");
  EXPECT_EQ(MakeLinkModel(p, 3, 1)->Name(), "radio");
  p.model = ParseLinkModelKind("ideal");
  p.loss.model = ParseLossModelKind("bernoulli");
  p.loss.bernoulli.p = 0.1;
  EXPECT_EQ(MakeLinkModel(p, 3, 1)->Name(), "ideal");
}

TEST(LinkFactory, KindNamesAreTheOnesParsed) {
  EXPECT_EQ(ToString(LinkModelKind::kIdeal), "ideal");
  EXPECT_EQ(ToString(LinkModelKind::kPointToPoint), "point_to_point");
  EXPECT_EQ(ToString(LinkModelKind::kSharedMedium), "shared_medium");
  EXPECT_EQ(ToString(LinkModelKind::kRadio), "radio");
  EXPECT_EQ(ToString(LossModelKind::kNone), "none");
  EXPECT_EQ(ToString(LossModelKind::kBernoulli), "bernoulli");
  EXPECT_EQ(ToString(LossModelKind::kGilbertElliott), "gilbert_elliott");
  for (LinkModelKind k :
       {LinkModelKind::kIdeal, LinkModelKind::kPointToPoint, LinkModelKind::kSharedMedium, LinkModelKind::kRadio}) {
    EXPECT_EQ(ParseLinkModelKind(ToString(k)), k);
  }
  for (LossModelKind k : {LossModelKind::kNone, LossModelKind::kBernoulli, LossModelKind::kGilbertElliott}) {
    EXPECT_EQ(ParseLossModelKind(ToString(k)), k);
  }
}

}  // namespace
}  // namespace dvpr

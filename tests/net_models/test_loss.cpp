#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "net_models/gilbert_elliott_loss.h"
#include "net_models/ideal_link.h"
#include "net_models/link_factory.h"
#include "net_models/lossy_link.h"
#include "net_models/network.h"
#include "net_models/point_to_point_link.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

TEST(BernoulliLoss, LossRateOver100000MessagesIsWithinThreeSigma) {
  // Single-frame messages through the whole Network, ideal link, p = 0.1.
  // Dropped ~ Binomial(100 000, 0.1): mean 10 000, sigma = sqrt(n p (1-p)) = 94.87.
  constexpr int kN = 100000;
  constexpr double kP = 0.1;
  NetworkModelParams params;
  params.model = LinkModelKind::kIdeal;
  params.loss.model = LossModelKind::kBernoulli;
  params.loss.bernoulli.p = kP;
  Simulator sim;
  Network net(sim, 2, MakeLinkModel(params, 2, /*run_seed=*/2024));
  const ChannelId ch = net.InternChannel("C");
  const MessageTypeId type = net.InternType("t");
  const NodeId dst[] = {NodeId(1)};
  for (int i = 0; i < kN; ++i) net.SendTo(NodeId(0), dst, ch, type, std::vector<std::uint8_t>(100));
  sim.Run();
  const LinkCounters& c = net.Counters(NodeId(0), NodeId(1));
  const double sigma = std::sqrt(kN * kP * (1 - kP));
  EXPECT_EQ(c.messages, static_cast<std::uint64_t>(kN));
  EXPECT_NEAR(static_cast<double>(c.dropped), kN * kP, 3 * sigma);
  EXPECT_EQ(c.delivered + c.dropped, c.messages);
}

TEST(BernoulliLoss, AMessageIsLostIfAnyOfItsFramesIs) {
  // p = 0.5 on 3-frame messages: a message survives with 0.5^3 = 1/8.
  // Delivered ~ Binomial(20 000, 0.125): mean 2500, sigma = 46.8.
  LossParams loss;
  loss.model = LossModelKind::kBernoulli;
  loss.bernoulli.p = 0.5;
  LossyLink link(std::make_unique<IdealLink>(), 2, loss, {}, 7);
  const std::vector<Bytes> frames(3, Bytes(100));
  const NodeId dst[] = {NodeId(1)};
  int delivered = 0;
  for (int i = 0; i < 20000; ++i) {
    LinkDelivery out[1];
    link.Transmit(LinkTransmission{NodeId(0), dst, SimTime::Zero(), frames}, out);
    delivered += out[0].drop == DropReason::kNone;
  }
  EXPECT_NEAR(delivered, 2500, 3 * 46.8);
  EXPECT_EQ(link.LossOf(NodeId(0), NodeId(1))->Frames(), 60000u);
}

TEST(GilbertElliottLoss, LongRunLossAndBurstLengthMatchTheChain) {
  // loss_good 0, loss_bad 1: a frame is lost iff the chain is bad. Stationary
  // bad fraction = 0.05 / (0.05 + 0.2) = 0.2; mean burst = 1 / 0.2 = 5 frames.
  // The chain's lag-1 correlation is 1 - 0.05 - 0.2 = 0.75, so the loss
  // fraction's variance is 0.2 x 0.8 x (1.75 / 0.25) / n: sigma = 0.0024 at
  // n = 200 000. Bursts: ~8000, geometric with variance 0.8 / 0.04 = 20:
  // the mean burst's sigma is sqrt(20 / 8000) = 0.05. Both checked at 4 sigma.
  GilbertElliottLoss ge(GilbertElliottParams{0.05, 0.2, 0.0, 1.0});
  RandomStream rng(11, 12);
  constexpr int kN = 200000;
  int lost = 0, bursts = 0;
  bool prev = false;
  for (int i = 0; i < kN; ++i) {
    const bool l = ge.IsLost(rng);
    lost += l;
    bursts += l && !prev;
    prev = l;
  }
  EXPECT_NEAR(static_cast<double>(lost) / kN, 0.2, 4 * 0.0024);
  EXPECT_NEAR(static_cast<double>(lost) / bursts, 5.0, 4 * 0.05);
}

// A lost frame was on the air all the same: the sender paid for it. Two
// 547-byte frames at 1 Mbit/s, both lost (p = 1).
TEST(LossyLink, ReportsTheInnerLinksMediumUseForLostFrames) {
  LossParams all;
  all.model = LossModelKind::kBernoulli;
  all.bernoulli.p = 1.0;
  LossyLink link(std::make_unique<PointToPointLink>(
                     PointToPointParams{DataRate::Mbps(1), SimTime::Millis(5), 100, {}}, 2),
                 2, all, {}, 1);
  const NodeId dst[] = {NodeId(1)};
  const Bytes frames[] = {Bytes(547), Bytes(547)};
  LinkDelivery out[1];
  const LinkModel::MediumUse use = link.Transmit(LinkTransmission{NodeId(0), dst, SimTime::Zero(), frames}, out);
  EXPECT_EQ(out[0].drop, DropReason::kLoss);
  EXPECT_EQ(use.transmissions, 1u);
  EXPECT_EQ(use.bytes, Bytes(2 * 547));
}

TEST(LossyLink, PairOverrideReplacesTheDefault) {
  LossParams none;
  LossParams all;
  all.model = LossModelKind::kBernoulli;
  all.bernoulli.p = 1.0;
  const PairLossOverride cut[] = {{NodeId(0), NodeId(2), all}};
  LossyLink link(std::make_unique<IdealLink>(), 3, none, cut, 1);
  const NodeId dsts[] = {NodeId(1), NodeId(2)};
  const Bytes frame[] = {Bytes(100)};
  LinkDelivery out[2];
  link.Transmit(LinkTransmission{NodeId(0), dsts, SimTime::Zero(), frame}, out);
  EXPECT_EQ(out[0].drop, DropReason::kNone);
  EXPECT_EQ(out[1].drop, DropReason::kLoss);
  EXPECT_EQ(link.LossOf(NodeId(0), NodeId(1)), nullptr);
}

}  // namespace
}  // namespace dvpr

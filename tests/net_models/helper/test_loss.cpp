#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "net_models/helper/link_factory.h"
#include "net_models/helper/network_helper.h"
#include "net_models/network/network.h"
#include "net_models/network/network_stack.h"
#include "net_models/propagation/gilbert_elliott_loss.h"
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
  Network net(sim, 2, MakeNetworkStack(params, 2, /*run_seed=*/2024));
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
  ReceptionLoss channel_loss(2, loss, {}, 7);
  const NodeId dst[] = {NodeId(1)};
  int delivered = 0;
  for (int i = 0; i < 20000; ++i) {
    LinkDelivery out[1];
    channel_loss.Apply(NodeId(0), dst, /*frames=*/3, out);
    delivered += out[0].drop == DropReason::kNone;
  }
  EXPECT_NEAR(delivered, 2500, 3 * 46.8);
  EXPECT_EQ(channel_loss.LossOf(NodeId(0), NodeId(1))->Frames(), 60000u);
  EXPECT_EQ(channel_loss.FramesLost(), channel_loss.LossOf(NodeId(0), NodeId(1))->Lost());
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

// A lost frame was on the air all the same: the sender paid for it. The same two-frame message
// over a 1 Mbit/s point-to-point link, lost on the channel (p = 1) and not: the same medium bytes.
TEST(ReceptionLoss, TheSenderPaysForLostFrames) {
  const auto send = [](double p) {
    NetworkModelParams params;
    params.bandwidth = DataRate::Mbps(1);
    params.latency = SimTime::Millis(5);
    if (p > 0) {
      params.loss.model = LossModelKind::kBernoulli;
      params.loss.bernoulli.p = p;
    }
    Simulator sim;
    Network net(sim, 2, MakeNetworkStack(params, 2, /*run_seed=*/1));
    const NodeId dst[] = {NodeId(1)};
    net.SendTo(NodeId(0), dst, net.InternChannel("C"), net.InternType("t"), std::vector<std::uint8_t>(2000));
    sim.Run();
    return std::pair{net.Sender(NodeId(0)), net.Counters(NodeId(0), NodeId(1))};
  };
  const auto [lossy, lossy_pair] = send(1.0);
  const auto [clear, clear_pair] = send(0.0);
  EXPECT_EQ(lossy_pair.dropped, 1u);
  EXPECT_EQ(clear_pair.delivered, 1u);
  EXPECT_EQ(lossy.transmissions, 1u);
  EXPECT_GT(lossy.medium_bytes, 2000);  // two frames: 2000 payload bytes and their headers
  EXPECT_EQ(lossy.medium_bytes, clear.medium_bytes);
}

// An override replaces the default of its pair only; a copy the medium already dropped draws
// nothing.
TEST(ReceptionLoss, PairOverrideReplacesTheDefault) {
  LossParams none;
  LossParams all;
  all.model = LossModelKind::kBernoulli;
  all.bernoulli.p = 1.0;
  const PairLossOverride cut[] = {{NodeId(0), NodeId(2), all}};
  ReceptionLoss channel_loss(3, none, cut, 1);
  const NodeId dsts[] = {NodeId(1), NodeId(2)};
  LinkDelivery out[2];
  channel_loss.Apply(NodeId(0), dsts, 1, out);
  EXPECT_EQ(out[0].drop, DropReason::kNone);
  EXPECT_EQ(out[1].drop, DropReason::kLoss);
  EXPECT_EQ(channel_loss.LossOf(NodeId(0), NodeId(1)), nullptr);
  out[1] = LinkDelivery{SimTime::Zero(), DropReason::kQueueFull};
  channel_loss.Apply(NodeId(0), dsts, 1, out);
  EXPECT_EQ(out[1].drop, DropReason::kQueueFull);
  EXPECT_EQ(channel_loss.LossOf(NodeId(0), NodeId(2))->Frames(), 1u);
}

}  // namespace
}  // namespace dvpr

// Who hears whom, asked in one place (net_models/propagation/propagation_channel.h): the drop of a receiver
// that does not hear a transmission's start, the one that leaves range before its frame ends, the
// air's delay on the others, and a link-local send's hearers, worked out by hand over a scripted
// propagation model; and every medium that decides at send time asks the channel it is bound to.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "net_models/link/transmission_ledger.h"
#include "net_models/medium/ideal_link.h"
#include "net_models/medium/point_to_point_link.h"
#include "net_models/medium/radio_link.h"
#include "net_models/medium/shared_medium_link.h"
#include "net_models/propagation/loss_params.h"
#include "net_models/propagation/propagation_channel.h"
#include "net_models/propagation/reception_loss.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

// Node 1 is always heard (the air adds 100 ns); node 2 until 5 us (50 ns); node 3 never. Counts
// the questions asked.
class Scripted final : public PropagationModel {
 public:
  explicit Scripted(bool changes) : changes_(changes) {}
  int questions = 0;
  std::vector<SimTime> asked_at;

 private:
  void DoReach(NodeId, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) override {
    ++questions;
    asked_at.push_back(now);
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      switch (receivers[i].value) {
        case 1: out[i] = {true, SimTime::Nanos(100)}; break;
        case 2: out[i] = now < SimTime::Micros(5) ? Reception{true, SimTime::Nanos(50)} : Reception{false, {}}; break;
        default: out[i] = {false, SimTime::Zero()}; break;
      }
    }
  }
  std::string_view DoName() const override { return "scripted"; }
  bool DoChangesOverTime() const override { return changes_; }
  bool changes_;
};

const std::vector<NodeId> kReceivers = {NodeId(1), NodeId(2), NodeId(3)};

const Bytes kFrames[] = {Bytes(100), Bytes(100), Bytes(100)};

// A transmission from node 0 at time zero to kReceivers of `frames` frames.
LinkTransmission From0(std::size_t frames, DropReason unheard = DropReason::kOutOfRange) {
  return LinkTransmission{.src = NodeId(0), .dsts = kReceivers, .now = SimTime::Zero(),
                          .frames = std::span<const Bytes>(kFrames, frames), .unheard = unheard};
}

// Every copy arrives at `arrival`, its frame having ended at `frame_end`.
std::vector<LinkDelivery> AllAt(SimTime arrival, SimTime frame_end) {
  return std::vector<LinkDelivery>(3, LinkDelivery{.arrival = arrival, .frame_end = frame_end});
}

// Frames end at 8 us and arrive 2 us later: node 2 has left by the frames' end.
TEST(PropagationChannel, UnheardAtTheStartOrGoneAtTheFramesEndIsLostTheOthersArriveLater) {
  Scripted p(/*changes=*/true);
  PropagationChannel channel(p);
  std::vector<LinkDelivery> out = AllAt(SimTime::Micros(10), SimTime::Micros(8));
  channel.Settle(From0(1, DropReason::kStaleRoute), out);
  EXPECT_EQ(out[0].drop, DropReason::kNone);
  EXPECT_EQ(out[0].arrival, SimTime::Nanos(10'100));
  EXPECT_EQ(out[1].drop, DropReason::kOutOfRange);   // heard at 0, not at the frame's end (8 us)
  EXPECT_EQ(out[2].drop, DropReason::kStaleRoute);   // never heard: the caller's reason
  EXPECT_EQ(p.questions, 2);                         // the start, and one frame end for both
  EXPECT_EQ(p.asked_at, (std::vector<SimTime>{SimTime::Zero(), SimTime::Micros(8)}));
}

// Nobody moves: asked once, node 2 arrives with its delay.
TEST(PropagationChannel, AStillChannelIsAskedOnce) {
  Scripted p(/*changes=*/false);
  PropagationChannel channel(p);
  std::vector<LinkDelivery> out = AllAt(SimTime::Micros(10), SimTime::Micros(8));
  channel.Settle(From0(1), out);
  EXPECT_EQ(out[1].drop, DropReason::kNone);
  EXPECT_EQ(out[1].arrival, SimTime::Nanos(10'050));
  EXPECT_EQ(out[2].drop, DropReason::kOutOfRange);
  EXPECT_EQ(p.questions, 1);
}

// A copy the medium dropped keeps its reason and is not asked about; frame ends are asked once per
// run of equal ends (10, 20 us: two questions after the start).
TEST(PropagationChannel, MediumDropsStayAndEachFrameEndIsAskedOnce) {
  Scripted p(/*changes=*/true);
  PropagationChannel channel(p);
  std::vector<LinkDelivery> out = {LinkDelivery{.arrival = SimTime::Micros(4), .frame_end = SimTime::Micros(2)},
                                   LinkDelivery{.arrival = SimTime::Micros(6), .frame_end = SimTime::Micros(4)},
                                   LinkDelivery{.arrival = SimTime::Micros(20), .drop = DropReason::kQueueFull}};
  channel.Settle(From0(1), out);  // node 2's frame ends at 4 us: still heard
  EXPECT_EQ(out[0].arrival, SimTime::Nanos(4'100));
  EXPECT_EQ(out[1].drop, DropReason::kNone);
  EXPECT_EQ(out[1].arrival, SimTime::Nanos(6'050));
  EXPECT_EQ(out[2].drop, DropReason::kQueueFull);
  EXPECT_EQ(out[2].arrival, SimTime::Micros(20));  // no delay added to a drop
  EXPECT_EQ(p.asked_at, (std::vector<SimTime>{SimTime::Zero(), SimTime::Micros(2), SimTime::Micros(4)}));
}

// The channel's loss comes first (reception_loss.h): a lost copy is lost, heard or not, and each
// pair draws once per frame whatever the propagation says (here 3 frames, p = 1 on 0 -> 3 only).
TEST(PropagationChannel, LossComesBeforeThePropagation) {
  Scripted p(/*changes=*/false);
  LossParams all;
  all.model = LossModelKind::kBernoulli;
  all.bernoulli.p = 1.0;
  const PairLossOverride cut[] = {{NodeId(0), NodeId(3), all}};
  ReceptionLoss loss(4, LossParams{}, cut, /*run_seed=*/5);
  PropagationChannel channel(p, &loss);
  std::vector<LinkDelivery> out = AllAt(SimTime::Micros(10), SimTime::Micros(10));
  channel.Settle(From0(3), out);
  EXPECT_EQ(out[0].drop, DropReason::kNone);
  EXPECT_EQ(out[2].drop, DropReason::kLoss);  // never heard, but lost first
  EXPECT_EQ(loss.LossOf(NodeId(0), NodeId(3))->Frames(), 3u);
}

TEST(PropagationChannel, ALinkLocalSendKeepsItsHearersInOrder) {
  Scripted p(/*changes=*/true);
  PropagationChannel channel(p);
  std::vector<NodeId> members = {NodeId(3), NodeId(2), NodeId(1)};
  channel.KeepHearers(NodeId(0), members, SimTime::Zero());
  EXPECT_EQ(members, (std::vector<NodeId>{NodeId(2), NodeId(1)}));
  channel.KeepHearers(NodeId(0), members, SimTime::Micros(6));
  EXPECT_EQ(members, (std::vector<NodeId>{NodeId(1)}));
}

class NoOwner final : public LedgerOwner {
  void Complete(std::uint32_t, std::span<const AwaitedCopy>, std::span<const LinkDelivery>) override {}
};

// Every medium that decides at send time hands its outcomes to the channel it is bound to: over
// the scripted propagation (it never changes here) node 3 is out of range and node 1 arrives
// 100 ns after the medium said; unbound, the same medium is on the full mesh without loss.
TEST(PropagationChannel, EveryMediumThatDecidesAtSendTimeAsksTheChannelItIsBoundTo) {
  const auto make = [](int which) -> std::unique_ptr<LinkModel> {
    switch (which) {
      case 0: return std::make_unique<IdealLink>();
      case 1: return std::make_unique<PointToPointLink>(PointToPointParams{}, 4);
      case 2: return std::make_unique<SharedMediumLink>(SharedMediumParams{}, 4);
      default: return std::make_unique<RadioLink>(RadioLinkParams{}, 4);
    }
  };
  for (int which = 0; which < 4; ++which) {
    Scripted p(/*changes=*/false);
    PropagationChannel channel(p);
    Simulator sim;
    NoOwner owner;
    TransmissionLedger ledger(owner);
    std::unique_ptr<LinkModel> unbound = make(which);
    std::unique_ptr<LinkModel> bound = make(which);
    bound->Bind(sim, ledger, channel);
    std::vector<LinkDelivery> free(3);
    std::vector<LinkDelivery> heard(3);
    unbound->Transmit(From0(1), free);
    bound->Transmit(From0(1), heard);
    SCOPED_TRACE(std::string(bound->Name()));
    EXPECT_EQ(p.questions, 1);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(free[i].drop, DropReason::kNone);
    EXPECT_EQ(heard[0].drop, DropReason::kNone);
    EXPECT_EQ(heard[0].arrival, free[0].arrival + SimTime::Nanos(100));
    EXPECT_EQ(heard[2].drop, DropReason::kOutOfRange);
  }
}

// The radio's frame ends when its last bit leaves the sender, its latency before the arrival: a
// receiver that moves is asked then. 300 B at 10 Mbit/s (PPP framing is the network's, not the
// medium's: the frames here are the link's bytes) end at 240 us; the latency is 2 ms.
TEST(PropagationChannel, TheRadiosFrameEndIsItsLastBitNotItsArrival) {
  Scripted p(/*changes=*/true);
  PropagationChannel channel(p);
  Simulator sim;
  NoOwner owner;
  TransmissionLedger ledger(owner);
  RadioLink radio(RadioLinkParams{}, 4);
  radio.Bind(sim, ledger, channel);
  std::vector<LinkDelivery> out(3);
  radio.Transmit(From0(3), out);
  EXPECT_EQ(p.asked_at, (std::vector<SimTime>{SimTime::Zero(), SimTime::Micros(240)}));
  EXPECT_EQ(out[0].arrival, SimTime::Micros(2240) + SimTime::Nanos(100));
}

}  // namespace
}  // namespace dvpr

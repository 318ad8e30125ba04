// Who hears whom, asked in one place (net_models/propagation_channel.h): the drop of a receiver
// that does not hear a transmission's start, the one that leaves range before its frame ends, the
// air's delay on the others, and a link-local send's hearers, worked out by hand over a scripted
// propagation model.
#include <gtest/gtest.h>

#include <vector>

#include "net_models/loss_params.h"
#include "net_models/propagation_channel.h"
#include "net_models/reception_loss.h"

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

std::vector<LinkDelivery> AllAt(SimTime arrival) { return std::vector<LinkDelivery>(3, LinkDelivery{arrival}); }

// Frames end 2 us before they arrive (after_frame), at 8 us: node 2 has left by then.
TEST(PropagationChannel, UnheardAtTheStartOrGoneAtTheFramesEndIsLostTheOthersArriveLater) {
  Scripted p(/*changes=*/true);
  PropagationChannel channel(p);
  std::vector<LinkDelivery> out = AllAt(SimTime::Micros(10));
  channel.Settle(NodeId(0), kReceivers, SimTime::Zero(), /*frames=*/1, out, DropReason::kStaleRoute, SimTime::Micros(2));
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
  std::vector<LinkDelivery> out = AllAt(SimTime::Micros(10));
  channel.Settle(NodeId(0), kReceivers, SimTime::Zero(), /*frames=*/1, out, DropReason::kOutOfRange, SimTime::Micros(2));
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
  std::vector<LinkDelivery> out = {LinkDelivery{SimTime::Micros(4)}, LinkDelivery{SimTime::Micros(4)},
                                   LinkDelivery{SimTime::Micros(20), DropReason::kQueueFull}};
  out[1].arrival = SimTime::Micros(6);  // node 2's frame ends at 4 us: still heard
  channel.Settle(NodeId(0), kReceivers, SimTime::Zero(), /*frames=*/1, out, DropReason::kOutOfRange, SimTime::Micros(2));
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
  std::vector<LinkDelivery> out = AllAt(SimTime::Micros(10));
  channel.Settle(NodeId(0), kReceivers, SimTime::Zero(), /*frames=*/3, out, DropReason::kOutOfRange, SimTime::Zero());
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

}  // namespace
}  // namespace dvpr

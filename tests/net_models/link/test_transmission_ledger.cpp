// The ledger of the transmissions a contending medium decides later (net_models/link/transmission_ledger.h):
// a message arrives with its last frame, keeps its first loss, goes to its owner with the copies
// that waited when its last frame is settled, and a message whose every frame the queue refused
// is final at once. Worked by hand.
#include "net_models/link/transmission_ledger.h"

#include <gtest/gtest.h>

#include <deque>
#include <stdexcept>
#include <vector>

namespace dvpr {
namespace {

struct Owner final : LedgerOwner {
  void Complete(std::uint32_t slot, std::span<const AwaitedCopy> copies, std::span<const LinkDelivery> outcomes) override {
    ++calls;
    this->slot = slot;
    waited.assign(copies.begin(), copies.end());
    decided.assign(outcomes.begin(), outcomes.end());
  }
  int calls = 0;
  std::uint32_t slot = 0;
  std::vector<AwaitedCopy> waited;
  std::vector<LinkDelivery> decided;
};

const NodeId kDsts[] = {NodeId(1), NodeId(2)};

TEST(TransmissionLedger, AMessageArrivesWithItsLastFrameKeepsItsFirstLossAndGoesToItsOwnerOnce) {
  Owner owner;
  TransmissionLedger ledger(owner);
  const TransmissionLedger::Id id = ledger.Open(kDsts, /*frames=*/2);
  ledger.Wait(id, /*slot=*/7, PendingCopy{NodeId(1), NodeId(1), 40, 1, 0, SimTime::Zero()}, /*receiver=*/0);
  ledger.Wait(id, 7, PendingCopy{NodeId(2), NodeId(2), 41, 1, 0, SimTime::Zero()}, 1);
  ledger.Reached(id, 0, SimTime::Micros(9));
  ledger.Lost(id, 1, DropReason::kCollision);
  EXPECT_FALSE(ledger.Settle(id));  // one frame of two
  EXPECT_EQ(owner.calls, 0);
  ledger.Reached(id, 0, SimTime::Micros(5));    // an earlier time does not move the arrival back
  ledger.Lost(id, 1, DropReason::kRetryLimit);  // the first loss stays
  EXPECT_TRUE(ledger.Settle(id));
  ASSERT_EQ(owner.calls, 1);
  EXPECT_EQ(owner.slot, 7u);
  ASSERT_EQ(owner.waited.size(), 2u);
  EXPECT_EQ(owner.waited[1].copy.copy, 41u);
  EXPECT_EQ(owner.waited[1].receiver, 1u);
  ASSERT_EQ(owner.decided.size(), 2u);
  EXPECT_EQ(owner.decided[0].arrival, SimTime::Micros(9));
  EXPECT_EQ(owner.decided[0].drop, DropReason::kNone);
  EXPECT_EQ(owner.decided[1].drop, DropReason::kCollision);
  EXPECT_EQ(ledger.open(), 0u);
  EXPECT_THROW(ledger.Wait(id, 7, PendingCopy{}, 0), std::logic_error);  // a freed entry
}

TEST(TransmissionLedger, EveryFrameRefusedIsFinalAtOnceAndIdsAreReusedLastFreedFirst) {
  Owner owner;
  TransmissionLedger ledger(owner);
  std::deque<MacFrame> queue = {MacFrame{Bytes(100), 99}};  // one frame waits already
  MacCounters counters;
  const Bytes frames[] = {Bytes(611), Bytes(611)};
  LinkModel::MediumUse use;
  int queued = 0;
  const LinkTransmission t{.src = NodeId(0), .dsts = kDsts, .now = SimTime::Zero(), .frames = frames};
  const TransmissionLedger::Id id = ledger.Enqueue(t, queue, /*capacity=*/1, counters, use, [&] { ++queued; });
  EXPECT_EQ(queued, 0);
  EXPECT_EQ(counters.dropped_queue_full, 2u);
  EXPECT_EQ(use.bytes, Bytes(0));
  std::vector<LinkDelivery> out(2);
  ledger.HandOver(id, out, use);
  EXPECT_EQ(use.pending, LinkModel::MediumUse::kNone);  // nothing left to decide
  EXPECT_FALSE(out[0].later);
  EXPECT_EQ(out[0].drop, DropReason::kQueueFull);
  EXPECT_EQ(out[1].drop, DropReason::kQueueFull);
  EXPECT_EQ(owner.calls, 0);  // never reported from inside Transmit
  // The freed id is the next one handed out; one frame queued is decided later.
  queue.clear();
  LinkModel::MediumUse later;
  const TransmissionLedger::Id again = ledger.Enqueue(t, queue, 4, counters, later, [&] { ++queued; });
  EXPECT_EQ(again, id);
  EXPECT_EQ(queued, 2);
  EXPECT_EQ(later.bytes, Bytes(1222));
  ledger.HandOver(again, out, later);
  EXPECT_EQ(later.pending, again);
  EXPECT_TRUE(out[0].later && out[1].later);
}

}  // namespace
}  // namespace dvpr

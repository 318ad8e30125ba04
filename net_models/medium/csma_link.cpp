#include "net_models/medium/csma_link.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"
#include "sim/simulator.h"

namespace dvpr {

void CsmaParams::Validate() const {
  CheckPositiveRate("rate", rate);
  CheckNonNegativeDuration("delay", delay);
  CheckNonNegativeCount("queue_packets", queue_packets);
}

CsmaLink::CsmaLink(const CsmaParams& params, int nodes, std::uint64_t run_seed)
    : params_(params), gap_(params.rate.TxTime(Bytes(CsmaParams::kInterframeGapBits / 8))) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  params_.Validate();
  stations_.reserve(static_cast<std::size_t>(nodes));
  for (int s = 0; s < nodes; ++s) {
    stations_.emplace_back(RandomStream(run_seed, ComponentId("csma/backoff/" + std::to_string(s))));
  }
  counters_.assign(static_cast<std::size_t>(nodes), MacCounters{});
}

void CsmaLink::DoBind(Simulator& sim, TransmissionLedger& ledger) {
  sim_ = &sim;
  messages_ = &ledger;
}

// CsmaNetDevice::Send for each frame: into the queue (or dropped when it is full), and straight
// on the bus when the station is ready.
LinkModel::MediumUse CsmaLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  if (sim_ == nullptr) throw std::logic_error("CsmaLink: Transmit before Bind (csma runs on a network's simulator)");
  const auto s = static_cast<std::size_t>(t.src.value);
  Station& st = stations_[s];
  MediumUse use{t.dsts.empty() ? 0u : 1u, Bytes(0)};
  const std::uint32_t id = messages_->Enqueue(t, st.queue, static_cast<std::size_t>(params_.queue_packets),
                                             counters_[s], use, [&] {
                                               if (st.state != TxState::kReady) return;
                                               st.current = st.queue.front();
                                               st.queue.pop_front();
                                               TransmitStart(s);
                                             });
  messages_->HandOver(id, out, use);
  return use;
}

void CsmaLink::TransmitStart(std::size_t s) {
  Station& st = stations_[s];
  if (bus_ != BusState::kIdle) {
    st.state = TxState::kBackoff;
    if (st.retries >= CsmaParams::kMaxRetries) {
      TransmitAbort(s);
      return;
    }
    ++st.retries;
    ++counters_[s].backoffs;
    const SimTime wait = CsmaParams::kSlot * DrawSlots(s, st.retries);
    sim_->Schedule(wait, [this, s] { TransmitStart(s); });
    return;
  }
  st.state = TxState::kBusy;
  st.retries = 0;
  bus_ = BusState::kTransmitting;
  const SimTime tx = params_.rate.TxTime(st.current.size);
  ++counters_[s].attempts;
  counters_[s].airtime += tx;
  busy_ += tx + params_.delay;
  sim_->Schedule(tx, [this, s] { TransmitComplete(s); });
}

// The frame's last bit is on the bus: every destination the network's channel lets hear it (all,
// on a wire's full mesh) receives it the channel delay later, when the bus goes idle; the sender
// rests the interframe gap.
void CsmaLink::TransmitComplete(std::size_t s) {
  Station& st = stations_[s];
  st.state = TxState::kGap;
  bus_ = BusState::kPropagating;
  const std::uint32_t id = st.current.message;
  const SimTime arrival = sim_->Now() + params_.delay;
  const std::span<const NodeId> dsts = messages_->Destinations(id);
  heard_.resize(dsts.size());
  Hear(NodeId(static_cast<int>(s)), dsts, sim_->Now(), heard_);
  for (std::size_t i = 0; i < dsts.size(); ++i) {
    if (heard_[i].reaches) {
      messages_->Reached(id, i, arrival + heard_[i].delay);
    } else {
      messages_->Lost(id, i, DropReason::kOutOfRange);
    }
  }
  messages_->Settle(id);
  sim_->Schedule(params_.delay, [this] { bus_ = BusState::kIdle; });
  sim_->Schedule(gap_, [this, s] { TransmitReady(s); });
}

void CsmaLink::TransmitReady(std::size_t s) {
  Station& st = stations_[s];
  st.state = TxState::kReady;
  if (st.queue.empty()) return;
  st.current = st.queue.front();
  st.queue.pop_front();
  TransmitStart(s);
}

void CsmaLink::TransmitAbort(std::size_t s) {
  Station& st = stations_[s];
  ++counters_[s].dropped_retry_limit;
  const std::uint32_t id = st.current.message;
  messages_->LostEverywhere(id, DropReason::kRetryLimit);
  st.retries = 0;
  st.state = TxState::kReady;
  messages_->Settle(id);
  if (st.state != TxState::kReady || st.queue.empty()) return;
  st.current = st.queue.front();
  st.queue.pop_front();
  TransmitStart(s);
}

// ns-3's Backoff::GetBackoffTime after IncrNumRetries: the bound doubles up to the ceiling.
std::uint32_t CsmaLink::DrawSlots(std::size_t s, std::uint32_t retries) {
  const std::uint32_t exponent = std::min(retries, CsmaParams::kCeiling);
  const std::uint32_t max_slot = std::min((std::uint32_t{1} << exponent) - 1, CsmaParams::kMaxSlots);
  const std::uint32_t min_slot = CsmaParams::kMinSlots;
  if (draw_) {
    // ns-3 draws from [min_slot, max_slot) (a whole number of slots, at least one).
    const std::uint32_t slots = draw_(min_slot, max_slot);
    if (slots < min_slot || slots > std::max(min_slot, max_slot - 1)) {
      throw std::logic_error("CsmaLink: a drawn backoff of " + std::to_string(slots) + " slots outside [" +
                             std::to_string(min_slot) + ", " + std::to_string(std::max(min_slot, max_slot - 1)) + "]");
    }
    return slots;
  }
  if (max_slot <= min_slot) return min_slot;
  return min_slot + static_cast<std::uint32_t>(stations_[s].rng.UniformInt(max_slot - min_slot));
}

}  // namespace dvpr

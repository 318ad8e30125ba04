#pragma once
// "csma": ns-3's CsmaNetDevice on a CsmaChannel (ns-3.37, src/csma), event for event, so that a
// run on it and ns-3's replay of the same traffic agree message by message up to the backoff
// draws (docs/network_model.md, "Contending media").
//
// The channel is one bus, idle, transmitting (one frame, for its transmission time) or
// propagating (for the channel delay after the frame's last bit, when every other station
// receives it). A station with a frame to send finds it idle and transmits, or finds it busy and
// backs off a whole number of 1 us slots, Uniform(1, min(2^k - 1, 1000)) truncated at its k-th
// retry (ns-3's Backoff: ceiling 10), and looks again; after 1000 retries the frame is dropped.
// After its own transmission a station waits the interframe gap (96 bit times) before its next
// frame; the gap delays no one else. Frames wait in the station's drop-tail queue of
// queue_packets packets (the frame being sent or backing off is not in it). There are no
// collisions: a station senses the bus at one instant and ns-3's channel refuses a second
// transmission, so two stations never overlap - the optimistic side of real Ethernet.
//
// Frames are DIX Ethernet (LinkWire, wire_format.h). A message to several stations is one
// transmission that all of them receive; every frame of a message is queued when it is sent.
#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include "net_models/link/link_model.h"
#include "net_models/link/mac_counters.h"
#include "net_models/link/transmission_ledger.h"
#include "sim/random.h"

namespace dvpr {

struct CsmaParams {
  DataRate rate = DataRate::Mbps(10);
  SimTime delay = SimTime::Millis(2);  // CsmaChannel's Delay: from a frame's end to its reception
  int queue_packets = 100;             // each station's drop-tail queue
  // ns-3's Backoff, fixed (CsmaNetDevice does not expose it): slot time, slots, ceiling, retries.
  static constexpr SimTime kSlot = SimTime::Nanos(1000);
  static constexpr std::uint32_t kMinSlots = 1;
  static constexpr std::uint32_t kMaxSlots = 1000;
  static constexpr std::uint32_t kCeiling = 10;
  static constexpr std::uint32_t kMaxRetries = 1000;
  static constexpr std::int64_t kInterframeGapBits = 96;
  // Throws std::invalid_argument "<field>: ..." naming the value.
  void Validate() const;
};

class CsmaLink final : public LinkModel {
 public:
  // The slots of one backoff, given its bounds [min_slot, max_slot]: by default a uniform double
  // in that range truncated, as ns-3 draws them (so max_slot only when the two are equal).
  using SlotDraw = std::function<std::uint32_t(std::uint32_t min_slot, std::uint32_t max_slot)>;

  CsmaLink(const CsmaParams& params, int nodes, std::uint64_t run_seed);
  // Replaces every station's draws (a test fixes them).
  void SetSlotDraw(SlotDraw draw) { draw_ = std::move(draw); }
  SimTime InterframeGap() const { return gap_; }

 private:
  enum class TxState : std::uint8_t { kReady, kBusy, kGap, kBackoff };
  enum class BusState : std::uint8_t { kIdle, kTransmitting, kPropagating };
  struct Station {
    explicit Station(RandomStream stream) : rng(stream) {}
    std::deque<MacFrame> queue;
    MacFrame current;
    TxState state = TxState::kReady;
    std::uint32_t retries = 0;  // backoffs of the current frame
    RandomStream rng;
  };

  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return "csma"; }
  void DoBind(Simulator& sim, TransmissionLedger& ledger) override;
  std::span<const MacCounters> DoMac() const override { return counters_; }
  SimTime DoMediumBusy() const override { return busy_; }

  // CsmaNetDevice's TransmitStart, TransmitCompleteEvent, TransmitReadyEvent, TransmitAbort.
  void TransmitStart(std::size_t s);
  void TransmitComplete(std::size_t s);
  void TransmitReady(std::size_t s);
  void TransmitAbort(std::size_t s);
  std::uint32_t DrawSlots(std::size_t s, std::uint32_t retries);

  CsmaParams params_;
  SimTime gap_;
  Simulator* sim_ = nullptr;
  std::vector<Station> stations_;
  std::vector<MacCounters> counters_;
  TransmissionLedger* messages_ = nullptr;  // the network's (Bind): the transmissions in hand
  SlotDraw draw_;
  BusState bus_ = BusState::kIdle;
  SimTime busy_;  // the bus's time transmitting or propagating
  std::vector<Reception> heard_;  // scratch of TransmitComplete: by destination, the channel's answer
};

}  // namespace dvpr

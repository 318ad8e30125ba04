#pragma once
// "wifi": 802.11a/g OFDM, the distributed coordination function (DCF) of an ad hoc network
// without QoS, with ns-3's constants (docs/network_model.md, "wifi: 802.11 DCF").
//
// A station senses the medium busy while it hears a transmission (the network's channel, asked
// for each frame put on the air: everyone on the full mesh, the robots in range over a range), while it transmits or waits for
// an ACK, and until the NAV of a unicast frame it overheard ends (its ACK). Its backoff counts
// down only while the medium has been idle for DIFS (EIFS after a frame it heard in error), one
// 9 us slot at a time; it transmits when the count reaches zero, or at once when a frame arrives
// on a medium idle for DIFS with the count already run out (the post-backoff after every
// transmission, as ns-3 draws one at start and after each frame). Stations whose counts end in
// the same slot transmit together, and every station that hears two transmissions at once loses
// both (no capture); a station loses what arrives while it transmits. Over the radio, the ends of
// a line that cannot hear each other both transmit to the middle: hidden terminals.
//
// A message for one robot is unicast at `rate` and acknowledged: the receiver sends a 14-byte ACK
// SIFS after the frame at AckRate (below); without one by the ACK timeout the sender doubles its
// contention window (15, 31, ... 1023) and tries again, up to 7 transmissions of the frame
// (ns-3's MaxSsrc), then drops it. A message for several robots is one broadcast frame at the
// basic rate, never acknowledged or retried. A frame's time on the air: 16 us preamble + 4 us
// SIGNAL + 4 us per OFDM symbol, the symbols carrying 16 service bits, the frame and 6 tail bits.
// Frames carry 24 B MAC header + 8 B LLC/SNAP + 4 B FCS (LinkWire, wire_format.h).
//
// Not modelled: RTS/CTS (ns-3's default threshold sends none), rate control (ns-3's
// ConstantRateWifiManager), the queue's 500 ms lifetime, fragmentation, propagation delay inside
// the MAC's timing (it is added to each arrival), capture and interference below the range.
#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include "net_models/core/slot_pool.h"
#include "net_models/link/link_model.h"
#include "net_models/link/mac_counters.h"
#include "net_models/link/transmission_ledger.h"
#include "sim/random.h"
#include "sim/simulator.h"

namespace dvpr {

struct WifiParams {
  static constexpr SimTime kSlot = SimTime::Micros(9);
  static constexpr SimTime kSifs = SimTime::Micros(16);
  static constexpr SimTime kDifs = kSifs + kSlot * 2;  // 34 us
  static constexpr std::uint32_t kCwMin = 15;
  static constexpr std::uint32_t kCwMax = 1023;
  static constexpr int kMaxTransmissions = 7;
  static constexpr SimTime kPreamble = SimTime::Micros(16);
  static constexpr SimTime kSignal = SimTime::Micros(4);
  static constexpr SimTime kSymbol = SimTime::Micros(4);
  static constexpr std::int64_t kServiceBits = 16;
  static constexpr std::int64_t kTailBits = 6;
  static constexpr Bytes kAck{14};  // frame control, duration, receiver address, FCS

  DataRate rate;                            // unicast data: one of the 802.11a rates (required)
  DataRate basic_rate = DataRate::Mbps(6);  // broadcast frames and ACKs
  int queue_packets = 100;                  // each station's drop-tail queue

  // Throws std::invalid_argument "<field>: ..." naming the value: no rate, a rate outside 6, 9,
  // 12, 18, 24, 36, 48, 54 Mbit/s, a queue outside [1, 2^30].
  void Validate() const;
  bool operator==(const WifiParams&) const = default;
};

// Whether `rate` is one of 802.11a's OFDM rates.
bool IsOfdmRate(DataRate rate);
// The time on the air of an 802.11a PPDU of `bytes` MAC bytes at `rate` (an OFDM rate).
SimTime OfdmDuration(Bytes bytes, DataRate rate);
// EIFS = SIFS + an ACK at the basic rate + DIFS.
SimTime Eifs(const WifiParams& params);
// The rate of the ACK to a unicast frame at params.rate: as ns-3, the highest of 802.11a's
// mandatory rates (6, 12, 24 Mbit/s) not above it, and at least the basic rate (24 Mbit/s for
// data at 54).
DataRate AckRate(const WifiParams& params);

class WifiLink final : public LinkModel {
 public:
  // The slots of a backoff for `station` whose contention window is cw: by default uniform in
  // [0, cw]; a test fixes them.
  using SlotDraw = std::function<std::uint32_t(int station, std::uint32_t cw)>;

  // run_seed seeds each station's backoffs. Who senses and hears whom is the channel's (Bind).
  WifiLink(const WifiParams& params, int nodes, std::uint64_t run_seed);
  void SetSlotDraw(SlotDraw draw) { draw_ = std::move(draw); }
  // Transmissions lost to a collision at each station as a receiver (a frame it heard in error).
  std::uint64_t CorruptedAt(NodeId station) const { return corrupted_[static_cast<std::size_t>(station.value)]; }

 private:
  enum class Phase : std::uint8_t { kIdle, kContend, kTransmit, kAwaitAck };
  struct Station {
    explicit Station(RandomStream stream) : rng(stream) {}
    std::deque<MacFrame> queue;
    MacFrame current;
    Phase phase = Phase::kIdle;
    std::uint32_t cw = WifiParams::kCwMin;
    std::uint32_t slots = 0;     // backoff left when the medium last went busy (or was drawn)
    bool drawn = false;          // the first backoff is drawn when first needed
    int transmissions = 0;       // of the current frame
    bool settled = false;        // the current frame's fate is the message's already (received)
    bool dst_heard = false;      // some transmission of the current frame reached its receiver
    std::uint64_t ack_token = 0; // the attempt an ACK timeout belongs to
    SimTime ack_deadline;        // when that timeout falls
    // The medium as this station senses it.
    int heard = 0;               // transmissions on the air it hears
    bool tx_on = false;          // it is transmitting (a frame or an ACK)
    SimTime nav_until;
    bool busy = false;
    SimTime idle_since;
    bool eifs = false;           // the last frame it heard was in error
    EventId attempt;
    SimTime access_at;
    SimTime not_before;          // a frame that arrived with the backoff run out: DIFS after it
    std::vector<std::uint32_t> hearing;  // the Air ids it hears
    RandomStream rng;
  };
  // What became of a transmission at one hearer: received, lost to another overlapping it (an
  // error it heard), or never received because the hearer was transmitting itself.
  static constexpr char kClean = 0, kCollided = 1, kUnheard = 2;
  struct Air {
    std::size_t src = 0;
    bool ack = false;
    bool broadcast = false;
    std::uint32_t message = 0;  // data: its TransmissionLedger id
    std::size_t to = 0;         // unicast data: its receiver; ACK: the station it acknowledges
    std::vector<std::size_t> hearers;
    std::vector<char> corrupted;  // by hearer: kClean, kCollided or kUnheard
    std::vector<SimTime> delay;   // by hearer: the propagation delay
  };

  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return "wifi"; }
  void DoBind(Simulator& sim, TransmissionLedger& ledger) override;
  std::span<const MacCounters> DoMac() const override { return counters_; }
  SimTime DoMediumBusy() const override { return medium_busy_; }

  void EnsureDrawn(std::size_t s);
  std::uint32_t Draw(std::size_t s);
  SimTime Ifs(const Station& st) const { return st.eifs ? eifs_ : WifiParams::kDifs; }
  // The backoff left at `now` while the medium is idle.
  std::uint32_t SlotsLeft(const Station& st) const;
  // Re-derives whether s senses the medium busy, freezing its backoff when it goes busy and
  // scheduling its access when it goes idle.
  void Reassess(std::size_t s);
  void ScheduleAccess(std::size_t s);
  void Access(std::size_t s);
  void NextFrame(std::size_t s);
  void StartAir(std::size_t src, Bytes bytes, DataRate rate, const Air& what);
  void Corrupt(std::uint32_t air, std::size_t station, char how);
  void EndAir(std::uint32_t id);
  void SendAck(std::size_t from, std::size_t to);
  void AckTimeout(std::size_t s, std::uint64_t token);
  void Failed(std::size_t s);
  std::size_t IndexOf(std::uint32_t message, std::size_t station) const;

  WifiParams params_;
  SimTime eifs_;
  DataRate ack_rate_;
  SimTime ack_time_;
  Simulator* sim_ = nullptr;
  std::vector<Station> stations_;
  std::vector<MacCounters> counters_;
  std::vector<std::uint64_t> corrupted_;
  TransmissionLedger* messages_ = nullptr;  // the network's (Bind): the transmissions in hand
  SlotDraw draw_;
  SlotPool<Air> air_;  // by id: the transmissions on the air (Station::hearing)
  int on_air_ = 0;
  SimTime on_air_since_;
  SimTime medium_busy_;
  std::vector<NodeId> others_;  // scratch: every station but the sender
  std::vector<Reception> reach_;
  std::vector<char> reached_;   // scratch of EndAir: by destination, what became of a broadcast frame
};

}  // namespace dvpr

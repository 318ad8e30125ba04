#pragma once
// The link layer as the Network sees it, the medium access of its stack
// (network_stack.h: who may send when): given one message (as its link
// frames) from a node to one or more nodes at time `now`, when does it arrive
// at each destination, or why is it dropped? Today's models (an own FIFO
// transmitter per link, the ideal shared bus, no limit at all) are the
// default; they are small state machines over virtual time that compute arrival times
// analytically when the message is sent instead of scheduling an event per packet, which keeps
// the message path fast.
//
// A contending MAC (csma_link.h, wifi_link.h) cannot: whether a station finds the medium idle
// after its backoff depends on what others send in the meantime. Such a model runs its own
// events on the network's simulator (Bind), marks the copies it decides later (`later`) and
// reports them through LinkCompletions once the medium has settled them, with the ticket of their
// transmission; it answers for the propagation too (who senses and who hears whom), so the
// Network applies none to those copies.
//
// LinkModel::Transmit is the public, non-virtual entry point (NVI): it checks
// the request, resets the outcomes and reports what the message put on the
// media; each model implements only DoTransmit. A model keeps no totals: the
// Network counts, per sender, what Transmit reports (one byte counter).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "net_models/mac_counters.h"
#include "net_models/node_id.h"
#include "net_models/units.h"
#include "sim/sim_time.h"

namespace dvpr {

enum class DropReason : std::uint8_t {
  kNone = 0,
  kQueueFull,  // a frame found the sender's drop-tail queue full
  kLoss,       // a frame was lost on the channel (loss model)
  kOffline,    // the sender or the receiver was offline
  kNoRoute,    // the routing model found no way to the destination (next_hop_routing.h)
  kOutOfRange, // the receiver did not hear the transmission (propagation_model.h)
  kHopLimit,   // a relayed copy had made Network::kMaxHops transmissions (a routing loop)
  kBufferFull, // store-and-forward: the holder's buffer had no room (disconnected_params.h)
  kExpired,    // store-and-forward: held hold_time without a route
  kStaleRoute, // the next hop a learned route named did not hear it (link_state_routing.h)
  kRetryLimit, // a contending MAC gave a frame up after its retries (CSMA backoffs, 802.11 retransmissions)
  kCollision,  // a frame that is never retried (802.11 broadcast) collided at the receiver
};
inline constexpr std::size_t kDropReasons = 12;  // the enumerators above, kNone included
std::string_view ToString(DropReason reason);

// One message handed to the link layer.
struct LinkTransmission {
  NodeId src;
  std::span<const NodeId> dsts;   // distinct nodes, none equal to src
  SimTime now;
  std::span<const Bytes> frames;  // the message's link frames, in order (wire_format.h)
  std::uint64_t ticket = 0;       // names the transmission to LinkCompletions::Complete
};

// The outcome for one destination: the arrival of the message's last frame,
// or a drop.
struct LinkDelivery {
  SimTime arrival;
  DropReason drop = DropReason::kNone;
  bool later = false;  // decided later: reported through LinkCompletions::Complete
};

// Where a contending model reports the copies it left `later`.
class LinkCompletions {
 public:
  virtual ~LinkCompletions() = default;
  // All copies of transmission `ticket`, now decided: outcomes[i] for its dsts[i] (later false).
  // Called from the model's own events, never from inside Transmit.
  virtual void Complete(std::uint64_t ticket, std::span<const LinkDelivery> outcomes) = 0;
};

class Simulator;

class LinkModel {
 public:
  // What one message put on the media: transmissions counts every copy handed
  // to a medium (a point-to-point copy per destination, one per message on a
  // shared medium), even one the sender's queue refused; bytes counts the
  // frames that went on the air (a frame lost on the channel did).
  struct MediumUse {
    std::uint64_t transmissions = 0;
    Bytes bytes;
  };

  virtual ~LinkModel() = default;

  // Fills out[i] with the outcome for t.dsts[i] (out.size() == t.dsts.size()).
  MediumUse Transmit(const LinkTransmission& t, std::span<LinkDelivery> out);

  // By node, what a contending medium access did (mac_counters.h); empty for the others.
  std::span<const MacCounters> Mac() const { return DoMac(); }
  // The time the medium was busy with at least one transmission (a contending model; else zero).
  SimTime MediumBusy() const { return DoMediumBusy(); }

  // The network the model serves: a contending model schedules its events on `sim` and reports
  // to `completions`; the others ignore it. Called once, before the first Transmit.
  void Bind(Simulator& sim, LinkCompletions& completions) { DoBind(sim, completions); }

  // "ideal", "point_to_point", "shared_medium", "bernoulli(point_to_point)", ...
  std::string_view Name() const { return DoName(); }
  // How long after a frame's last bit is sent its arrival comes (a fixed per-hop processing
  // delay added after serialization; zero for a model without one): the frame ended at the
  // arrival minus this, when a moving receiver must still have been in range.
  SimTime DelayAfterFrame() const { return DoDelayAfterFrame(); }

 private:
  // out[i] arrives preset to {t.now, kNone}.
  virtual MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) = 0;
  virtual std::string_view DoName() const = 0;
  virtual SimTime DoDelayAfterFrame() const { return SimTime::Zero(); }
  virtual void DoBind(Simulator& /*sim*/, LinkCompletions& /*completions*/) {}
  virtual std::span<const MacCounters> DoMac() const { return {}; }
  virtual SimTime DoMediumBusy() const { return SimTime::Zero(); }
};

}  // namespace dvpr

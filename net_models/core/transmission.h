#pragma once
// What became of one copy of a message on its way: the words every room of the network shares.
// A medium (link_model.h) fills a LinkDelivery per destination of a LinkTransmission; the
// channel (propagation_channel.h) and the reception loss (reception_loss.h) may turn it into a
// drop; the forwarder and the network count and report it (network_observer.h) by DropReason.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "net_models/core/node_id.h"
#include "net_models/core/units.h"
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
  // The drop reason of a destination that does not hear the transmission when it starts (out of
  // range, or a stale route when a learned next hop no longer hears its sender).
  DropReason unheard = DropReason::kOutOfRange;
};

// The outcome for one destination: the arrival of the message's last frame,
// or a drop.
struct LinkDelivery {
  SimTime arrival;
  DropReason drop = DropReason::kNone;
  bool later = false;  // decided later: settled in the TransmissionLedger
  // When the copy's last frame ended at the sender (a medium deciding at send time sets it): a
  // receiver that moves must still hear the transmission then (PropagationChannel::Settle).
  SimTime frame_end = {};
};

}  // namespace dvpr

#pragma once
// The link layer as the Network sees it, the medium access of its stack
// (network_stack.h: who may send when): given one message (as its link
// frames) from a node to one or more nodes at time `now`, when does it arrive
// at each destination, or why is it dropped? Today's models (an own FIFO
// transmitter per link, the ideal shared bus, no limit at all) are the
// default; a contending MAC (CSMA, 802.11 DCF) is one more model, built over
// the stack's PropagationModel to know who senses whom. Models are small state machines
// over virtual time; they compute arrival times analytically instead of
// scheduling an event per packet, which keeps the message path fast.
//
// LinkModel::Transmit is the public, non-virtual entry point (NVI): it checks
// the request, resets the outcomes and reports what the message put on the
// media; each model implements only DoTransmit. A model keeps no totals: the
// Network counts, per sender, what Transmit reports (one byte counter).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

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
};
inline constexpr std::size_t kDropReasons = 10;  // the enumerators above, kNone included
std::string_view ToString(DropReason reason);

// One message handed to the link layer.
struct LinkTransmission {
  NodeId src;
  std::span<const NodeId> dsts;   // distinct nodes, none equal to src
  SimTime now;
  std::span<const Bytes> frames;  // the message's link frames, in order (wire_format.h)
};

// The outcome for one destination: the arrival of the message's last frame,
// or a drop.
struct LinkDelivery {
  SimTime arrival;
  DropReason drop = DropReason::kNone;
};

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
};

}  // namespace dvpr

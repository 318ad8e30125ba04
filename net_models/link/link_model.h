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
// settles them in the network's TransmissionLedger (transmission_ledger.h, lent at Bind), which
// tells the network when the last frame of a transmission is decided.
//
// Every medium asks the network's channel (propagation_channel.h, lent at Bind) who hears whom,
// the same channel whichever way it decides: one that decides at send time hands it its outcomes
// (Settle: loss, then who hears the transmission when it starts and still at its frame's end);
// a contending one asks who hears a frame it puts on the air (Hear). An unbound medium is on the
// full mesh without loss (every receiver hears every frame, no delay added).
//
// LinkModel::Transmit is the public, non-virtual entry point (NVI): it checks
// the request, resets the outcomes and reports what the message put on the
// media; each model implements only DoTransmit. A model keeps no totals: the
// Network counts, per sender, what Transmit reports (one byte counter).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "net_models/core/node_id.h"
#include "net_models/core/transmission.h"
#include "net_models/core/units.h"
#include "net_models/link/mac_counters.h"
#include "net_models/propagation/propagation_model.h"
#include "sim/sim_time.h"

namespace dvpr {

class Simulator;
class PropagationChannel;
class TransmissionLedger;

class LinkModel {
 public:
  // What one message put on the media: transmissions counts every copy handed
  // to a medium (a point-to-point copy per destination, one per message on a
  // shared medium), even one the sender's queue refused; bytes counts the
  // frames that went on the air (a frame lost on the channel did).
  struct MediumUse {
    std::uint64_t transmissions = 0;
    Bytes bytes;
    // The TransmissionLedger entry of a transmission whose copies are decided later; kNone else.
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};
    std::uint32_t pending = kNone;
  };

  virtual ~LinkModel() = default;

  // Fills out[i] with the outcome for t.dsts[i] (out.size() == t.dsts.size()).
  MediumUse Transmit(const LinkTransmission& t, std::span<LinkDelivery> out);

  // By node, what a contending medium access did (mac_counters.h); empty for the others.
  std::span<const MacCounters> Mac() const { return DoMac(); }
  // The time the medium was busy with at least one transmission (a contending model; else zero).
  SimTime MediumBusy() const { return DoMediumBusy(); }

  // The network the model serves: every model asks `channel` who hears whom; a contending model
  // schedules its events on `sim` and settles what it decides later in `ledger` (all must outlive
  // the model). Called once, before the first Transmit.
  void Bind(Simulator& sim, TransmissionLedger& ledger, PropagationChannel& channel) {
    channel_ = &channel;
    DoBind(sim, ledger);
  }

  // "ideal", "point_to_point", "shared_medium", "radio", "csma", "wifi".
  std::string_view Name() const { return DoName(); }

 protected:
  // A medium that decided t's copies at send time (out[i].arrival and frame_end set, or a drop)
  // ends its DoTransmit here: the channel loses, delays or keeps each (PropagationChannel::Settle).
  void Settle(const LinkTransmission& t, std::span<LinkDelivery> out);
  // A contending medium: who hears a frame src puts on the air at `at` (PropagationModel::Reach).
  void Hear(NodeId src, std::span<const NodeId> receivers, SimTime at, std::span<Reception> out);

 private:
  // out[i] arrives preset to {t.now, kNone, frame_end t.now}.
  virtual MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) = 0;
  virtual std::string_view DoName() const = 0;
  virtual void DoBind(Simulator& /*sim*/, TransmissionLedger& /*ledger*/) {}
  virtual std::span<const MacCounters> DoMac() const { return {}; }
  virtual SimTime DoMediumBusy() const { return SimTime::Zero(); }

  PropagationChannel* channel_ = nullptr;  // null until Bind: the full mesh without loss
};

}  // namespace dvpr

#pragma once
// "radio": each robot has one radio (docs/network_model.md). A robot's messages are serialized
// one after another at the bandwidth with the wire format's framing, through its own drop-tail
// queue; a message for several robots (a broadcast) is ONE transmission that every robot in
// range hears while it is sent. Who is in range is the network's channel's question
// (propagation_channel.h: range, log_distance over the robots' positions), asked once the queue
// has put the message on the air.
//
// Radios do not contend here: two neighbours may transmit at once and both are heard, the
// optimistic bound that a contending MAC (CSMA, 802.11 DCF) replaces behind the same seam.
// `latency` is the fixed per-hop processing delay; the air's propagation delay comes from the
// propagation model.
#include <vector>

#include "net_models/link/link_model.h"
#include "net_models/medium/fifo_transmitter.h"
#include "net_models/medium/one_transmission.h"

namespace dvpr {

// rate, latency (the fixed processing delay per hop), queue_packets per robot.
using RadioLinkParams = TransmitterParams;

class RadioLink final : public LinkModel {
 public:
  RadioLink(const RadioLinkParams& params, int nodes);

 private:
  struct Radio {
    FifoTransmitter queue;
    SimTime busy_until;
  };

  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return "radio"; }

  RadioLinkParams params_;
  std::vector<Radio> radios_;  // one per node
};

}  // namespace dvpr

#pragma once
// What the shared medium and the radio have in common (shared_medium_link.h, radio_link.h): a
// message is ONE transmission heard by all its destinations, put on the air by the sender's own
// drop-tail queue when the medium is free. They differ only in whose medium that is: one channel
// for the whole team, or each robot's own radio.
#include <span>

#include "net_models/link/link_model.h"
#include "net_models/medium/fifo_transmitter.h"

namespace dvpr {

struct TransmitterParams {
  DataRate rate = DataRate::Mbps(10);
  SimTime latency = SimTime::Millis(2);  // added to the last frame's end for every destination
  int queue_packets = 100;               // per sending node
  // Throws std::invalid_argument "<field>: ..." naming the value.
  void Validate() const;
};

// Sends t's frames through `tx` onto the medium that is free at `medium_busy_until` (updated).
// Every destination gets the last frame's end + latency (frame_end: that end), or every one loses
// the message to a full queue; one transmission when there is a destination. The caller hands the
// outcomes to its channel (LinkModel::Settle).
LinkModel::MediumUse TransmitOnce(FifoTransmitter& tx, SimTime& medium_busy_until, const TransmitterParams& params,
                                  const LinkTransmission& t, std::span<LinkDelivery> out);

}  // namespace dvpr

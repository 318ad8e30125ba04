#pragma once
// "shared_medium": one channel that every node shares, like an ad hoc radio
// network. Every transmission occupies the channel for its frames'
// serialization time, whoever sends it; a message for several nodes (a
// broadcast) is ONE transmission that all of them hear. Access to the channel
// is an idealized MAC: first come, first served, no collisions, no backoff.
// Each node has its own drop-tail queue of frames waiting for the channel.
#include <vector>

#include "net_models/link/link_model.h"
#include "net_models/medium/fifo_transmitter.h"
#include "net_models/medium/one_transmission.h"

namespace dvpr {

// rate, latency (propagation and processing, the same for all pairs), queue_packets per node.
using SharedMediumParams = TransmitterParams;

class SharedMediumLink final : public LinkModel {
 public:
  SharedMediumLink(const SharedMediumParams& params, int nodes);

 private:
  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return "shared_medium"; }

  SharedMediumParams params_;
  SimTime channel_busy_until_;
  std::vector<FifoTransmitter> senders_;  // one queue per node
};

}  // namespace dvpr

#include "net_models/shared_medium_link.h"

#include <stdexcept>
#include <string>

namespace dvpr {

void SharedMediumParams::Validate() const {
  if (rate.bps() <= 0) {
    throw std::invalid_argument("network.bandwidth = " + std::to_string(rate.bps()) +
                                "bps: a data rate must be positive");
  }
  if (latency < SimTime::Zero()) {
    throw std::invalid_argument("network.latency = " + std::to_string(latency.ns()) +
                                "ns: a latency must not be negative");
  }
  if (queue_packets < 0) {
    throw std::invalid_argument("network.queue_packets = " + std::to_string(queue_packets) +
                                ": must not be negative");
  }
}

SharedMediumLink::SharedMediumLink(const SharedMediumParams& params, int nodes) : params_(params) {
  if (nodes <= 0) {
    throw std::invalid_argument("robots = " + std::to_string(nodes) + ": a network needs at least one node");
  }
  params_.Validate();
  senders_.assign(static_cast<std::size_t>(nodes), FifoTransmitter(params.queue_packets));
}

LinkModel::MediumUse SharedMediumLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  FifoTransmitter& tx = senders_[static_cast<std::size_t>(t.src.value)];
  const FifoTransmitter::Result r = tx.Send(t.frames, t.now, params_.rate, channel_busy_until_);
  for (LinkDelivery& d : out) {
    if (r.queue_full) {
      d.drop = DropReason::kQueueFull;
    } else {
      d.arrival = r.last_end + params_.latency;
    }
  }
  return MediumUse{t.dsts.empty() ? 0u : 1u, r.bytes_sent};
}

}  // namespace dvpr

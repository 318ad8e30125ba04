#include "net_models/radio_link.h"

#include <string>

#include "net_models/param_checks.h"

namespace dvpr {

void RadioLinkParams::Validate() const {
  CheckPositiveRate("rate", rate);
  CheckNonNegativeDuration("latency", latency);
  CheckNonNegativeCount("queue_packets", queue_packets);
}

RadioLink::RadioLink(const RadioLinkParams& params, int nodes) : params_(params) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  params_.Validate();
  radios_.assign(static_cast<std::size_t>(nodes), Radio{FifoTransmitter(params.queue_packets), SimTime::Zero()});
}

// One transmission for all destinations: the sender's radio is its own medium, so its
// transmitter's free time is the medium's.
LinkModel::MediumUse RadioLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  Radio& radio = radios_[static_cast<std::size_t>(t.src.value)];
  const FifoTransmitter::Result r = radio.queue.Send(t.frames, t.now, params_.rate, radio.busy_until);
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

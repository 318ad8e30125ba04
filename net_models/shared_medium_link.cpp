#include "net_models/shared_medium_link.h"

#include <stdexcept>
#include <string>

#include "net_models/param_checks.h"

namespace dvpr {

void SharedMediumParams::Validate() const {
  CheckPositiveRate("rate", rate);
  CheckNonNegativeDuration("latency", latency);
  CheckNonNegativeCount("queue_packets", queue_packets);
}

SharedMediumLink::SharedMediumLink(const SharedMediumParams& params, int nodes) : params_(params) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
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

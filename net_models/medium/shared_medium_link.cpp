#include "net_models/medium/shared_medium_link.h"

#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {

SharedMediumLink::SharedMediumLink(const SharedMediumParams& params, int nodes) : params_(params) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  params_.Validate();
  senders_.assign(static_cast<std::size_t>(nodes), FifoTransmitter(params.queue_packets));
}

LinkModel::MediumUse SharedMediumLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  const MediumUse use = TransmitOnce(senders_[static_cast<std::size_t>(t.src.value)], channel_busy_until_, params_, t, out);
  Settle(t, out);
  return use;
}

}  // namespace dvpr

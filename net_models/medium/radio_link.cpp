#include "net_models/medium/radio_link.h"

#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {

RadioLink::RadioLink(const RadioLinkParams& params, int nodes) : params_(params) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  params_.Validate();
  radios_.assign(static_cast<std::size_t>(nodes), Radio{FifoTransmitter(params.queue_packets), SimTime::Zero()});
}

// The sender's radio is its own medium: its transmitter's free time is the medium's.
LinkModel::MediumUse RadioLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  Radio& radio = radios_[static_cast<std::size_t>(t.src.value)];
  const MediumUse use = TransmitOnce(radio.queue, radio.busy_until, params_, t, out);
  Settle(t, out);
  return use;
}

}  // namespace dvpr

#include "net_models/link/link_model.h"

#include <algorithm>
#include <stdexcept>

#include "net_models/propagation/propagation_channel.h"

namespace dvpr {

LinkModel::MediumUse LinkModel::Transmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  if (out.size() != t.dsts.size()) {
    throw std::logic_error("LinkModel::Transmit: one outcome slot per destination expected");
  }
  if (t.frames.empty()) throw std::logic_error("LinkModel::Transmit: a message has at least one frame");
  for (LinkDelivery& d : out) d = LinkDelivery{.arrival = t.now, .frame_end = t.now};
  return DoTransmit(t, out);
}

void LinkModel::Settle(const LinkTransmission& t, std::span<LinkDelivery> out) {
  if (channel_ != nullptr) channel_->Settle(t, out);
}

void LinkModel::Hear(NodeId src, std::span<const NodeId> receivers, SimTime at, std::span<Reception> out) {
  if (channel_ != nullptr) {
    channel_->Hear(src, receivers, at, out);
  } else {
    std::fill(out.begin(), out.end(), Reception{});
  }
}

}  // namespace dvpr

#include "net_models/medium/ideal_link.h"

namespace dvpr {

// Outcomes arrive preset to {now, delivered, frame end now}: the channel settles them as they are;
// the medium use is a copy of the frames per destination, as on point-to-point links.
LinkModel::MediumUse IdealLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  Bytes frame_bytes;
  for (Bytes f : t.frames) frame_bytes += f;
  const auto copies = static_cast<std::int64_t>(t.dsts.size());
  Settle(t, out);
  return MediumUse{static_cast<std::uint64_t>(copies), frame_bytes * copies};
}

}  // namespace dvpr

#include "net_models/ideal_link.h"

namespace dvpr {

// Outcomes arrive preset to {now, delivered}; only the medium use is left:
// a copy of the frames per destination, as on point-to-point links.
LinkModel::MediumUse IdealLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery>) {
  Bytes frame_bytes;
  for (Bytes f : t.frames) frame_bytes += f;
  const auto copies = static_cast<std::int64_t>(t.dsts.size());
  return MediumUse{static_cast<std::uint64_t>(copies), frame_bytes * copies};
}

}  // namespace dvpr

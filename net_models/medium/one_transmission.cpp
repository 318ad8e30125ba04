#include "net_models/medium/one_transmission.h"

#include "net_models/core/param_checks.h"

namespace dvpr {

void TransmitterParams::Validate() const {
  CheckPositiveRate("rate", rate);
  CheckNonNegativeDuration("latency", latency);
  CheckNonNegativeCount("queue_packets", queue_packets);
}

LinkModel::MediumUse TransmitOnce(FifoTransmitter& tx, SimTime& medium_busy_until, const TransmitterParams& params,
                                  const LinkTransmission& t, std::span<LinkDelivery> out) {
  const FifoTransmitter::Result r = tx.Send(t.frames, t.now, params.rate, medium_busy_until);
  for (LinkDelivery& d : out) {
    if (r.queue_full) {
      d.drop = DropReason::kQueueFull;
    } else {
      d.arrival = r.last_end + params.latency;
      d.frame_end = r.last_end;
    }
  }
  return LinkModel::MediumUse{t.dsts.empty() ? 0u : 1u, r.bytes_sent};
}

}  // namespace dvpr

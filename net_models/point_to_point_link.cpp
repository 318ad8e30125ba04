#include "net_models/point_to_point_link.h"

#include <stdexcept>
#include <string>

#include "net_models/param_checks.h"

namespace dvpr {

void PointToPointParams::Validate(int nodes) const {
  CheckPositiveRate("rate", rate);
  CheckNonNegativeDuration("latency", latency);
  CheckNonNegativeCount("queue_packets", queue_packets);
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    const PairOverride& o = overrides[i];
    const std::string field = "overrides[" + std::to_string(i) + "]";
    const std::string pair = std::to_string(o.src.value) + "->" + std::to_string(o.dst.value);
    if (o.src.value < 0 || o.src.value >= nodes || o.dst.value < 0 || o.dst.value >= nodes) {
      InvalidParam(field, "nodes must lie in [0, " + std::to_string(nodes) + "), got " + pair);
    }
    if (o.src == o.dst) InvalidParam(field, "a node has no link to itself, got " + pair);
    if (o.rate) CheckPositiveRate(field + ".rate", *o.rate);
    if (o.latency) CheckNonNegativeDuration(field + ".latency", *o.latency);
  }
}

PointToPointLink::PointToPointLink(const PointToPointParams& params, int nodes) : nodes_(nodes) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  params.Validate(nodes);
  links_.assign(static_cast<std::size_t>(nodes) * static_cast<std::size_t>(nodes),
                Link{params.rate, params.latency, SimTime::Zero(), FifoTransmitter(params.queue_packets)});
  for (const auto& o : params.overrides) {
    Link& link = links_[Index(o.src, o.dst)];
    if (o.rate) link.rate = *o.rate;
    if (o.latency) link.latency = *o.latency;
  }
}

LinkModel::MediumUse PointToPointLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  MediumUse use;
  for (std::size_t i = 0; i < t.dsts.size(); ++i) {
    Link& link = links_[Index(t.src, t.dsts[i])];
    const FifoTransmitter::Result r = link.tx.Send(t.frames, t.now, link.rate, link.busy_until);
    use.transmissions += 1;
    use.bytes += r.bytes_sent;
    if (r.queue_full) {
      out[i].drop = DropReason::kQueueFull;
    } else {
      out[i].arrival = r.last_end + link.latency;
    }
  }
  return use;
}

}  // namespace dvpr

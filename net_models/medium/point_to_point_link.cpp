#include "net_models/medium/point_to_point_link.h"

#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

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

namespace {

int CheckedNodes(int nodes) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  return nodes;
}

}  // namespace

PointToPointLink::PointToPointLink(const PointToPointParams& params, int nodes)
    : unused_{params.rate, params.latency, SimTime::Zero(), FifoTransmitter(params.queue_packets)},
      links_(CheckedNodes(nodes)) {
  params.Validate(nodes);
  for (const auto& o : params.overrides) {
    Link& link = links_.At(o.src, o.dst, unused_);
    if (o.rate) link.rate = *o.rate;
    if (o.latency) link.latency = *o.latency;
  }
}

const PointToPointLink::Link& PointToPointLink::Peek(NodeId src, NodeId dst) const {
  const Link* link = links_.Find(src, dst);
  return link != nullptr ? *link : unused_;
}

LinkModel::MediumUse PointToPointLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  MediumUse use;
  for (std::size_t i = 0; i < t.dsts.size(); ++i) {
    Link& link = links_.At(t.src, t.dsts[i], unused_);
    const FifoTransmitter::Result r = link.tx.Send(t.frames, t.now, link.rate, link.busy_until);
    use.transmissions += 1;
    use.bytes += r.bytes_sent;
    if (r.queue_full) {
      out[i].drop = DropReason::kQueueFull;
    } else {
      out[i].arrival = r.last_end + link.latency;
      out[i].frame_end = r.last_end;
    }
  }
  Settle(t, out);
  return use;
}

}  // namespace dvpr

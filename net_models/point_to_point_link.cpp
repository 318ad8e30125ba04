#include "net_models/point_to_point_link.h"

#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

[[noreturn]] void Invalid(const std::string& key, const std::string& value, const std::string& why) {
  throw std::invalid_argument(key + " = " + value + ": " + why);
}

void CheckRate(const std::string& key, DataRate rate) {
  if (rate.bps() <= 0) Invalid(key, std::to_string(rate.bps()) + "bps", "a data rate must be positive");
}

void CheckLatency(const std::string& key, SimTime latency) {
  if (latency < SimTime::Zero()) Invalid(key, std::to_string(latency.ns()) + "ns", "a latency must not be negative");
}

}  // namespace

void PointToPointParams::Validate(int nodes) const {
  CheckRate("network.bandwidth", rate);
  CheckLatency("network.latency", latency);
  if (queue_packets < 0) Invalid("network.queue_packets", std::to_string(queue_packets), "must not be negative");
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    const PairOverride& o = overrides[i];
    const std::string key = "network.links[" + std::to_string(i) + "]";
    const std::string pair = std::to_string(o.src.value) + "->" + std::to_string(o.dst.value);
    if (o.src.value < 0 || o.src.value >= nodes || o.dst.value < 0 || o.dst.value >= nodes) {
      Invalid(key, pair, "nodes must lie in [0, " + std::to_string(nodes) + ")");
    }
    if (o.src == o.dst) Invalid(key, pair, "a node has no link to itself");
    if (o.rate) CheckRate(key + ".bandwidth", *o.rate);
    if (o.latency) CheckLatency(key + ".latency", *o.latency);
  }
}

PointToPointLink::PointToPointLink(const PointToPointParams& params, int nodes) : nodes_(nodes) {
  if (nodes <= 0) Invalid("robots", std::to_string(nodes), "a network needs at least one node");
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

#pragma once
// "point_to_point": a full-duplex link per directed pair of nodes, as ns-3's
// PointToPointNetDevice + PointToPointChannel: frames are serialized at the
// link rate through a drop-tail queue, then travel for the propagation
// latency. A message for several nodes is sent as one copy per link.
// Heterogeneous teams: per-pair overrides of rate and latency.
#include <optional>
#include <vector>

#include "net_models/core/pair_map.h"
#include "net_models/link/link_model.h"
#include "net_models/medium/fifo_transmitter.h"

namespace dvpr {

struct PointToPointParams {
  struct PairOverride {
    NodeId src;
    NodeId dst;
    std::optional<DataRate> rate;      // unset: the default rate
    std::optional<SimTime> latency;    // unset: the default latency
  };

  DataRate rate = DataRate::Mbps(10);
  SimTime latency = SimTime::Millis(2);
  int queue_packets = 100;
  std::vector<PairOverride> overrides;  // directed: list both directions for a symmetric link

  // Throws std::invalid_argument "<field>: ..." naming the value: rate <= 0,
  // latency < 0, queue_packets < 0, an override outside [0, nodes) or on a
  // node's link to itself.
  void Validate(int nodes) const;
};

class PointToPointLink final : public LinkModel {
 public:
  PointToPointLink(const PointToPointParams& params, int nodes);

  DataRate RateOf(NodeId src, NodeId dst) const { return Peek(src, dst).rate; }
  SimTime LatencyOf(NodeId src, NodeId dst) const { return Peek(src, dst).latency; }

 private:
  struct Link {
    DataRate rate;
    SimTime latency;
    SimTime busy_until;
    FifoTransmitter tx;
  };

  // A pair's link, as configured if it never carried anything.
  const Link& Peek(NodeId src, NodeId dst) const;
  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return "point_to_point"; }

  Link unused_;           // an idle link at the default rate and latency
  PairMap<Link> links_;   // the links used so far and the overridden ones
};

}  // namespace dvpr

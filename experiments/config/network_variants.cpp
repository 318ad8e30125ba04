#include "experiments/config/network_variants.h"

#include "net_models/core/units.h"
#include "net_models/core/wire_format.h"

namespace dvpr {

namespace {

NetworkVariant MakeVariant(int index, const NetworkConfig& n, LinkModelKind model, DataRate rate,
                           SimTime latency, int queue, Bytes mtu, const PropagationParams& propagation,
                           const NextHopEntry& routing) {
  NetworkVariant v;
  v.index = index;
  v.params = NetworkModelParams{.model = model, .bandwidth = rate, .latency = latency, .queue_packets = queue,
                                .wire = WireParams{.mtu = mtu, .trailer = Bytes(wire::kTeamTrailer)}, .loss = n.loss, .links = n.links, .propagation = propagation,
                                .wifi = n.wifi, .next_hop = routing.kind, .link_state = routing.link_state,
                                .disconnected = n.disconnected};
  NetworkLabel& l = v.label;
  l.variant = index;
  l.model = ToString(model);
  l.loss = ToString(n.loss.model);
  if (model != LinkModelKind::kIdeal) {
    if (model == LinkModelKind::kWifi) {
      // Its rate is the wifi's (the bandwidth and latency keys do not apply); the air's delay is
      // the propagation's.
      l.bandwidth_bps = static_cast<double>(n.wifi.rate.bps());
    } else {
      l.bandwidth_bps = static_cast<double>(rate.bps());
      l.latency_ms = latency.ToMillis();
    }
    if (n.queue_packets.size() > 1) l.queue_packets = queue;
    if (n.mtu.size() > 1) l.mtu_bytes = static_cast<int>(mtu.value());
  }
  if (propagation.kind == PropagationKind::kRange) {
    l.propagation = "range " + FormatMeters(propagation.range_m);
    l.range_m = propagation.range_m;
  } else if (propagation.kind != PropagationKind::kFullMesh) {
    l.propagation = ToString(propagation.kind);
  }
  if (routing.kind != NextHopKind::kDirect) l.next_hop = ToString(routing.kind);
  return v;
}

}  // namespace

std::vector<NetworkVariant> ExpandNetworks(const NetworkConfig& n) {
  std::vector<NetworkVariant> out;
  for (LinkModelKind model : n.model) {
    if (model == LinkModelKind::kIdeal) {
      out.push_back(MakeVariant(static_cast<int>(out.size()), n, model, n.bandwidth.front(),
                                n.latency.front(), n.queue_packets.front(), n.mtu.front(), PropagationParams{},
                                NextHopEntry{}));
      continue;
    }
    // A medium with a propagation sweeps its entries (PropagationsOf); only the radio sweeps its
    // routing entries, every other model has the default (unused: one hop to every robot).
    const bool radio_model = model == LinkModelKind::kRadio;
    const std::vector<NextHopEntry> routings = radio_model ? n.routing : std::vector<NextHopEntry>{NextHopEntry{}};
    // wifi has its own rate: the bandwidth and latency lists do not multiply it.
    const bool wifi = model == LinkModelKind::kWifi;
    const std::vector<DataRate> rates = wifi ? std::vector<DataRate>{n.bandwidth.front()} : n.bandwidth;
    const std::vector<SimTime> latencies = wifi ? std::vector<SimTime>{n.latency.front()} : n.latency;
    for (const PropagationParams& propagation : PropagationsOf(n, model)) {
      for (const NextHopEntry& routing : routings) {
        for (DataRate rate : rates) {
          for (SimTime latency : latencies) {
            for (int queue : n.queue_packets) {
              for (Bytes mtu : n.mtu) {
                out.push_back(
                    MakeVariant(static_cast<int>(out.size()), n, model, rate, latency, queue, mtu, propagation, routing));
              }
            }
          }
        }
      }
    }
  }
  return out;
}

std::vector<NetworkLabel> VariantLabels(const NetworkConfig& network) {
  std::vector<NetworkLabel> labels;
  for (NetworkVariant& v : ExpandNetworks(network)) labels.push_back(std::move(v.label));
  return labels;
}

}  // namespace dvpr

#include "experiments/sweep/sweep.h"

#include "experiments/results/protocol_traits.h"
#include "experiments/strategies/run_centroids.h"

namespace dvpr {

namespace {

NetworkVariant MakeVariant(int index, const NetworkConfig& n, LinkModelKind model, DataRate rate,
                           SimTime latency, int queue, Bytes mtu, const RadioParams& radio,
                           const NextHopEntry& routing) {
  NetworkVariant v;
  v.index = index;
  v.params = NetworkModelParams{.model = model, .bandwidth = rate, .latency = latency, .queue_packets = queue,
                                .wire = WireParams{.mtu = mtu, .trailer = Bytes(wire::kTeamTrailer)}, .loss = n.loss, .links = n.links, .radio = radio,
                                .wifi = n.wifi, .wifi_radio = n.wifi_radio, .next_hop = routing.kind, .link_state = routing.link_state,
                                .disconnected = n.disconnected};
  v.label.variant = index;
  v.label.model = ToString(model);
  v.label.loss = ToString(n.loss.model);
  v.name = v.label.model;
  if (model != LinkModelKind::kIdeal) {
    if (model == LinkModelKind::kWifi) {
      // Its rate is the wifi's (the bandwidth and latency keys do not apply); the air's delay is
      // the propagation's.
      v.label.bandwidth_bps = static_cast<double>(n.wifi.rate.bps());
      v.label.latency_ms = kNotApplicable;
      v.name += " " + ToString(n.wifi.rate);
    } else {
      v.label.bandwidth_bps = static_cast<double>(rate.bps());
      v.label.latency_ms = latency.ToMillis();
      v.name += " " + ToString(rate) + " " + FormatDuration(latency);
    }
    if (n.queue_packets.size() > 1) v.name += " q" + std::to_string(queue);
    if (n.mtu.size() > 1) v.name += " mtu" + std::to_string(mtu.value());
  }
  if (model == LinkModelKind::kRadio || (model == LinkModelKind::kWifi && n.wifi_radio)) {
    v.label.radio = radio.propagation == PropagationKind::kRange ? "range " + FormatMeters(radio.range_m)
                                                                 : std::string(ToString(radio.propagation));
    v.name += " " + v.label.radio;
  }
  if (routing.kind != NextHopKind::kDirect) {
    v.label.routing = ToString(routing.kind);
    v.name += " " + v.label.routing;
  }
  if (n.loss.model != LossModelKind::kNone) v.name += " loss:" + v.label.loss;
  return v;
}

}  // namespace

std::vector<NetworkVariant> ExpandNetworks(const NetworkConfig& n) {
  std::vector<NetworkVariant> out;
  for (LinkModelKind model : n.model) {
    if (model == LinkModelKind::kIdeal) {
      out.push_back(MakeVariant(static_cast<int>(out.size()), n, model, n.bandwidth.front(),
                                n.latency.front(), n.queue_packets.front(), n.mtu.front(), RadioParams{},
                                NextHopEntry{}));
      continue;
    }
    // Only the radio sweeps its radio and routing entries; every other model has the default
    // ones (unused: one hop to every robot).
    const bool radio_model = model == LinkModelKind::kRadio;
    const bool radios_swept = radio_model || (model == LinkModelKind::kWifi && n.wifi_radio);
    const std::vector<RadioParams> radios = radios_swept ? n.radio : std::vector<RadioParams>{RadioParams{}};
    const std::vector<NextHopEntry> routings = radio_model ? n.routing : std::vector<NextHopEntry>{NextHopEntry{}};
    // wifi has its own rate: the bandwidth and latency lists do not multiply it.
    const bool wifi = model == LinkModelKind::kWifi;
    const std::vector<DataRate> rates = wifi ? std::vector<DataRate>{n.bandwidth.front()} : n.bandwidth;
    const std::vector<SimTime> latencies = wifi ? std::vector<SimTime>{n.latency.front()} : n.latency;
    for (const RadioParams& radio : radios) {
      for (const NextHopEntry& routing : routings) {
        for (DataRate rate : rates) {
          for (SimTime latency : latencies) {
            for (int queue : n.queue_packets) {
              for (Bytes mtu : n.mtu) {
                out.push_back(
                    MakeVariant(static_cast<int>(out.size()), n, model, rate, latency, queue, mtu, radio, routing));
              }
            }
          }
        }
      }
    }
  }
  return out;
}

std::vector<RunSpec> ExpandSweep(const ExperimentConfig& config,
                                 const std::vector<NetworkVariant>& networks) {
  std::vector<RunSpec> specs;
  for (const std::string& protocol : config.sweep.protocols) {
    std::vector<const NetworkVariant*> variants;
    if (TraitsOf(protocol).simulated_network) {
      for (const auto& v : networks) variants.push_back(&v);
    } else {
      variants.push_back(nullptr);  // no network of the sweep's (the static protocol has none)
    }
    for (const NetworkVariant* variant : variants) {
      for (int robots : config.sweep.robots) {
        for (int run = 0; run < config.sweep.runs; ++run) {
          RunSpec s;
          s.index = specs.size();
          s.protocol = protocol;
          s.strategies = config.sweep.strategies;
          s.robots = robots;
          s.run = run;
          s.seed = RunSeed(config.seed, robots, run);
          s.network = variant;
          specs.push_back(std::move(s));
        }
      }
    }
  }
  return specs;
}

}  // namespace dvpr

#pragma once
// The network variants of a sweep: network.{model, radio, routing, bandwidth, latency,
// queue_packets, mtu} crossed, in that nesting order (model outermost). Each variant has what the
// link factory builds (NetworkModelParams) and its label for the result files (NetworkLabel), made
// here and only here: the typed fields the figures and the replay read (range, rate, latency, next
// hop) and the text its name shows come from the same values, so nothing parses a name back.
//
// The ideal model ignores bandwidth, latency, queue and MTU, so it yields one variant however many
// values those lists hold; only the radio crosses network.routing; wifi has its own rate (the
// bandwidth and latency lists do not multiply it).
#include <vector>

#include "experiments/config/config.h"
#include "experiments/results/results.h"
#include "net_models/helper/link_factory.h"

namespace dvpr {

struct NetworkVariant {
  int index = 0;
  NetworkModelParams params;  // what the link factory builds for the run
  NetworkLabel label;         // how result files, figures and progress lines name it (NetworkName)
};

std::vector<NetworkVariant> ExpandNetworks(const NetworkConfig& network);

// The labels of ExpandNetworks(network), by variant index: what `dvpr plot` and `dvpr replay`
// read from a result folder's config.yaml to know each variant's range and next hop.
std::vector<NetworkLabel> VariantLabels(const NetworkConfig& network);

}  // namespace dvpr

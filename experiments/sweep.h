#pragma once
// Sweep expansion: the config's lists (protocols, robots, runs, network parameters) become a flat
// list of RunSpecs in a fixed order; that order is the order of the rows in every result file.
//
// Order: protocol (as listed), then network variant (sim only; paper has one, with no network),
// then robots (as listed), then run. One spec covers all strategies of that (protocol, network,
// robots, run): the sim runs decentralized and broadcast on the same data and needs broadcast's
// AUC for the relative AUC; the paper protocol's reference is the centralized AUC, computed once.
//
// Seeding: seed = MixSeed(MixSeed(config seed, robots), run) (sim/random_bits.h), the same
// formula as the static protocol's PaperRunSeed. It does not depend on the protocol or network
// variant, so one (robots, run) trains the same centroids everywhere and network variants are
// compared on identical data; adding robot counts or runs changes no other run's seed.
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/config.h"
#include "experiments/results.h"

namespace dvpr {

// One network of the sweep, with its label for result files.
struct NetworkVariant {
  int index = 0;
  NetworkSettings settings;
  NetworkLabel label;
  std::string name;  // "point_to_point 10Mbps 2ms" (human-readable, for tables and legends)
};

struct RunSpec {
  std::size_t index = 0;               // position in the sweep
  std::string protocol;                // paper | sim
  std::vector<std::string> strategies; // as in the config
  int robots = 0;
  int run = 0;
  std::uint64_t seed = 0;
  const NetworkVariant* network = nullptr;  // null for protocol=paper
  RunKey Key(const std::string& strategy) const;
};

// The cross product of network.{model, bandwidth, latency, queue_packets, mtu}, in that nesting
// order (model outermost). The ideal model ignores bandwidth, latency, queue and MTU, so it
// yields one variant however many values those lists hold.
std::vector<NetworkVariant> ExpandNetworks(const NetworkConfig& network);

std::uint64_t RunSeed(std::uint64_t config_seed, int robots, int run);

// Specs point into `networks`, which must outlive them.
std::vector<RunSpec> ExpandSweep(const ExperimentConfig& config,
                                 const std::vector<NetworkVariant>& networks);

}  // namespace dvpr

#pragma once
// Sweep expansion: the config's lists (protocols, robots, runs, network parameters) become a flat
// list of RunSpecs in a fixed order; that order is the order of the rows in every result file.
//
// Order: protocol (as listed), then network variant (sim only; paper has one, with no network),
// then robots (as listed), then run. One spec covers all strategies of that (protocol, network,
// robots, run): the sim runs decentralized and broadcast on the same data and needs broadcast's
// AUC for the relative AUC; the paper protocol's reference is the centralized AUC, computed once.
//
// Seeding: seed = RunSeed(config seed, robots, run) (experiments/domain/strategies/run_centroids.h), the
// seed of the run's k-means in every protocol. It does not depend on the protocol or network
// variant, so one (robots, run) trains the same centroids everywhere and network variants are
// compared on identical data; adding robot counts or runs changes no other run's seed.
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/config/config.h"
#include "experiments/config/network_variants.h"
#include "experiments/protocols/run.h"

namespace dvpr {

// Specs point into `networks`, which must outlive them.
std::vector<RunSpec> ExpandSweep(const ExperimentConfig& config,
                                 const std::vector<NetworkVariant>& networks);

}  // namespace dvpr

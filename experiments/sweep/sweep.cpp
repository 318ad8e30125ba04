#include "experiments/sweep/sweep.h"

#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/results/protocol_traits.h"

namespace dvpr {

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

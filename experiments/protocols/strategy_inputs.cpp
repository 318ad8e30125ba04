#include "experiments/protocols/strategy_inputs.h"

#include <stdexcept>

namespace dvpr {

StrategyInputs StrategyInputsOf(const SharedInputs& inputs) {
  if (inputs.config == nullptr) throw std::invalid_argument("StrategyInputsOf: the shared inputs have no config");
  const ExperimentConfig& c = *inputs.config;
  StrategyInputs s;
  s.training = &inputs.training;
  s.deployment = &inputs.deployment.descriptors;
  s.fps = inputs.deployment.fps;
  if (inputs.deployment.plan) s.plan = &*inputs.deployment.plan;
  s.bow = &inputs.bow;
  s.centroids = c.training.run_centroids;  // the config seed, clusters per robot, centroid files
  s.cache = inputs.centroid_cache.get();   // the sweep's k-means, shared by every run of a (robots, run)
  s.failover = c.failover;
  return s;
}

StrategyInputs StrategyInputsOf(const SharedInputs& inputs, int robots) {
  StrategyInputs s = StrategyInputsOf(inputs);
  const Dataset& team = inputs.Team(robots);
  s.deployment = &team.descriptors;
  s.plan = team.plan ? &*team.plan : nullptr;
  return s;
}

}  // namespace dvpr

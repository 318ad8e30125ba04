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
  s.centroids.seed = c.seed;
  s.centroids.clusters_per_robot = c.training.clusters_per_robot;
  s.centroids.centroids_pattern = c.training.centroids.value_or("");
  return s;
}

}  // namespace dvpr

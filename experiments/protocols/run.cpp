#include "experiments/protocols/run.h"

namespace dvpr {

RunKey RunSpec::Key(const std::string& strategy) const {
  RunKey key;
  key.protocol = protocol;
  key.strategy = strategy;
  key.robots = robots;
  key.run = run;
  if (network != nullptr) key.network = network->label;
  return key;
}

const Dataset& SharedInputs::Team(int robots) const {
  if (!deployment.plan || deployment.plan->robots() == robots) return deployment;
  return smaller_teams.at(robots);
}

}  // namespace dvpr

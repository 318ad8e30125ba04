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

}  // namespace dvpr

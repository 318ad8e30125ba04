#pragma once
// Loads what every run of an experiment reads (the deployment data, the training descriptors)
// from a validated config, once. Errors that need the data (dim larger than the descriptors,
// frame counts of poses and descriptors differing, NaN values) are ConfigErrors naming the key.
#include "experiments/config/config.h"
#include "experiments/protocols/run.h"

namespace dvpr {

// `origin` names the config file in error messages.
SharedInputs LoadSharedInputs(const ExperimentConfig& config, const std::string& origin);

}  // namespace dvpr

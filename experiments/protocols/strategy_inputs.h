#pragma once
// What BuildRunPlacement (experiments/domain/strategies/run_placement.h) builds every run's table from,
// taken from the inputs and config a protocol is given, so the paper, sim and lcm protocols
// build a strategy from the same data and settings.
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/protocols/run.h"

namespace dvpr {

// Points into `inputs` (which must outlive the result); inputs.config must be set. Centroids:
// the config's seed, training.clusters_per_robot and training.centroids files; no cache.
StrategyInputs StrategyInputsOf(const SharedInputs& inputs);
// The same for the runs of `robots` robots: the deployment (sample tables, re-clustering) and plan
// of that team (SharedInputs::Team); the training side is the shared one.
StrategyInputs StrategyInputsOf(const SharedInputs& inputs, int robots);

}  // namespace dvpr

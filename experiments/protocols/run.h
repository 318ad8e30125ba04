#pragma once
// What a protocol (paper, sim, lcm) is given and gives back: one RunSpec of the sweep in, one
// RunOutput out, with the inputs every run shares. The sweep (experiments/sweep/) expands a
// config into RunSpecs and calls the protocols' RunFunctions; the protocols know nothing of it.
//
// A ProtocolFactory gets the SharedInputs, does its one-off work (e.g. the centralized AUC of the
// paper protocol) and returns a RunFunction, which is then called from several threads at once
// (it must be safe for that: const state only, or its own locking).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "experiments/config/config.h"
#include "experiments/config/network_variants.h"
#include "experiments/domain/data/bow_data.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/domain/strategies/strategy_spec.h"
#include "experiments/results/bow_rows.h"
#include "experiments/results/closure_rows.h"
#include "experiments/results/connectivity_rows.h"
#include "experiments/results/medium_rows.h"
#include "experiments/results/radio_rows.h"
#include "experiments/results/results.h"
#include "net_models/helper/link_factory.h"

namespace dvpr {

struct RunSpec {
  std::size_t index = 0;               // position in the sweep
  std::string protocol;                // paper | sim
  std::vector<StrategySpec> strategies; // as in the config
  int robots = 0;
  int run = 0;
  std::uint64_t seed = 0;
  const NetworkVariant* network = nullptr;  // null for protocol=paper
  RunKey Key(const std::string& strategy) const;
};

// What every run reads; loaded once before the first run (experiments/protocols/inputs.h).
struct SharedInputs {
  const ExperimentConfig* config = nullptr;
  Dataset deployment;                  // a team plan's: its largest team (every robot of the plan)
  // A team plan swept over team sizes (docs/config.md, "Team plans"): for each swept count n below
  // the plan's, the team of its first n robots (FirstRobots).
  std::map<int, Dataset> smaller_teams;
  // The deployment a run of `robots` robots drives: `deployment` for the paper's split and the
  // plan's own count, else smaller_teams' (std::out_of_range for a count the sweep has not).
  const Dataset& Team(int robots) const;
  BowData bow;                         // the deployment's BoW vectors; empty unless a bow_ strategy runs
  DescriptorMatrix training;           // no rows (dim columns) when training.centroids gives the centroids
  std::filesystem::path out_dir;       // centroids go to out_dir/centroids/
  // Each (robots, run)'s k-means, computed once for every protocol, network variant and strategy
  // of the sweep that uses it (StrategyInputsOf hands it to the strategies).
  std::shared_ptr<RunCentroidCache> centroid_cache = std::make_shared<RunCentroidCache>();
};

// Everything one spec produced: one RunResult per strategy, plus the detail rows. Run functions
// fill each row's key with spec.Key(strategy) and the run's seed.
struct RunOutput {
  std::vector<RunResult> runs;
  std::vector<RobotLoadRow> per_robot;
  std::vector<LinkRow> links;
  std::vector<QueryRow> queries;      // only when outputs.queries
  std::vector<MessageRow> messages;   // only when outputs.messages
  std::vector<PrCurve> curves;        // for figure 2; kept only at outputs.pr_robots, run 0
  std::vector<FailoverRow> failover;  // sim: one per dropped robot (failover.csv)
  std::vector<BowRow> bow;            // bow_ strategies only (bow.csv)
  std::vector<BowSizeRow> bow_sizes;  // bow_ strategies only (bow_sizes.csv)
  std::vector<RadioRow> radio;        // sim on a radio variant only (radio.csv)
  std::vector<MediumRow> medium;      // sim on a contending variant only (medium.csv)
  std::vector<ConnectivityRow> connectivity;  // sim on a radio variant, when outputs.connectivity
  std::vector<ClosurePairRow> closure_pairs;  // sim and lcm (closure_pairs.csv)
};

using RunFunction = std::function<RunOutput(const RunSpec&)>;
using ProtocolFactory = std::function<RunFunction(const SharedInputs&)>;

}  // namespace dvpr

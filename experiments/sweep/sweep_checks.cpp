#include "experiments/sweep/sweep_checks.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include "agents/ids.h"
#include "experiments/protocols/strategy_inputs.h"
#include "experiments/strategies/run_routing.h"
#include "experiments/sweep/sweep.h"
#include "net_models/param_checks.h"

namespace dvpr {

namespace {

std::string Robots(const SweepConfig& sweep) {
  std::string s;
  for (const int n : sweep.robots) s += (s.empty() ? "" : ", ") + std::to_string(n);
  return s;
}

// Link overrides (and every other network parameter) hold for a team of n robots if they hold
// for the smallest: a pair lies in every larger team too.
void CheckNetworks(const ExperimentConfig& c, const std::string& origin) {
  if (std::find(c.sweep.protocols.begin(), c.sweep.protocols.end(), "sim") == c.sweep.protocols.end()) return;
  const int smallest = *std::min_element(c.sweep.robots.begin(), c.sweep.robots.end());
  for (const NetworkVariant& v : ExpandNetworks(c.network)) {
    try {
      ValidateNested("network.", [&] { v.params.Validate(smallest); });
    } catch (const std::invalid_argument& e) {
      throw ConfigError(origin + ": " + e.what() + " (robots: " + Robots(c.sweep) +
                        "; every team of the sweep runs the same network section)");
    }
  }
}

// A strategy that reads the training side: its name and index in `strategies`, for messages.
struct TrainingReader {
  std::size_t index = 0;
  const StrategySpec* spec = nullptr;
};

void CheckTrainingDescriptors(const SharedInputs& in, const TrainingReader& s, const TrainingUse& use,
                              const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  const std::string key = origin + ": strategies[" + std::to_string(s.index) + "]: '" + s.spec->name + "' ";
  if (!c.training.run_centroids.centroids_pattern.empty()) {
    if (use.descriptors) {
      throw ConfigError(key + "needs the training descriptors, but training.centroids replaces them "
                        "(drop the strategy or training.centroids)");
    }
    return;
  }
  const int largest = *std::max_element(c.sweep.robots.begin(), c.sweep.robots.end());
  const auto k = static_cast<Eigen::Index>(largest) * use.clusters_per_robot;
  if (in.training.rows() < k) {
    throw ConfigError(key + "clusters the training descriptors into k = " + std::to_string(k) + " (" +
                      std::to_string(largest) + " robots x " + std::to_string(use.clusters_per_robot) +
                      "), but there are only " + std::to_string(in.training.rows()));
  }
}

// Every centroid file the sweep will read, once per clusters-per-robot value.
void CheckCentroidFilesOf(const SharedInputs& in, const std::map<int, TrainingReader>& readers,
                          const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  for (const auto& [clusters, reader] : readers) {
    RunCentroidParams params = c.training.run_centroids;
    params.clusters_per_robot = clusters;
    const std::string strategy =
        clusters != c.training.run_centroids.clusters_per_robot ? " (strategy '" + reader.spec->name + "')" : "";
    try {
      CheckCentroidFiles(params, c.sweep.robots, c.sweep.runs, in.deployment.dim());
    } catch (const std::invalid_argument& e) {  // the file's shape or values
      throw ConfigError(origin + ": training.centroids: " + e.what() + strategy);
    } catch (const std::runtime_error& e) {  // the npy reader
      throw ConfigError(origin + ": training.centroids: " + e.what() + strategy);
    }
  }
}

void CheckStrategies(const SharedInputs& in, const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  const StrategyInputs strategy_inputs = StrategyInputsOf(in);
  std::map<int, TrainingReader> centroid_readers;  // by clusters per robot
  // A re-clustering leader sends its table in a centroid_table_t, whose k is an int16 (the paper
  // protocol evaluates the plan without messages).
  const int largest = *std::max_element(c.sweep.robots.begin(), c.sweep.robots.end());
  const bool sends = c.sweep.SendsMessages();
  for (std::size_t i = 0; i < c.sweep.strategies.size(); ++i) {
    const StrategySpec& spec = c.sweep.strategies[i];
    if (sends && spec.reclusters() && static_cast<std::int64_t>(largest) * spec.clusters_per_robot > kMaxWireInt16) {
      throw ConfigError(origin + ": strategies[" + std::to_string(i) + "]: '" + spec.name + "' sends tables of " +
                        std::to_string(static_cast<std::int64_t>(largest) * spec.clusters_per_robot) + " centroids (" +
                        std::to_string(largest) + " robots x " + std::to_string(spec.clusters_per_robot) +
                        "), but a centroid_table_t carries at most 32767 (its k is an int16 on the wire)");
    }
    const TrainingUse use = TrainingUseOf(spec, strategy_inputs);
    if (!use.run_centroids && !use.descriptors) continue;
    CheckTrainingDescriptors(in, TrainingReader{i, &spec}, use, origin);
    if (use.run_centroids) centroid_readers.try_emplace(use.clusters_per_robot, TrainingReader{i, &spec});
  }
  if (!c.training.run_centroids.centroids_pattern.empty()) CheckCentroidFilesOf(in, centroid_readers, origin);
}

// The bag-of-words strategies run in the static protocol and the simulation (docs/bow.md); a
// protocol registered besides them would not know them.
void CheckBowProtocols(const ExperimentConfig& c, const std::string& origin) {
  const auto& protocols = c.sweep.protocols;
  const auto other = std::find_if(protocols.begin(), protocols.end(),
                                  [](const std::string& p) { return p != "paper" && p != "sim"; });
  for (std::size_t i = 0; i < c.sweep.strategies.size() && other != protocols.end(); ++i) {
    const StrategySpec& s = c.sweep.strategies[i];
    if (s.bag_of_words()) {
      throw ConfigError(origin + ": strategies[" + std::to_string(i) + "]: '" + s.name + "' runs in the paper and " +
                        "sim protocols only, not in '" + *other + "'; see docs/bow.md");
    }
  }
}

}  // namespace

void CheckSweepInputs(const SharedInputs& inputs, const std::string& origin) {
  if (inputs.config == nullptr) throw std::invalid_argument("CheckSweepInputs: the shared inputs have no config");
  CheckBowProtocols(*inputs.config, origin);
  CheckNetworks(*inputs.config, origin);
  CheckStrategies(inputs, origin);
}

}  // namespace dvpr

#include "experiments/sweep/run_sweep.h"

#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/run_distributor.h"
#include "experiments/sweep/sweep.h"
#include "experiments/sweep/sweep_size.h"

namespace dvpr {

void RunSweep(const SharedInputs& inputs, const ProtocolRegistry& protocols,
              const ExecutorOptions& options, const RunConsumer& consume) {
  const ExperimentConfig& config = *inputs.config;
  std::map<std::string, RunFunction> run_functions;
  for (const std::string& p : config.sweep.protocols) {
    const ProtocolFactory* factory = protocols.Find(p);
    if (factory == nullptr) throw std::invalid_argument("RunSweep: no protocol '" + p + "'");
    // The static evaluation's centralized search of every frame takes seconds on KITTI 00;
    // the other protocols' factories take no time worth a line.
    if (options.phase && TraitsOf(p).static_evaluation) {
      options.phase(p + ": the centralized search of every frame (relative_auc's reference), once for all runs");
    }
    run_functions[p] = (*factory)(inputs);
  }
  const std::vector<NetworkVariant> networks = ExpandNetworks(config.network);
  const std::vector<RunSpec> specs = ExpandSweep(config, networks);
  ExecutorOptions weighed = options;  // the progress's estimate weighs each run by the sweep-size model
  if (weighed.progress && weighed.run_seconds.empty()) weighed.run_seconds = RunSeconds(config, inputs.deployment, specs);
  if (options.distributor != nullptr) {
    options.distributor->Execute(specs, run_functions, inputs.out_dir, consume, weighed);
  } else {
    ExecuteRuns(specs, run_functions, consume, weighed);
  }
}

std::vector<RunOutput> RunSweepInMemory(const SharedInputs& inputs, const ExecutorOptions& options) {
  std::vector<RunOutput> outputs;
  RunSweep(inputs, BuiltinProtocols(), options,
           [&outputs](const RunSpec&, RunOutput&& out) { outputs.push_back(std::move(out)); });
  return outputs;
}

}  // namespace dvpr

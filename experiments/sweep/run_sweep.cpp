#include "experiments/sweep/run_sweep.h"

#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "experiments/sweep/run_distributor.h"
#include "experiments/sweep/sweep.h"

namespace dvpr {

void RunSweep(const SharedInputs& inputs, const ProtocolRegistry& protocols,
              const ExecutorOptions& options, const RunConsumer& consume) {
  const ExperimentConfig& config = *inputs.config;
  std::map<std::string, RunFunction> run_functions;
  for (const std::string& p : config.sweep.protocols) {
    const ProtocolFactory* factory = protocols.Find(p);
    if (factory == nullptr) throw std::invalid_argument("RunSweep: no protocol '" + p + "'");
    run_functions[p] = (*factory)(inputs);
  }
  const std::vector<NetworkVariant> networks = ExpandNetworks(config.network);
  const std::vector<RunSpec> specs = ExpandSweep(config, networks);
  if (options.distributor != nullptr) {
    options.distributor->Execute(specs, run_functions, inputs.out_dir, consume, options);
  } else {
    ExecuteRuns(specs, run_functions, consume, options);
  }
}

std::vector<RunOutput> RunSweepInMemory(const SharedInputs& inputs, const ExecutorOptions& options) {
  std::vector<RunOutput> outputs;
  RunSweep(inputs, BuiltinProtocols(), options,
           [&outputs](const RunSpec&, RunOutput&& out) { outputs.push_back(std::move(out)); });
  return outputs;
}

}  // namespace dvpr

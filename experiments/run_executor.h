#pragma once
// Runs the specs of a sweep on all cores and hands the outputs on in spec order, so everything
// written is identical to a serial run whatever the thread count.
//
// Protocols plug in through a ProtocolRegistry: a factory gets the inputs shared by all runs
// (deployment data, training descriptors, the config), does its one-off work (e.g. the
// centralized AUC of the paper protocol) and returns a RunFunction, which is then called from
// several threads at once (it must be safe for that: const state only, or its own locking).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "agents/descriptors.h"
#include "experiments/config.h"
#include "experiments/dataset.h"
#include "experiments/results.h"
#include "experiments/sweep.h"

namespace dvpr {

// What every run reads; loaded once before the first run (experiments/inputs.h).
struct SharedInputs {
  const ExperimentConfig* config = nullptr;
  Dataset deployment;
  DescriptorMatrix training;           // empty when training.centroids gives the centroids
  std::filesystem::path out_dir;       // centroids go to out_dir/centroids/
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
};

using RunFunction = std::function<RunOutput(const RunSpec&)>;
using ProtocolFactory = std::function<RunFunction(const SharedInputs&)>;

class ProtocolRegistry {
 public:
  void Add(const std::string& name, ProtocolFactory factory);
  const ProtocolFactory* Find(const std::string& name) const;
  std::vector<std::string> Names() const;

 private:
  std::map<std::string, ProtocolFactory> factories_;
};

// The protocols built into this dvpr (experiments/protocols.cpp).
ProtocolRegistry BuiltinProtocols();

struct ExecutorOptions {
  int threads = 0;          // 0: all cores
  bool progress = true;     // runs done/total, elapsed, estimate on stderr
};

// Calls run_functions.at(spec.protocol)(spec) for every spec, on worker threads, and consume()
// on the calling thread in spec order as soon as each output and all before it are done (so
// memory holds only the outputs waiting for a slower earlier run). The first exception (from a
// run, with the run named, or from consume) stops new runs and is rethrown after the workers
// have joined.
void ExecuteRuns(const std::vector<RunSpec>& specs,
                 const std::map<std::string, RunFunction>& run_functions,
                 const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                 const ExecutorOptions& options = {});

// "paper n=5 run 3" / "sim point_to_point 10Mbps 2ms n=5 run 3", for messages.
std::string Describe(const RunSpec& spec);

}  // namespace dvpr

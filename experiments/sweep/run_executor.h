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

#include "agents/algorithms/descriptors.h"
#include "experiments/config/config.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/results/results.h"
#include "experiments/sweep/sweep.h"

namespace dvpr {

class ProtocolRegistry {
 public:
  // `name` must have traits (TraitsOf, experiments/results/protocol_traits.h); std::invalid_argument if not.
  void Add(const std::string& name, ProtocolFactory factory);
  const ProtocolFactory* Find(const std::string& name) const;
  std::vector<std::string> Names() const;

 private:
  std::map<std::string, ProtocolFactory> factories_;
};

// The protocols built into this dvpr (experiments/sweep/builtin_protocols.cpp).
ProtocolRegistry BuiltinProtocols();

class RunDistributor;  // experiments/sweep/run_distributor.h

struct ExecutorOptions {
  int threads = 0;          // 0: all cores
  bool progress = true;     // runs done/total, elapsed, estimate on stderr
  // Spreads the runs over several processes (MPI ranks: experiments/mpi/); null runs them all
  // in this one (ExecuteRuns).
  const RunDistributor* distributor = nullptr;
  // dvpr run --allow-large: run a sweep CheckSweepSize (sweep_size.h) would refuse.
  bool allow_large = false;
  // The modelled cost of each spec, by index (RunSeconds, sweep_size.h), which the progress's
  // estimate weighs the runs done and left by; empty: every run alike. RunSweep fills it.
  std::vector<double> run_seconds = {};
  // Told as a step of the sweep other than its runs starts (a protocol's work done once for all
  // its runs, RunSweep), for the progress; empty: not told.
  std::function<void(const std::string& what)> phase = {};
};

// Calls run_functions.at(spec.protocol)(spec) for every spec on the ParallelFor pool
// (experiments/domain/parallel/parallel_for_in_order.h), and consume() in spec order as soon as each
// output and all before it are done (so memory holds only the outputs waiting for a slower
// earlier run); consume is never called on two threads at once. The progress counts a run as it
// finishes, in whatever order. The first exception (from a
// run, with the run named, or from consume) stops new runs and is rethrown after the workers
// have joined.
void ExecuteRuns(const std::vector<RunSpec>& specs,
                 const std::map<std::string, RunFunction>& run_functions,
                 const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                 const ExecutorOptions& options = {});

// options.run_seconds when it has a cost for each spec, else 1 for each (the progress's weights).
std::vector<double> RunCosts(const std::vector<RunSpec>& specs, const ExecutorOptions& options);

// "paper n=5 run 3" / "sim point_to_point 10Mbps 2ms n=5 run 3", for messages.
std::string Describe(const RunSpec& spec);

}  // namespace dvpr

#pragma once
// The one driver of a config's sweep: `dvpr run` (experiments/app/experiment.cpp) hands its
// outputs to the result files, the tests and benchmarks keep them in memory; both go through
// RunSweep, so what the tests check (e.g. the paper protocol against the numpy implementation in
// tests/tools/paper_eval.py) is what users run.
#include <functional>
#include <vector>

#include "experiments/protocols/run.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

using RunConsumer = std::function<void(const RunSpec&, RunOutput&&)>;

// Expands inputs.config's sweep (ExpandSweep), makes the run function of each of its protocols
// from `protocols` (once, with `inputs`), runs every spec (ExecuteRuns) and hands each output to
// consume in spec order (with options.distributor, this process's part of a sweep spread over
// several: run_distributor.h). Throws std::invalid_argument when a protocol is not in `protocols`.
void RunSweep(const SharedInputs& inputs, const ProtocolRegistry& protocols,
              const ExecutorOptions& options, const RunConsumer& consume);

// RunSweep with the built-in protocols, the outputs kept in spec order.
std::vector<RunOutput> RunSweepInMemory(const SharedInputs& inputs,
                                        const ExecutorOptions& options = {.threads = 0, .progress = false});

}  // namespace dvpr

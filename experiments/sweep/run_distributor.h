#pragma once
// How a sweep's runs are spread over several processes, e.g. the ranks of an MPI job
// (experiments/mpi/mpi_run_distributor.h). Every process expands the same config into the same
// specs and calls RunSweep; the distributor decides which process runs which spec. Exactly one
// process writes the results: it gets every output through `consume`, in spec order as
// ExecuteRuns hands them on, and the files the others' runs wrote into their run_folder() land
// under its own out_dir, so its result folder is the one a single process writes.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "experiments/protocols/run.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

class RunDistributor {
 public:
  virtual ~RunDistributor() = default;

  // True in the one process that writes the result folder.
  virtual bool writes_results() const = 0;
  // Where the runs of a process that does not write the results write their files
  // (SharedInputs::out_dir there); the distributor hands them to the one that does.
  virtual const std::filesystem::path& run_folder() const = 0;

  // This process's part of the sweep: runs its share of `specs` (ExecuteRuns' contract for the
  // run functions) and, in the writing process, calls consume for every spec in spec order and
  // puts the other processes' files under out_dir. A failed run anywhere throws here in the
  // writing process, its message naming the run and the process.
  virtual void Execute(const std::vector<RunSpec>& specs,
                       const std::map<std::string, RunFunction>& run_functions,
                       const std::filesystem::path& out_dir,
                       const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                       const ExecutorOptions& options) const = 0;
};

}  // namespace dvpr

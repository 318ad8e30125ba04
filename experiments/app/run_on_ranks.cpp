#include "experiments/app/run_on_ranks.h"

#include <exception>
#include <iostream>
#include <sstream>

#include "experiments/app/cli.h"
#include "experiments/mpi/mpi_run_distributor.h"

namespace dvpr {

int RunOnRanks(const MpiWorld& world, ExecutorOptions options,
               const std::function<int(const ExecutorOptions&, std::ostream&)>& run, std::ostream& out,
               std::ostream& err) {
  int status = kExitOk;
  {
    const MpiRunDistributor distributor(world);
    options.distributor = &distributor;
    options.threads = ThreadsPerRank(world, options.threads);
    options.progress = options.progress && world.rank() == 0;
    std::ostringstream unused;  // the summary table is rank 0's
    try {
      status = run(options, world.rank() == 0 ? out : unused);
    } catch (...) {
      distributor.ReportFailure(std::current_exception());  // returns on rank 0 (and when too late)
      status = ReportError(std::current_exception(), err);
    }
  }
  if (status != kExitOk) {
    out.flush();
    err.flush();
    world.Abort(status);
  }
  return status;
}

}  // namespace dvpr

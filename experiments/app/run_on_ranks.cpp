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
  bool clean_stop = false;
  {
    const MpiRunDistributor distributor(world);
    options.distributor = &distributor;
    options.threads = ThreadsPerRank(world, options.threads);
    options.progress = options.progress && world.rank() == 0;
    std::ostringstream unused;  // the summary table is rank 0's
    try {
      status = run(options, world.rank() == 0 ? out : unused);
    } catch (...) {
      std::exception_ptr error = std::current_exception();
      if (!distributor.agreed()) {  // failed before the runs: the other ranks learn it collectively
        try {
          distributor.AgreeBeforeStart(error);
        } catch (...) {
          error = std::current_exception();
        }
      }
      if (distributor.stopped_before_start()) {
        // Every rank stops here: rank 0 says it once and returns the status, the others return 0
        // silently (a non-zero status from one of them makes the launcher end rank 0, perhaps
        // before its line is out; the job's status is rank 0's), and nobody aborts (MPI_Abort's
        // text would follow the error line).
        clean_stop = true;
        std::ostringstream silent;
        status = ReportError(error, world.rank() == 0 ? err : silent);
        if (world.rank() != 0) status = kExitOk;
      } else {
        distributor.ReportFailure(error);  // returns on rank 0 (and when too late)
        status = ReportError(error, err);
      }
    }
  }
  if (status != kExitOk && !clean_stop) {
    out.flush();
    err.flush();
    world.Abort(status);
  }
  return status;
}

}  // namespace dvpr

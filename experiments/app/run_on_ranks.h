#pragma once
// `dvpr run` as one rank of an MPI job (mpirun -n K, srun): the sweep's runs spread over the
// ranks (experiments/mpi/mpi_run_distributor.h), rank 0 writing the result folder and the
// summary, the others nothing. A failure anywhere is reported once, by rank 0, with the exit
// status a single process would have (cli.h), and then ends every rank (MPI_Abort): no rank is
// left waiting for another.
#include <functional>
#include <ostream>

#include "experiments/mpi/mpi_world.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

// Runs `run(options, out)` on this rank with options.distributor set and each rank's threads
// from ThreadsPerRank; returns its status on success (0) and does not return on failure.
int RunOnRanks(const MpiWorld& world, ExecutorOptions options,
               const std::function<int(const ExecutorOptions&, std::ostream&)>& run, std::ostream& out,
               std::ostream& err);

}  // namespace dvpr

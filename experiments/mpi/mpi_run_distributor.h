#pragma once
// A sweep spread over the ranks of an MPI job (`mpirun -n K dvpr run CONFIG`, `srun dvpr run
// CONFIG`). Spec i runs on rank i mod K (each rank on its own pool of threads); ranks 1..K-1
// send each output to rank 0 as it is done, then the files their runs wrote (centroids, LCM
// logs) and "done"; rank 0 runs its own share meanwhile and hands every output on in spec order,
// so it writes the result folder a single process writes, byte for byte. The others write
// nothing of it (their runs write into a temporary run folder, removed at the end).
//
// A failure before the runs start (a config error, which every rank finds, or a rank's own)
// stops every rank cleanly: each passes AgreeBeforeStart once (at Execute's start, or where it
// failed), rank 0 reports the first failed rank's error as the one error line, and every rank
// returns its exit status, with no MPI_Abort (whose text Open MPI prints).
// A failure on any rank once the runs started ends the sweep: a rank whose run failed sends
// the error to rank 0 and waits; rank 0 throws it, naming the run and the rank, its result
// folder is removed as for any failed run, and the job is aborted (RunOnRanks in
// experiments/app/). A rank that dies is noticed by the launcher, which ends the others (rank 0
// then removes its temporary folder on SIGTERM: termination_cleanup.h); the run folder of a
// killed rank is removed by the next job's ranks.
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "experiments/mpi/mpi_world.h"
#include "experiments/sweep/run_distributor.h"

namespace dvpr {

class MpiRunDistributor final : public RunDistributor {
 public:
  // Ranks other than 0 create their run folder (in the system's temporary folder); every rank
  // first removes those that killed ranks of earlier jobs on this machine left there.
  explicit MpiRunDistributor(const MpiWorld& world);
  ~MpiRunDistributor() override;
  MpiRunDistributor(const MpiRunDistributor&) = delete;
  MpiRunDistributor& operator=(const MpiRunDistributor&) = delete;

  bool writes_results() const override { return world_.rank() == 0; }
  const std::filesystem::path& run_folder() const override { return run_folder_; }
  void Execute(const std::vector<RunSpec>& specs, const std::map<std::string, RunFunction>& run_functions,
               const std::filesystem::path& out_dir,
               const std::function<void(const RunSpec&, RunOutput&&)>& consume,
               const ExecutorOptions& options) const override;

  // On a rank other than 0: sends `error` to rank 0 and waits for rank 0 to report it and abort
  // the job; never returns then. Returns at once, having sent nothing, when this rank has told
  // rank 0 it is done (rank 0 may have finished): the caller then reports and aborts itself.
  void ReportFailure(std::exception_ptr error) const;

  // The ranks agree whether any failed before the runs start; every rank calls it exactly once:
  // Execute calls it with nullptr, a rank that fails before Execute with its error. Returns when
  // none failed. Else throws: on rank 0 the error to report (its own, or the first failed rank's,
  // named "rank r of K: ..."), on the others RanksStoppedBeforeStart (rank 0 reports).
  void AgreeBeforeStart(std::exception_ptr error) const;
  bool agreed() const { return agreed_; }
  bool stopped_before_start() const { return stopped_before_start_; }

 private:
  void Gather(const std::vector<RunSpec>& specs, const std::map<std::string, RunFunction>& run_functions,
              const std::filesystem::path& out_dir,
              const std::function<void(const RunSpec&, RunOutput&&)>& consume,
              const ExecutorOptions& options) const;
  void Contribute(const std::vector<RunSpec>& specs, const std::map<std::string, RunFunction>& run_functions,
                  const ExecutorOptions& options) const;
  std::vector<RunSpec> Share(const std::vector<RunSpec>& specs) const;

  void SendRunFiles() const;

  const MpiWorld& world_;
  std::filesystem::path run_folder_;  // empty on rank 0
  mutable bool sent_done_ = false;
  mutable bool agreed_ = false;
  mutable bool stopped_before_start_ = false;
};

// What AgreeBeforeStart throws on a rank other than 0 when a rank failed before the runs: that
// rank's error is rank 0's to report; this one ends with exit status 1 and says nothing.
struct RanksStoppedBeforeStart : std::runtime_error {
  RanksStoppedBeforeStart() : std::runtime_error("a rank failed before the runs started (rank 0 reports it)") {}
};

// The threads of each rank's pool: `requested` when given (--threads); else the cores the rank
// is bound to, if the launcher bound it; else this machine's cores shared among its ranks.
int ThreadsPerRank(const MpiWorld& world, int requested);

// This machine's cores (at least 1), and those this process may run on (its affinity).
int MachineCores();
int BoundCores();

// A note for the user when the launcher bound the ranks on this machine to fewer cores than it
// has (Open MPI binds each rank to one core by default for -n 1 and 2: `mpirun -n 1 dvpr run`
// then takes twice as long as `dvpr run` on 2 cores); empty when they can use them all.
std::string BoundCoresNote(int machine_cores, int bound_cores, int local_ranks);

}  // namespace dvpr

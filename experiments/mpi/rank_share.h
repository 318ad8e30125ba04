#pragma once
// This rank's share of a distributed sweep, run on a thread of its own (ExecuteRuns on its
// pool) while the rank's main thread talks MPI: the outputs queue up here, in spec order, until
// the main thread takes them.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "experiments/mpi/rank_messages.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

class RankShare {
 public:
  // Starts running `specs` (this rank's share, in spec order).
  RankShare(std::vector<RunSpec> specs, const std::map<std::string, RunFunction>& run_functions,
            const ExecutorOptions& options);
  // Starts no new run, waits for those running and joins.
  ~RankShare();
  RankShare(const RankShare&) = delete;
  RankShare& operator=(const RankShare&) = delete;

  // The next output, waiting up to `wait` for it; nullopt when none came in time or all have
  // been taken (finished()). When the share has failed, throws its error (ExecuteRuns': the run
  // is named) once the outputs before it have been taken.
  std::optional<IndexedOutput> Next(std::chrono::milliseconds wait);
  // Every output has been taken.
  bool finished();

 private:
  void Work(const std::map<std::string, RunFunction>& run_functions, ExecutorOptions options);

  std::vector<RunSpec> specs_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<IndexedOutput> outputs_;
  bool done_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once everything above exists
};

}  // namespace dvpr

#include "experiments/mpi/rank_share.h"

#include <stdexcept>
#include <utility>

namespace dvpr {

RankShare::RankShare(std::vector<RunSpec> specs, const std::map<std::string, RunFunction>& run_functions,
                     const ExecutorOptions& options)
    : specs_(std::move(specs)), thread_([this, &run_functions, options] { Work(run_functions, options); }) {}

RankShare::~RankShare() {
  stop_ = true;
  thread_.join();
}

void RankShare::Work(const std::map<std::string, RunFunction>& run_functions, ExecutorOptions options) {
  // Each run function checks the stop flag first, so a failing job waits only for the runs
  // already running, not for the whole share.
  std::map<std::string, RunFunction> stoppable;
  for (const auto& [name, fn] : run_functions) {
    stoppable[name] = [this, &fn](const RunSpec& spec) {
      if (stop_) throw std::runtime_error("stopped: the sweep failed elsewhere");
      return fn(spec);
    };
  }
  options.distributor = nullptr;
  options.progress = false;
  std::exception_ptr error;
  try {
    ExecuteRuns(specs_, stoppable, [this](const RunSpec& spec, RunOutput&& out) {
      const std::lock_guard lock(mutex_);
      outputs_.push_back(IndexedOutput{spec.index, std::move(out)});
      ready_.notify_one();
    }, options);
  } catch (...) {
    error = std::current_exception();
  }
  const std::lock_guard lock(mutex_);
  done_ = true;
  error_ = error;
  ready_.notify_one();
}

std::optional<IndexedOutput> RankShare::Next(std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, wait, [this] { return !outputs_.empty() || done_; });
  if (!outputs_.empty()) {
    IndexedOutput out = std::move(outputs_.front());
    outputs_.pop_front();
    return out;
  }
  if (done_ && error_) std::rethrow_exception(std::exchange(error_, nullptr));
  return std::nullopt;
}

bool RankShare::finished() {
  const std::lock_guard lock(mutex_);
  return done_ && outputs_.empty() && !error_;
}

}  // namespace dvpr

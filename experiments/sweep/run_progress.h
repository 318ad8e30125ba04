#pragma once
// The sweep's progress on stderr: a rewritten line on a terminal, else the first item, a line every
// 10% and at least one a minute (logs stay short, the first line gives an estimate early, and a
// long run never goes quiet for long). Used by ExecuteRuns,
// by the rank that gathers a distributed sweep, for the synthetic BoW world's frames and for the
// figures `dvpr run` draws; PhaseLog names the long steps between them.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace dvpr {

using ProgressClock = std::function<std::chrono::steady_clock::time_point()>;

// What is left of items of unequal cost, some done in any order: elapsed x (cost of the items
// not done) / (cost of those done). With the costs of the sweep-size model (RunSeconds,
// sweep_size.h), a sweep whose larger teams run last is not estimated from its small ones as if
// every run took as long (issue 48: 12 s of estimate for a 93 s sweep). Equal costs give
// elapsed / done x remaining, the estimate before; when the items done cost nothing by the model,
// their count stands in for it.
class RemainingTime {
 public:
  explicit RemainingTime(std::vector<double> costs);
  // Item `index` is done (again: no change).
  void Finish(std::size_t index);
  std::size_t total() const { return costs_.size(); }
  std::size_t done() const { return done_; }
  // Seconds still to go, `elapsed_s` after the first item started.
  double Estimate(double elapsed_s) const;

 private:
  std::vector<double> costs_;
  std::vector<bool> finished_;
  std::size_t done_ = 0;
  double done_cost_ = 0;
  double total_cost_ = 0;
};

class RunProgress {
 public:
  // `what` names the items: "runs 3/760  elapsed ..."; the time elapsed counts from `start`.
  // Items of equal cost.
  RunProgress(std::size_t total, bool enabled, std::string what = "runs",
              std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());
  // Items of the given costs (any unit: only their ratios count), read from `now`, written to `out`.
  RunProgress(std::vector<double> costs, bool enabled, std::string what,
              std::chrono::steady_clock::time_point start, ProgressClock now = std::chrono::steady_clock::now,
              std::FILE* out = stderr);
  // The first `done` items of `total` have been handed on.
  void Done(std::size_t done);
  // Item `index` is done, whichever others are; safe to call from several threads at once.
  void Finished(std::size_t index);

 private:
  void Show();  // with mutex_ held

  std::mutex mutex_;
  RemainingTime remaining_;
  bool enabled_;
  std::FILE* out_;
  bool tty_;
  std::string what_;
  ProgressClock now_;
  std::size_t handed_on_ = 0;  // Done's items so far
  std::size_t last_decile_ = 0;
  bool first_ = true;
  std::chrono::steady_clock::time_point start_;
  double last_shown_ = 0;  // seconds after start_
};

// A line on stderr as each long step of `dvpr run` that is not a run starts, "inputs: describing
// the deployment (4541 frames)  elapsed 0.3s" (elapsed since `start`), so that no step of a few
// seconds goes by without a word. Off (nothing written) when the progress is (--quiet).
class PhaseLog {
 public:
  explicit PhaseLog(bool enabled, std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(),
                    ProgressClock now = std::chrono::steady_clock::now, std::FILE* out = stderr);
  void Start(const std::string& what) const;
  bool enabled() const { return enabled_; }
  std::chrono::steady_clock::time_point start() const { return start_; }

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  ProgressClock now_;
  std::FILE* out_;
};

}  // namespace dvpr

#pragma once
// The sweep's progress on stderr: a rewritten line on a terminal, else the first item, a line every
// 10% and at least one a minute (logs stay short, the first line gives an estimate early, and a
// long run never goes quiet for long). Used by ExecuteRuns,
// by the rank that gathers a distributed sweep, and for the synthetic BoW world's frames.
#include <chrono>
#include <cstddef>
#include <string>

namespace dvpr {

class RunProgress {
 public:
  // `what` names the items: "runs 3/760  elapsed ..."; the time elapsed counts from `start`.
  RunProgress(std::size_t total, bool enabled, std::string what = "runs",
              std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());
  // `done` runs of `total` have been handed on.
  void Done(std::size_t done);

 private:
  std::size_t total_;
  bool enabled_;
  bool tty_;
  std::string what_;
  std::size_t last_decile_ = 0;
  bool first_ = true;
  std::chrono::steady_clock::time_point start_;
  double last_shown_ = 0;  // seconds after start_
};

}  // namespace dvpr

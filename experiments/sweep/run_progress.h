#pragma once
// The sweep's progress on stderr: a rewritten line on a terminal, else a line every 10% (logs
// stay short). Used by ExecuteRuns and by the rank that gathers a distributed sweep.
#include <chrono>
#include <cstddef>

namespace dvpr {

class RunProgress {
 public:
  RunProgress(std::size_t total, bool enabled);
  // `done` runs of `total` have been handed on.
  void Done(std::size_t done);

 private:
  std::size_t total_;
  bool enabled_;
  bool tty_;
  std::size_t last_decile_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace dvpr

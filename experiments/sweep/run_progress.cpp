#include "experiments/sweep/run_progress.h"

#include <unistd.h>

#include <cstdio>

namespace dvpr {

RunProgress::RunProgress(std::size_t total, bool enabled)
    : total_(total), enabled_(enabled && total > 0), tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

void RunProgress::Done(std::size_t done) {
  if (!enabled_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::size_t decile = done * 10 / total_;
  if (!tty_ && decile == last_decile_ && done != total_) return;
  last_decile_ = decile;
  const double eta = elapsed / static_cast<double>(done) * static_cast<double>(total_ - done);
  std::fprintf(stderr, "%sruns %zu/%zu  elapsed %.1fs  eta %.1fs%s", tty_ ? "\r" : "", done,
               total_, elapsed, eta, tty_ && done != total_ ? "\033[K" : "\n");
  std::fflush(stderr);
}

}  // namespace dvpr

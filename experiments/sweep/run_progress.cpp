#include "experiments/sweep/run_progress.h"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace dvpr {

RunProgress::RunProgress(std::size_t total, bool enabled, std::string what,
                         std::chrono::steady_clock::time_point start)
    : total_(total), enabled_(enabled && total > 0), tty_(isatty(STDERR_FILENO) != 0), what_(std::move(what)),
      start_(start) {}

void RunProgress::Done(std::size_t done) {
  if (!enabled_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::size_t decile = done * 10 / total_;
  if (!tty_ && !first_ && decile == last_decile_ && done != total_ && elapsed - last_shown_ < 60) return;
  first_ = false;
  last_shown_ = elapsed;
  last_decile_ = decile;
  const double eta = elapsed / static_cast<double>(done) * static_cast<double>(total_ - done);
  std::fprintf(stderr, "%s%s %zu/%zu  elapsed %.1fs  eta %.1fs%s", tty_ ? "\r" : "", what_.c_str(), done,
               total_, elapsed, eta, tty_ && done != total_ ? "\033[K" : "\n");
  std::fflush(stderr);
}

}  // namespace dvpr

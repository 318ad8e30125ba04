#include "experiments/sweep/run_progress.h"

#include <unistd.h>

#include <numeric>
#include <stdexcept>
#include <utility>

namespace dvpr {

RemainingTime::RemainingTime(std::vector<double> costs)
    : costs_(std::move(costs)), finished_(costs_.size(), false),
      total_cost_(std::accumulate(costs_.begin(), costs_.end(), 0.0)) {
  for (const double c : costs_) {
    if (!(c >= 0)) throw std::invalid_argument("RemainingTime: a cost is negative or NaN");
  }
}

void RemainingTime::Finish(std::size_t index) {
  if (index >= costs_.size()) throw std::out_of_range("RemainingTime: item " + std::to_string(index) + " of " +
                                                      std::to_string(costs_.size()));
  if (finished_[index]) return;
  finished_[index] = true;
  ++done_;
  done_cost_ += costs_[index];
}

double RemainingTime::Estimate(double elapsed_s) const {
  if (done_ == 0) return 0;
  if (done_cost_ > 0) return elapsed_s * (total_cost_ - done_cost_) / done_cost_;
  return elapsed_s / static_cast<double>(done_) * static_cast<double>(costs_.size() - done_);
}

RunProgress::RunProgress(std::size_t total, bool enabled, std::string what,
                         std::chrono::steady_clock::time_point start)
    : RunProgress(std::vector<double>(total, 1.0), enabled, std::move(what), start) {}

RunProgress::RunProgress(std::vector<double> costs, bool enabled, std::string what,
                         std::chrono::steady_clock::time_point start, ProgressClock now, std::FILE* out)
    : remaining_(std::move(costs)), enabled_(enabled && remaining_.total() > 0), out_(out),
      tty_(isatty(fileno(out)) != 0), what_(std::move(what)), now_(std::move(now)), start_(start) {}

void RunProgress::Done(std::size_t done) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  for (; handed_on_ < done && handed_on_ < remaining_.total(); ++handed_on_) remaining_.Finish(handed_on_);
  Show();
}

void RunProgress::Finished(std::size_t index) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  remaining_.Finish(index);
  Show();
}

void RunProgress::Show() {
  const std::size_t done = remaining_.done(), total = remaining_.total();
  const double elapsed = std::chrono::duration<double>(now_() - start_).count();
  const std::size_t decile = done * 10 / total;
  if (!tty_ && !first_ && decile == last_decile_ && done != total && elapsed - last_shown_ < 60) return;
  first_ = false;
  last_shown_ = elapsed;
  last_decile_ = decile;
  std::fprintf(out_, "%s%s %zu/%zu  elapsed %.1fs  eta %.1fs%s", tty_ ? "\r" : "", what_.c_str(), done, total,
               elapsed, remaining_.Estimate(elapsed), tty_ && done != total ? "\033[K" : "\n");
  std::fflush(out_);
}

PhaseLog::PhaseLog(bool enabled, std::chrono::steady_clock::time_point start, ProgressClock now, std::FILE* out)
    : enabled_(enabled), start_(start), now_(std::move(now)), out_(out) {}

void PhaseLog::Start(const std::string& what) const {
  if (!enabled_) return;
  const double elapsed = std::chrono::duration<double>(now_() - start_).count();
  std::fprintf(out_, "%s  elapsed %.1fs\n", what.c_str(), elapsed);
  std::fflush(out_);
}

}  // namespace dvpr

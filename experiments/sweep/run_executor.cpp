#include "experiments/sweep/run_executor.h"

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "experiments/parallel/parallel_for_in_order.h"

namespace dvpr {

void ProtocolRegistry::Add(const std::string& name, ProtocolFactory factory) {
  factories_[name] = std::move(factory);
}

const ProtocolFactory* ProtocolRegistry::Find(const std::string& name) const {
  const auto it = factories_.find(name);
  return it == factories_.end() ? nullptr : &it->second;
}

std::vector<std::string> ProtocolRegistry::Names() const {
  std::vector<std::string> names;
  for (const auto& [name, f] : factories_) names.push_back(name);
  return names;
}

std::string Describe(const RunSpec& spec) {
  std::string s = spec.protocol;
  if (spec.network != nullptr) s += " " + spec.network->name;
  return s + " n=" + std::to_string(spec.robots) + " run " + std::to_string(spec.run);
}

namespace {

// Progress on stderr: a rewritten line on a terminal, else a line every 10% (logs stay short).
class Progress {
 public:
  Progress(std::size_t total, bool enabled)
      : total_(total), enabled_(enabled && total > 0), tty_(isatty(STDERR_FILENO) != 0),
        start_(std::chrono::steady_clock::now()) {}

  void Done(std::size_t done) {
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

 private:
  std::size_t total_;
  bool enabled_;
  bool tty_;
  std::size_t last_decile_ = 0;
  std::chrono::steady_clock::time_point start_;
};

// Runs one spec; an error names the run.
RunOutput RunOne(const RunSpec& spec, const std::map<std::string, RunFunction>& fns) {
  const auto fn = fns.find(spec.protocol);
  if (fn == fns.end()) throw std::logic_error("no run function for " + spec.protocol);
  // The message gains the run's name; the type stays, so a bug (std::logic_error) is still
  // told apart from an input error (dvpr's exit status 3, not 1).
  const std::string run = "run " + Describe(spec) + ": ";
  try {
    return fn->second(spec);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(run + e.what());
  } catch (const std::logic_error& e) {
    throw std::logic_error(run + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(run + e.what());
  }
}

}  // namespace

void ExecuteRuns(const std::vector<RunSpec>& specs,
                 const std::map<std::string, RunFunction>& run_functions,
                 const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                 const ExecutorOptions& options) {
  Progress progress(specs.size(), options.progress);
  ParallelForInOrder(
      static_cast<std::int64_t>(specs.size()), options.threads,
      [&](std::int64_t i) { return RunOne(specs[static_cast<std::size_t>(i)], run_functions); },
      [&](std::int64_t i, RunOutput&& out) {
        consume(specs[static_cast<std::size_t>(i)], std::move(out));
        progress.Done(static_cast<std::size_t>(i) + 1);
      });
}

}  // namespace dvpr

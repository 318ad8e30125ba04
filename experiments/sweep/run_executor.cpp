#include "experiments/sweep/run_executor.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

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

// The slots where workers put finished outputs, and the signal for the consuming thread.
struct Slots {
  std::mutex mutex;
  std::condition_variable ready;
  std::vector<std::optional<RunOutput>> outputs;
  std::exception_ptr error;
  std::atomic<bool> stop{false};
};

void Work(const std::vector<RunSpec>& specs, const std::map<std::string, RunFunction>& fns,
          std::atomic<std::size_t>& next, Slots& slots) {
  while (!slots.stop) {
    const std::size_t i = next++;
    if (i >= specs.size()) return;
    try {
      const auto fn = fns.find(specs[i].protocol);
      if (fn == fns.end()) throw std::logic_error("no run function for " + specs[i].protocol);
      RunOutput out = fn->second(specs[i]);
      std::lock_guard lock(slots.mutex);
      slots.outputs[i] = std::move(out);
    } catch (const std::exception& e) {
      std::lock_guard lock(slots.mutex);
      if (!slots.error) {
        slots.error = std::make_exception_ptr(
            std::runtime_error("run " + Describe(specs[i]) + ": " + e.what()));
      }
      slots.stop = true;
    }
    slots.ready.notify_all();
  }
}

}  // namespace

void ExecuteRuns(const std::vector<RunSpec>& specs,
                 const std::map<std::string, RunFunction>& run_functions,
                 const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                 const ExecutorOptions& options) {
  Slots slots;
  slots.outputs.resize(specs.size());
  std::atomic<std::size_t> next{0};
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t workers = std::min<std::size_t>(
      options.threads > 0 ? static_cast<std::size_t>(options.threads) : cores, specs.size());
  std::vector<std::jthread> threads;
  for (std::size_t t = 0; t < workers; ++t) {
    threads.emplace_back([&] { Work(specs, run_functions, next, slots); });
  }
  Progress progress(specs.size(), options.progress);
  for (std::size_t i = 0; i < specs.size(); ++i) {
    RunOutput out;
    {
      std::unique_lock lock(slots.mutex);
      slots.ready.wait(lock, [&] { return slots.outputs[i].has_value() || slots.error; });
      if (slots.error) break;
      out = std::move(*slots.outputs[i]);
      slots.outputs[i].reset();
    }
    try {
      consume(specs[i], std::move(out));
    } catch (...) {
      std::lock_guard lock(slots.mutex);
      slots.error = std::current_exception();
      slots.stop = true;
      break;
    }
    progress.Done(i + 1);
  }
  threads.clear();  // joins
  if (slots.error) std::rethrow_exception(slots.error);
}

}  // namespace dvpr

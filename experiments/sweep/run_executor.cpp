#include "experiments/sweep/run_executor.h"

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "experiments/domain/parallel/parallel_for_in_order.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/run_progress.h"

namespace dvpr {

void ProtocolRegistry::Add(const std::string& name, ProtocolFactory factory) {
  // A protocol declares its traits before it runs: whatever asks about a run's protocol (the
  // sweep's expansion and checks, the figures, the replay) asks them, never its name.
  static_cast<void>(TraitsOf(name));  // throws std::invalid_argument for a name without traits
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
  if (spec.network != nullptr) s += " " + NetworkName(spec.network->label);
  return s + " n=" + std::to_string(spec.robots) + " run " + std::to_string(spec.run);
}

namespace {

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

std::vector<double> RunCosts(const std::vector<RunSpec>& specs, const ExecutorOptions& options) {
  if (options.run_seconds.size() == specs.size()) return options.run_seconds;
  return std::vector<double>(specs.size(), 1.0);
}

void ExecuteRuns(const std::vector<RunSpec>& specs,
                 const std::map<std::string, RunFunction>& run_functions,
                 const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                 const ExecutorOptions& options) {
  RunProgress progress(RunCosts(specs, options), options.progress, "runs", std::chrono::steady_clock::now());
  ParallelForInOrder(
      static_cast<std::int64_t>(specs.size()), options.threads,
      [&](std::int64_t i) {
        RunOutput out = RunOne(specs[static_cast<std::size_t>(i)], run_functions);
        progress.Finished(static_cast<std::size_t>(i));
        return out;
      },
      [&](std::int64_t i, RunOutput&& out) { consume(specs[static_cast<std::size_t>(i)], std::move(out)); });
}

}  // namespace dvpr

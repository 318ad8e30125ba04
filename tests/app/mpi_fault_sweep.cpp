// `dvpr run` under MPI with one run made to fail, for tests/mpi/test_mpi_sweep.py: the
// built-in protocols, except that the run of spec INDEX throws (MODE input: a
// std::runtime_error, exit status 1; internal: a std::logic_error, 3) or kills its process
// (die: SIGKILL, as the kernel's OOM killer would). The failing run is the same under every
// thread count and launch, so the test knows which rank holds it (spec i runs on rank i mod K).
//
// Usage: mpi_fault_sweep CONFIG OUT INDEX MODE
#include <signal.h>

#include <cstddef>
#include <iostream>
#include <stdexcept>
#include <string>

#include "experiments/app/cli.h"
#include "experiments/app/experiment.h"
#include "experiments/app/run_on_ranks.h"
#include "experiments/config/config.h"
#include "experiments/mpi/mpi_world.h"
#include "experiments/sweep/run_executor.h"

namespace {

dvpr::ProtocolRegistry FaultyProtocols(std::size_t index, const std::string& mode) {
  const dvpr::ProtocolRegistry builtin = dvpr::BuiltinProtocols();
  dvpr::ProtocolRegistry faulty;
  for (const std::string& name : builtin.Names()) {
    const dvpr::ProtocolFactory inner = *builtin.Find(name);
    faulty.Add(name, [inner, index, mode](const dvpr::SharedInputs& in) -> dvpr::RunFunction {
      const dvpr::RunFunction run = inner(in);
      return [run, index, mode](const dvpr::RunSpec& spec) {
        if (spec.index != index) return run(spec);
        const std::string what = "injected failure (" + dvpr::Describe(spec) + ")";
        if (mode == "input") throw std::runtime_error(what);
        if (mode == "internal") throw std::logic_error(what);
        ::raise(SIGKILL);
        throw std::logic_error("still alive after SIGKILL");
      };
    });
  }
  return faulty;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: mpi_fault_sweep CONFIG OUT INDEX MODE\n";
    return dvpr::kExitUsage;
  }
  const std::string config_path = argv[1], out = argv[2], mode = argv[4];
  const std::size_t index = std::stoul(argv[3]);
  const dvpr::MpiWorld world;
  const auto run = [&](const dvpr::ExecutorOptions& options, std::ostream& summary) {
    const dvpr::ExperimentConfig config = dvpr::LoadConfig(config_path, {});
    dvpr::RunExperiment(config, config_path, out, FaultyProtocols(index, mode), options, summary);
    return dvpr::kExitOk;
  };
  return dvpr::RunOnRanks(world, dvpr::ExecutorOptions{.threads = 0, .progress = false}, run, std::cout,
                          std::cerr);
}

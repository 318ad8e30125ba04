// How the decentralized simulation's cost grows (issue 15): frames 10^4..10^6 x robots 10..1000
// on a synthetic trajectory (KITTI 00 tiled, bench/sim_inputs.h), point-to-point links. Each
// configuration should run in a process of its own, so that peak_rss_MiB is its own:
//   bench/run_scaling.sh   (all of them, 3 runs each, then docs/figures/performance_scaling.png)
//   build/release/bench/bench_scaling --benchmark_filter='BM_ScalingDeploymentTrained/1000000/1000/'
// Two routing tables: BM_Scaling learns the centroids on the diverse training set (the paper's
// setting; the deployment is one environment, so a few robots store most frames and the search
// grows with their square), BM_ScalingDeploymentTrained on the deployment's own environment (the
// stores are shared out; the search grows with frames^2 / robots).
// Time is the simulation alone (wall and CPU); the peak memory includes the inputs.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>

#include "bench/bench_main.h"
#include "bench/sim_inputs.h"

#include "agents/placement/decentralized_placement.h"

namespace dvpr {
namespace {

void Scaling(benchmark::State& state, bench::Training training) {
  const auto frames = static_cast<Eigen::Index>(state.range(0));
  const int robots = static_cast<int>(state.range(1));
  const Dataset data = bench::Tiled(frames);
  const DecentralizedPlacement routing(bench::Table(robots, 10, training));  // training is not measured
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, routing, bench::PointToPoint(robots));
    benchmark::DoNotOptimize(log.queries.data());
  }
  std::int64_t comparisons = 0;
  std::int64_t largest_store = 0;
  for (const auto& l : log.loads) {
    comparisons += l.comparisons;
    largest_store = std::max(largest_store, l.stored);
  }
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["robots"] = robots;
  state.counters["events"] = static_cast<double>(log.events);
  state.counters["comparisons"] = static_cast<double>(comparisons);
  state.counters["largest_store"] = static_cast<double>(largest_store);
  state.counters["verifications"] = static_cast<double>(log.verify_requested);
  state.counters["peak_rss_MiB"] = bench::PeakRssMiB();
}

// Centroids from the diverse training set, as in the paper's experiment.
void BM_Scaling(benchmark::State& state) { Scaling(state, bench::Training::kDiverse); }
// Centroids from the deployment's own environment: the team shares the stores.
void BM_ScalingDeploymentTrained(benchmark::State& state) { Scaling(state, bench::Training::kDeployment); }

BENCHMARK(BM_Scaling)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {10, 100, 1000}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_ScalingDeploymentTrained)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {10, 100, 1000}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()

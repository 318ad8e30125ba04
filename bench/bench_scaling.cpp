// How the decentralized simulation's cost grows (issue 15): frames 10^4..10^6 x robots 10..1000
// on a synthetic trajectory (KITTI 00 tiled, bench/sim_inputs.h), point-to-point links. Each
// configuration should run in a process of its own, so that peak_rss_MiB is its own:
//   bench/run_scaling.sh   (all of them, 3 runs each, then docs/figures/performance_scaling.png)
//   build/release/bench/bench_scaling --benchmark_filter='BM_Scaling/1000000/1000/'
// Time is the simulation alone (wall and CPU); the peak memory includes the inputs.
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"
#include "bench/sim_inputs.h"

#include "agents/decentralized_routing.h"

namespace dvpr {
namespace {

void BM_Scaling(benchmark::State& state) {
  const auto frames = static_cast<Eigen::Index>(state.range(0));
  const int robots = static_cast<int>(state.range(1));
  const Dataset data = bench::Tiled(frames);
  const DecentralizedRouting routing(bench::Table(robots, 10));  // training is not measured
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, routing, bench::PointToPoint(robots));
    benchmark::DoNotOptimize(log.queries.data());
  }
  std::int64_t comparisons = 0;
  for (const auto& l : log.loads) comparisons += l.comparisons;
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["robots"] = robots;
  state.counters["events"] = static_cast<double>(log.events);
  state.counters["comparisons"] = static_cast<double>(comparisons);
  state.counters["peak_rss_MiB"] = bench::PeakRssMiB();
}
BENCHMARK(BM_Scaling)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {10, 100, 1000}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()

// Whole simulation runs (network and matching), as issue 5 asks:
//   build/release/bench/bench_simulation --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// - KITTI 00 (4541 frames, d = 128) with 100 robots, broadcast and decentralized, on
//   10 Mbit/s point-to-point links with 2 ms latency;
// - decentralized, 1000 robots on a 100 000-frame synthetic trajectory (KITTI 00 tiled 22
//   times, 3 km apart), one iteration; peak RSS reported as a counter.
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"
#include "bench/sim_inputs.h"

#include <memory>

#include "agents/decentralized_routing.h"

namespace dvpr {
namespace {

using bench::Kitti00;
using bench::PeakRssMiB;
using bench::PointToPoint;
using bench::Table;

void Report(benchmark::State& state, const SimRunLog& log) {
  std::int64_t messages = 0;
  for (const auto& l : log.links) messages += static_cast<std::int64_t>(l.counters.messages);
  state.counters["messages"] = static_cast<double>(messages);
  state.counters["events"] = static_cast<double>(log.events);
  state.counters["peak_rss_MiB"] = PeakRssMiB();
}

void BM_Kitti00_100Robots(benchmark::State& state, const char* strategy) {
  static const Dataset data = Kitti00();
  const int robots = 100;
  std::unique_ptr<RoutingStrategy> routing;
  if (std::string(strategy) == "broadcast") {
    routing = std::make_unique<BroadcastRouting>(robots);
  } else {
    routing = std::make_unique<DecentralizedRouting>(Table(robots, 30));
  }
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, *routing, PointToPoint(robots));
    benchmark::DoNotOptimize(log.queries.data());
  }
  Report(state, log);
}
BENCHMARK_CAPTURE(BM_Kitti00_100Robots, broadcast, "broadcast")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Kitti00_100Robots, decentralized, "decentralized")->Unit(benchmark::kMillisecond);

void BM_Decentralized_1000Robots_100kFrames(benchmark::State& state) {
  static const Dataset data = bench::Tiled(23 * 4541);  // 23 copies: 104 443 frames
  const auto table = Table(1000, 10);  // training is not what this measures
  const DecentralizedRouting routing(table);
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, routing, PointToPoint(1000));
    benchmark::DoNotOptimize(log.queries.data());
  }
  Report(state, log);
  state.counters["frames"] = static_cast<double>(data.size());
}
BENCHMARK(BM_Decentralized_1000Robots_100kFrames)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()

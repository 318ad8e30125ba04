// Whole simulation runs (network and matching), as issue 5 asks:
//   build/release/bench/bench_simulation --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// - KITTI 00 (4541 frames, d = 128) with 100 robots, broadcast and decentralized, on
//   10 Mbit/s point-to-point links with 2 ms latency;
// - decentralized, 1000 robots on a 100 000-frame synthetic trajectory (KITTI 00 tiled 22
//   times, 3 km apart), one iteration; peak RSS reported as a counter.
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"
#include <sys/resource.h>

#include <memory>

#include "agents/centroid_table.h"
#include "agents/decentralized_routing.h"
#include "agents/kmeans.h"
#include "experiments/data/loaders.h"
#include "experiments/protocols/sim/simulation.h"
#include "experiments/data/synthetic.h"

namespace dvpr {
namespace {

Dataset Kitti00() {
  Dataset d;
  d.name = "kitti00";
  d.trajectory = LoadKittiPoses(std::string(DVPR_SOURCE_DIR) + "/data/kitti/00_poses.txt");
  d.descriptors = SyntheticDeployment(d.trajectory, SyntheticParams{}, 1);
  return d;
}

Dataset Tiled(const Dataset& base, int min_frames) {
  const Eigen::Index n = base.size();
  const Eigen::Index copies = (min_frames + n - 1) / n;
  Dataset d;
  d.name = "tiled";
  d.trajectory.positions.resize(copies * n, 3);
  d.trajectory.headings.resize(copies * n, 3);
  for (Eigen::Index c = 0; c < copies; ++c) {
    d.trajectory.positions.middleRows(c * n, n) = base.trajectory.positions;
    d.trajectory.positions.middleRows(c * n, n).col(0).array() += 3000.0 * static_cast<double>(c);
    d.trajectory.headings.middleRows(c * n, n) = base.trajectory.headings;
  }
  d.descriptors = SyntheticDeployment(d.trajectory, SyntheticParams{}, 1);
  return d;
}

std::shared_ptr<const CentroidTable> Table(int robots, int iterations) {
  KMeansParams p;
  p.k = robots;
  p.seed = 3;
  p.max_iterations = iterations;
  const DescriptorMatrix training =
      SyntheticTrainingDiverse(SyntheticParams{}, SyntheticTrainingParams{.samples = 20000}, 2);
  return std::make_shared<CentroidTable>(CentroidTable::RoundRobin(KMeans(training, p), robots));
}

SimRunParams PointToPoint(int robots) {
  SimRunParams p;
  p.robots = robots;
  p.network.model = LinkModelKind::kPointToPoint;
  p.network.bandwidth = DataRate::Mbps(10);
  p.network.latency = SimTime::Millis(2);
  return p;
}

double PeakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

void Report(benchmark::State& state, const SimRunLog& log) {
  std::int64_t messages = 0;
  for (const auto& l : log.links) messages += static_cast<std::int64_t>(l.messages);
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
  static const Dataset data = Tiled(Kitti00(), 100000);
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

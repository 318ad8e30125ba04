// The responders' exact search and the routing's nearest centroid alone, outside the simulator
// (issue 15): the 10^6 x 1000 run spends most of its time in these two.
//   build/release/bench/bench_search --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// Inputs: KITTI 00 tiled to 2 x 10^5 frames, routed by the deployment-trained table of 1000
// robots (bench/sim_inputs.h); the 100 largest stores are replayed frame by frame, search then
// store, in the order the frames arrive, so consecutive searches hit different stores as in the
// simulation. A store of 2 x 10^5 / 1000 frames on average is what a robot holds halfway
// through the 10^6-frame run. Counters: ns per comparison (every stored entry counts, as in the
// model) and checksums of the answers (equal across versions that give the same matches).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "bench/bench_main.h"
#include "bench/sim_inputs.h"

#include "agents/algorithms/descriptor_index.h"

namespace dvpr {
namespace {

constexpr Eigen::Index kFrames = 200'000;
constexpr int kRobots = 1000;

struct Inputs {
  Dataset data = bench::Tiled(kFrames);
  std::shared_ptr<const CentroidTable> table = bench::Table(kRobots, 10, bench::Training::kDeployment);
  std::vector<RobotId> routes;
};

const Inputs& TheInputs() {
  static const Inputs inputs = [] {
    Inputs in;
    in.routes = in.table->RouteAll(in.data.descriptors);
    return in;
  }();
  return inputs;
}

void BM_ReplayLargestStores(benchmark::State& state) {
  const Inputs& in = TheInputs();
  const auto largest = static_cast<std::size_t>(state.range(0));
  std::vector<std::int64_t> count(kRobots, 0);
  for (RobotId r : in.routes) ++count[static_cast<std::size_t>(r.value)];
  std::vector<int> order(kRobots);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return count[static_cast<std::size_t>(a)] > count[static_cast<std::size_t>(b)]; });
  std::vector<bool> replayed(kRobots, false);
  for (std::size_t i = 0; i < largest; ++i) replayed[static_cast<std::size_t>(order[i])] = true;
  std::int64_t comparisons = 0;
  double checksum = 0.0;
  for (auto _ : state) {
    std::vector<IncrementalIndex> stores(kRobots, IncrementalIndex(static_cast<int>(in.data.descriptors.cols())));
    comparisons = 0, checksum = 0.0;
    for (Eigen::Index f = 0; f < kFrames; ++f) {
      const auto robot = static_cast<std::size_t>(in.routes[static_cast<std::size_t>(f)].value);
      if (!replayed[robot]) continue;
      const float* descriptor = in.data.descriptors.row(f).data();
      const IndexSearchResult r = stores[robot].Search(descriptor, FrameId(static_cast<std::int32_t>(f)), 50);
      comparisons += r.comparisons;
      if (r.best) checksum += r.best->distance + static_cast<double>(r.best->frame.value);
      stores[robot].Add(RobotId(static_cast<std::int32_t>(robot)), FrameId(static_cast<std::int32_t>(f)), descriptor);
    }
  }
  state.counters["comparisons"] = static_cast<double>(comparisons);
  state.counters["time_per_comparison"] = benchmark::Counter(static_cast<double>(comparisons) * static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["checksum"] = checksum;
}
BENCHMARK(BM_ReplayLargestStores)->Arg(100)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_NearestCentroid(benchmark::State& state) {
  const Inputs& in = TheInputs();
  Eigen::Index f = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.table->NearestCentroidOf(in.data.descriptors.row(f).data()));
    f = (f + 97) % kFrames;
  }
  std::int64_t checksum = 0;  // over a fixed set of frames, the same for every run
  for (Eigen::Index g = 0; g < kFrames; g += 20) checksum += (g % 7 + 1) * in.table->NearestCentroidOf(in.data.descriptors.row(g).data());
  state.counters["checksum"] = static_cast<double>(checksum);
}
BENCHMARK(BM_NearestCentroid)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()

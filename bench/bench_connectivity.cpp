// What tracking connectivity costs (outputs.connectivity, docs/network_model.md "Connectivity"):
// ConnectivityAt at every frame period of the KITTI 00 split, as a run asks it, for n = 20 and
// n = 100 robots on radios of 200 m. One iteration is a whole run's steps (4541 / n frames per
// robot at 10 fps); the counter `per_robot_virtual_s` is the wall time per robot per second of
// virtual time (seconds; Google Benchmark prints it scaled, e.g. "1.2us").
//   build/release/bench/bench_connectivity --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// (a one-iteration check: --benchmark_min_time=0.01)
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"
#include "bench/sim_inputs.h"

#include "experiments/domain/data/split.h"
#include "experiments/domain/scenario/scenario.h"
#include "net_models/propagation/connectivity.h"
#include "net_models/propagation/range_propagation.h"

namespace dvpr {
namespace {

void BM_Kitti00_Connectivity_Range200m(benchmark::State& state) {
  static const Dataset data = [] {
    Dataset d;
    d.name = "kitti00";
    d.trajectory = bench::Kitti00Poses();
    d.descriptors = DescriptorMatrix(d.trajectory.size(), 1);  // only the frame times are used
    return d;
  }();
  const int robots = static_cast<int>(state.range(0));
  // The robots' tracks as a run places them (Scenario: RobotTracks over the split).
  const TrackMobility tracks = RobotTracks(data, SplitSequence(static_cast<int>(data.size()), robots));
  RangePropagation propagation(tracks, 200.0);
  const SimTime step = SimTime::Nanos(std::llround(1e9 / data.fps));
  const int longest = (static_cast<int>(data.size()) + robots - 1) / robots;  // frames of the longest share
  const SimTime last = SimTime::Nanos(step.ns() * (longest - 1));
  std::int64_t connected = 0;
  for (auto _ : state) {
    const std::vector<ConnectivitySnapshot> steps = ConnectivityOver(propagation, robots, step, last);
    for (const ConnectivitySnapshot& s : steps) connected += s.connected() ? 1 : 0;
    benchmark::DoNotOptimize(connected);
  }
  const double virtual_s = last.ToSeconds();
  state.counters["virtual_s"] = virtual_s;
  state.counters["per_robot_virtual_s"] = benchmark::Counter(
      static_cast<double>(robots) * virtual_s * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Kitti00_Connectivity_Range200m)->Arg(20)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()
